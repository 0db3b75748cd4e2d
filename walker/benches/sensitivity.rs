//! The cost of parameter sensitivities (`walker::sensitivity`, `docs/poincare.md`) against one
//! map evaluation (`harness = false`: `cargo bench -p walker --bench sensitivity`).
//!
//! On the paper's active walker at its fixed point: the median wall time of `REPS` evaluations
//! of the map with its exact Jacobian at the sensitivities' tolerances (`rtol = 1e-12`,
//! `atol = 1e-14`, a Table-1 neighbour, as the differences evaluate it), of the sensitivities to
//! `mu0`, and to `mu0` and `T_set`; one parameter column is the difference of the last two.
//! Printed as ratios to the map.

use std::time::Instant;

use walker::poincare::{FixedPointOptions, fixed_point, poincare_map};
use walker::sensitivity::sensitivities;
use walker::setup::Setup;
use walker::sim::SimConfig;

const REPS: usize = 11;

/// The median of `REPS` timings of `f` (seconds).
fn time(mut f: impl FnMut()) -> f64 {
    let mut t: Vec<f64> = (0..REPS)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[REPS / 2]
}

fn main() {
    let cfg = SimConfig::default();
    let setup = Setup::built_in("active-level").expect("a built-in scene");
    let model = setup.model().expect("compiled");
    let fp = fixed_point(&model, &cfg, &FixedPointOptions::for_model(&model)).expect("a cycle");
    let shifted = setup
        .with("mu0", 0.401)
        .expect("in range")
        .model()
        .expect("kernels");
    let tight = SimConfig {
        rtol: 1e-12,
        atol: 1e-14,
        ..cfg
    };
    let map = time(|| {
        let _ = poincare_map(&shifted, &tight, &fp.state_plus);
    });
    let one = time(|| {
        let _ = sensitivities(&setup, &cfg, &fp, &["mu0"]);
    });
    let two = time(|| {
        let _ = sensitivities(&setup, &cfg, &fp, &["mu0", "T_set"]);
    });
    println!(
        "active-level: sensitivities to mu0 / map {:.1}; to mu0, T_set / map {:.1}; one more column / map {:.1}",
        one / map,
        two / map,
        (two - one) / map
    );
}
