//! Steps that cannot start: on their own heel-strike guard moving into the floor, or with
//! velocities too large for `lambda` to be computed.

use crate::common;

use common::{heel_strike_angle, start};
use walker::sim::{Failure, FailureKind, SimConfig, WalkLimits, walk};

/// The passive wheel started exactly at its heel-strike angle, rolling forward: the impact is
/// at `t = 0`, the step has no duration, and the failure says so (it used to surface as a
/// non-finite speed `dx / 0`).
#[test]
fn a_heel_strike_at_the_start_of_a_step_is_named() {
    // `mu0 = 0.4` (the active walker's value), not the built-in scene's 0.2.
    let model = common::passive(&[("phi", 0.05), ("mu0", 0.4)]);
    let heel = heel_strike_angle(&model);
    let start = [0.0, 0.0, heel, 0.0, 0.0, 0.0, 1e-6, 0.0];
    let limits = WalkLimits {
        max_steps: 1,
        ..WalkLimits::default()
    };
    let w = walk(&model, &SimConfig::default(), &start, &limits);
    assert!(w.steps.is_empty());
    assert!(
        matches!(
            w.failure,
            Some(Failure {
                step: 0,
                kind: FailureKind::ImpactAtStart,
                ..
            })
        ),
        "{:?}",
        w.failure
    );
}

/// Angular velocities whose squares overflow (`omega0 = 1e308`, as `walker simulate --omega0
/// 1e308` gives) make `lambda` non-finite with a regular denominator: the failure names the
/// state (`non-finite`), not a pole of `lambda` (which it used to). Started at a pole of
/// `lambda` itself, the same walker still reports the pole.
#[test]
fn an_overflowing_start_is_non_finite_and_a_pole_is_still_a_pole() {
    let limits = WalkLimits {
        max_steps: 1,
        ..WalkLimits::default()
    };
    let active = common::active(&[]);
    for omega0 in [1e308, -1e200, 1e160] {
        let w = walk(
            &active,
            &SimConfig::default(),
            &start(&active, omega0),
            &limits,
        );
        assert!(
            matches!(
                w.failure,
                Some(Failure {
                    step: 0,
                    kind: FailureKind::NonFinite,
                    ..
                })
            ),
            "omega0 = {omega0:e}: {:?}",
            w.failure
        );
    }
    // The passive wheel on level ground (`u = 0`) with `mu = mu0 = 1` (the foot sliding
    // backwards): the denominator `2 I1 + 2 m_t l^2 sin th1 (sin th1 - mu cos th1)` of Eq. 23
    // vanishes at `th1 = 0.222781` (docs/stability.md), and the reaction there is huge at any
    // angular velocity, modest or overflowing.
    let passive = common::passive(&[("phi", 0.0), ("mu0", 1.0)]);
    let th1 = bisect_pole(0.2, 0.25);
    for omega in [0.0, 1.0, 1e300] {
        let start = [0.0, 0.0, th1, 0.0, -1.0, 0.0, omega, omega];
        let w = walk(&passive, &SimConfig::default(), &start, &limits);
        assert!(
            matches!(
                w.failure,
                Some(Failure {
                    step: 0,
                    kind: FailureKind::LambdaDenominatorZero { .. },
                    ..
                })
            ),
            "omega = {omega:e}: {:?}",
            w.failure
        );
    }
}

/// The root of `cos 2 th1 + sin 2 th1 - (1 + 2 I1 / (m_t l^2))` in `[a, b]` (Table 1: `I1 =
/// 0.5`, `m_t l^2 = 3`; `mu = 1`), the pole of `lambda` on level ground.
fn bisect_pole(mut a: f64, mut b: f64) -> f64 {
    let f = |th: f64| (2.0 * th).cos() + (2.0 * th).sin() - (1.0 + 2.0 * 0.5 / 3.0);
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if f(a) * f(m) <= 0.0 {
            b = m;
        } else {
            a = m;
        }
    }
    0.5 * (a + b)
}
