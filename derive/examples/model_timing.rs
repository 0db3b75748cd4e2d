//! Prints, for every model file given (default: every file in `models/`), the time of its whole
//! derivation (mechanics and every kernel) and the size of each kernel in terms of its canonical
//! form. Run with `--release`:
//! `cargo run --release -p walker-symbolic --example model_timing [-- models/compass-gait.toml]`.
use std::time::Instant;

use walker_scene::model::Model;
use walker_symbolic::model::ModelDerivation;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut files: Vec<std::path::PathBuf> = std::env::args().skip(1).map(Into::into).collect();
    if files.is_empty() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../models");
        files = std::fs::read_dir(dir)?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .collect();
        files.sort();
    }
    for file in files {
        let model = Model::from_file(&file)?;
        let start = Instant::now();
        let d = ModelDerivation::new(&model)?;
        let elapsed = start.elapsed();
        let terms: usize = d
            .kernels
            .iter()
            .flat_map(|k| &k.outputs)
            .map(|(_, r)| r.num().len() + r.den().len())
            .sum();
        println!(
            "{:14} {} coordinates, {} kernels, {:7} terms, derived in {:.3} s",
            model.name,
            d.syms.q.len(),
            d.kernels.len(),
            terms,
            elapsed.as_secs_f64()
        );
    }
    Ok(())
}
