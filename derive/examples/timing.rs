//! Prints the time of the whole derivation (run with `--release`).
use std::time::Instant;

fn main() -> Result<(), walker_symbolic::Error> {
    let start = Instant::now();
    let d = walker_symbolic::Derivation::new()?;
    let elapsed = start.elapsed();
    for k in &d.kernels {
        let terms: usize = k
            .outputs
            .iter()
            .map(|(_, r)| r.num().len() + r.den().len())
            .sum();
        println!(
            "{:18} {:3} outputs {:6} terms",
            k.name,
            k.outputs.len(),
            terms
        );
    }

    println!("lambda = {:?}", d.quantities.level.lambda);
    println!("derivation of every kernel: {:.3} s", elapsed.as_secs_f64());
    Ok(())
}
