//! A step that starts on its own heel-strike guard, moving into the floor.

use walker::model::{Model, Runtime};
use walker::sim::{Failure, SimConfig, WalkLimits, walk};

/// The passive wheel started exactly at its heel-strike angle, rolling forward: the impact is
/// at `t = 0`, the step has no duration, and the failure says so (it used to surface as a
/// non-finite speed `dx / 0`).
#[test]
fn a_heel_strike_at_the_start_of_a_step_is_named() {
    let model = Model::passive_slope(Runtime {
        phi: 0.05,
        ..Runtime::default()
    });
    let heel = model.heel_strike_angle();
    let start = [0.0, 0.0, heel, 0.0, 0.0, 0.0, 1e-6, 0.0];
    let limits = WalkLimits {
        max_steps: 1,
        ..WalkLimits::default()
    };
    let w = walk(&model, &SimConfig::default(), start, &limits);
    assert!(w.steps.is_empty());
    assert!(
        matches!(w.failure, Some(Failure::ImpactAtStart { step: 0, .. })),
        "{:?}",
        w.failure
    );
}
