//! The cost of the Poincare map's exact Jacobian (variational equations and saltation,
//! `docs/poincare.md`) against one step of the simulator and against central differences
//! (`harness = false`: `cargo bench -p walker --bench poincare_jacobian`).
//!
//! Per model, at its fixed point: the median wall time of `REPS` evaluations of one simulated
//! step (`walk`, one step, at the map's tolerances `rtol = 1e-12`, `atol = 1e-14` where the map
//! uses them), of the map with its exact Jacobian, and of the map by central differences
//! (`h = 1e-4`); and the ratios.

use std::path::Path;
use std::time::Instant;

use walker::model::Model;
use walker::poincare::{
    FixedPointOptions, JacobianMethod, Section, fixed_point, poincare_map_with,
};
use walker::setup::{Overrides, Setup};
use walker::sim::{SimConfig, WalkLimits, walk};

const REPS: usize = 21;

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

fn bench(name: &str, model: &Model, cfg: &SimConfig) {
    let fp = fixed_point(model, cfg, &FixedPointOptions::for_model(model)).expect("a fixed point");
    let s = fp.state_plus;
    let limits = WalkLimits {
        max_steps: 1,
        ..WalkLimits::default()
    };
    let exact = poincare_map_with(model, cfg, &s, JacobianMethod::Variational).expect("the map");
    let step_cfg = if exact.method == JacobianMethod::Variational && cfg.rtol > 1e-12 {
        *cfg
    } else {
        SimConfig {
            rtol: cfg.rtol.min(1e-12),
            atol: cfg.atol.min(1e-14),
            ..*cfg
        }
    };
    let step = time(|| {
        let _ = walk(model, &step_cfg, &s, &limits);
    });
    let section = Section::of(model);
    let r = section.reduce(&s);
    let along = time(|| {
        let _ = section.map(cfg, &r);
    });
    let var = time(|| {
        let _ = poincare_map_with(model, cfg, &s, JacobianMethod::Variational);
    });
    let fd = time(|| {
        let _ = poincare_map_with(model, cfg, &s, JacobianMethod::FiniteDifferences);
    });
    println!(
        "{name:<58} step {:>8.1} us  section ({} columns) {:>8.1} us  full {:>8.1} us ({:?})  fd {:>8.1} us  section/step {:>5.2}  full/step {:>5.2}  fd/section {:>5.2}",
        step * 1e6,
        section.dim(),
        along * 1e6,
        var * 1e6,
        exact.method,
        fd * 1e6,
        along / step,
        var / step,
        fd / along
    );
}

/// A shipped model file (its compiled kernels: every shipped model the library compiles), with
/// exact Coulomb friction in stance and at the impact and `mu0` set.
fn coulomb_model(path: &Path, mu0: f64) -> Model {
    let source = walker_load::runtime_source();
    let mut setup = Setup::from_model_file(path, &Overrides::default(), Some(&source as &_))
        .expect("the model");
    setup.friction = walker::model::Friction::Coulomb;
    setup.impact = walker::model::ImpactLaw::Coulomb;
    setup.set("mu0", mu0).expect("mu0");
    setup.model().expect("kernels")
}

fn main() {
    let cfg = SimConfig::default();
    let models = Path::new(env!("CARGO_MANIFEST_DIR")).join("../models");
    let passive = Setup::built_in("passive-slope")
        .expect("a built-in scene")
        .model()
        .expect("compiled");
    bench("passive-slope (compiled, Table 1, tanh)", &passive, &cfg);
    let active = Setup::built_in("active-level")
        .expect("a built-in scene")
        .model()
        .expect("compiled");
    bench("active-level (compiled, Table 1, tanh)", &active, &cfg);
    // Under exact Coulomb friction in stance and at the impact: the held foot through the
    // sliding kernels (`docs/poincare.md`), held through the step (mu0 = 1) and slipping twice
    // within it (mu0 = 0.5).
    for (mu0, what) in [(1.0, "held"), (0.5, "stick-slip")] {
        let mut setup = Setup::built_in("active-level").expect("a built-in scene");
        setup.friction = walker::model::Friction::Coulomb;
        setup.impact = walker::model::ImpactLaw::Coulomb;
        setup.set("mu0", mu0).expect("mu0");
        let model = setup.model().expect("compiled");
        bench(
            &format!("active-level (compiled, Coulomb, {what}, mu0 = {mu0})"),
            &model,
            &cfg,
        );
    }
    let source = walker_load::runtime_source();
    let simplest = Setup::from_model_file(
        &models.join("simplest-walker.toml"),
        &Overrides::default(),
        Some(&source as &_),
    )
    .expect("the model")
    .model()
    .expect("kernels");
    bench(
        "simplest-walker (run time, Coulomb, stuck)",
        &simplest,
        &cfg,
    );
    let compass = coulomb_model(&models.join("compass-gait.toml"), 5.0);
    bench("compass-gait (compiled, Coulomb, mu0 = 5)", &compass, &cfg);
    // Sliding within its step: `accel_jacobian` of the structured solve, differentiated.
    let sliding = coulomb_model(&models.join("compass-gait.toml"), 0.27);
    bench(
        "compass-gait (compiled, Coulomb, mu0 = 0.27)",
        &sliding,
        &cfg,
    );
    // No closed forms, inputs, held: `closed_loop_stick_jacobian`.
    let three = coulomb_model(&models.join("three-link.toml"), 1.0);
    bench("three-link (compiled, Coulomb, mu0 = 1)", &three, &cfg);
    let wheel = coulomb_model(&models.join("rimless-wheel.toml"), 3.0);
    bench("rimless-wheel (compiled, Coulomb, mu0 = 3)", &wheel, &cfg);
}
