//! The hopper compiled by this crate's build script against the same model file derived at
//! run time and evaluated by the tape (`walker-load`), side by side in one run: a 100 s walk,
//! and a 100-point sweep of `mu0` (one chain, each point continuing from the last, 10 s each).
//! Both sides do the same arithmetic (the walks are equal bit for bit,
//! `tests/it/compiled_vs_tape.rs`); the ratio is the price of evaluating kernels by
//! interpretation.
//!
//! `cargo bench -p own-walker --bench compiled_vs_tape`

#![allow(clippy::unwrap_used, missing_docs, reason = "benchmark")]

use std::path::Path;
use std::sync::Arc;

use criterion::{Criterion, criterion_group, criterion_main};
use own_walker::compiled::MODELS;
use walker::model::{KernelSource, Spec, Walker};
use walker::setup::Setup;
use walker::sim::{SimConfig, WalkLimits, walk};
use walker::sweep::sweep_chains;
use walker_scene::model::Model as ModelFile;

fn setups() -> [(&'static str, Setup); 2] {
    let file =
        ModelFile::from_file(&Path::new(env!("CARGO_MANIFEST_DIR")).join("hopper.toml")).unwrap();
    let derived = walker_load::Derived::new(file.clone()).unwrap();
    let tape = Walker::new(
        Spec::new(file).unwrap(),
        Arc::new(derived) as Arc<dyn KernelSource>,
    );
    [
        (
            "compiled",
            Setup::of(Walker::from_compiled(&MODELS[0]).unwrap()),
        ),
        ("tape", Setup::of(tape)),
    ]
}

fn limits(duration: f64) -> WalkLimits {
    WalkLimits {
        max_steps: 1_000_000,
        duration,
        record: false,
        periodic: None,
    }
}

fn bench(c: &mut Criterion) {
    let cfg = SimConfig::default();
    let setups = setups();
    let mut group = c.benchmark_group("hopper_walk_100s");
    group.sample_size(10);
    for (name, setup) in &setups {
        let model = setup.model().unwrap();
        let start = model.start_state();
        group.bench_function(*name, |b| {
            b.iter(|| walk(&model, &cfg, &start, &limits(100.0)));
        });
    }
    group.finish();
    let grid: Vec<f64> = (0..100).map(|i| 0.3 + 0.005 * f64::from(i)).collect();
    let mut group = c.benchmark_group("hopper_sweep_100_points");
    group.sample_size(10);
    for (name, setup) in &setups {
        group.bench_function(*name, |b| {
            b.iter(|| {
                sweep_chains(
                    &[0.0],
                    |_, mu0| setup.with("mu0", mu0).unwrap().model().unwrap(),
                    &cfg,
                    &grid,
                    |m| m.start_state(),
                    &limits(10.0),
                    false,
                    &|| {},
                )
            });
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    // No plots: plotters' fonts are not on every machine.
    config = Criterion::default().without_plots();
    targets = bench
}
criterion_main!(benches);
