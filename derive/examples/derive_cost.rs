//! The work and time of each model file's derivation, against the derivation budget:
//! `cargo run --release -p walker-symbolic --example derive_cost -- FILE...`.
use std::time::Instant;

use walker_scene::model::Model;
use walker_symbolic::budget::DERIVATION_BUDGET;
use walker_symbolic::model::ModelDerivation;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // A budget other than the shipped one: `DERIVE_BUDGET=N`.
    let budget = std::env::var("DERIVE_BUDGET")
        .ok()
        .and_then(|b| b.parse().ok())
        .unwrap_or(DERIVATION_BUDGET);
    for file in std::env::args().skip(1) {
        let model = Model::from_file(std::path::Path::new(&file))?;
        let t = Instant::now();
        let m = ModelDerivation::measured(&model, budget);
        println!(
            "{file}: {} term products ({:.4} of the budget) in {:.3} s: {}",
            m.work,
            m.work as f64 / budget as f64,
            t.elapsed().as_secs_f64(),
            match &m.result {
                Ok(d) => format!("{} kernels", d.kernels.len()),
                Err(e) => e.to_string(),
            }
        );
    }
    Ok(())
}
