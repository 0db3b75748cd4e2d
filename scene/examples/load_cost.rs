//! What loading a model file costs: the median time of `Model::from_toml` (parse, checks and
//! the validation layer) over repeated loads of each file named on the command line.
//!
//! ```sh
//! cargo run --release -p walker-scene --example load_cost -- models/*.toml
//! ```

use std::time::Instant;

use walker_scene::model::Model;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    const RUNS: usize = 301;
    for path in std::env::args().skip(1) {
        let text = std::fs::read_to_string(&path)?;
        let mut times = Vec::with_capacity(RUNS);
        let mut outcome = String::new();
        for _ in 0..RUNS {
            let started = Instant::now();
            let result = Model::from_toml(&text, &path);
            times.push(started.elapsed().as_secs_f64());
            outcome = match result {
                Ok(_) => "loads".to_owned(),
                Err(e) => format!(
                    "refused: {}",
                    e.kind().map_or("read".into(), |k| format!("{k:?}"))
                ),
            };
        }
        times.sort_by(f64::total_cmp);
        println!(
            "{path}: median {:.1} us over {RUNS} loads ({outcome})",
            times[RUNS / 2] * 1e6
        );
    }
    Ok(())
}
