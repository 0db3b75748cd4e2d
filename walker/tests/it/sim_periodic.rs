//! `WalkLimits::periodic`: a walk that stops once its gait is periodic reports the descriptors
//! the full walk ends with, to within the stop's tolerance.

use crate::common;

use common::start;
use walker::model::Model;
use walker::sim::{SimConfig, Walk, WalkLimits, walk};

fn walk_100s(model: &Model, tol: f64, periodic: Option<f64>) -> Walk {
    let cfg = SimConfig {
        rtol: tol,
        atol: tol,
        ..SimConfig::default()
    };
    let limits = WalkLimits {
        max_steps: 10_000,
        duration: 100.0,
        periodic,
        ..WalkLimits::default()
    };
    walk(model, &cfg, &start(model, 0.8), &limits)
}

/// The active walker at `mu0 = 0.4` converges slowly (Floquet multiplier 0.76, Fig. 7) and
/// at `mu0 = 1` quickly. Stopped once the predicted rest of the step-to-step change is 1e-10,
/// its last `T`, `dx` and `p` are those of the 100 s walk within 2e-10: the 1e-10 of the stop
/// (exact for a linear convergence at the measured ratio) plus the integration error of the
/// two runs' descriptors at `rtol = atol = 1e-11` (a few 1e-11 each; `sim_walk.rs`).
#[test]
fn a_periodic_stop_keeps_the_descriptors_of_the_full_walk() {
    for mu0 in [0.4, 1.0] {
        let model = common::active(&[("mu0", mu0)]);
        let full = walk_100s(&model, 1e-11, None);
        let stopped = walk_100s(&model, 1e-11, Some(1e-10));
        assert!(full.failure.is_none() && stopped.failure.is_none());
        assert!(!full.periodic && stopped.periodic, "mu0 = {mu0}");
        let (a, b) = (
            full.steps.last().expect("steps"),
            stopped.steps.last().expect("steps"),
        );
        assert!(
            stopped.steps.len() < full.steps.len() / 2,
            "mu0 = {mu0}: {} of {} steps",
            stopped.steps.len(),
            full.steps.len()
        );
        let rel = |x: f64, y: f64| ((x - y) / x).abs();
        let err = rel(a.period, b.period)
            .max(rel(a.dx, b.dx))
            .max(rel(a.p.expect("active: p"), b.p.expect("active: p")));
        assert!(err <= 2e-10, "mu0 = {mu0}: {err:e}");
    }
}
