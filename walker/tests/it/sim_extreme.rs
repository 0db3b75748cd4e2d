//! Walks at the edges of the parameter ranges end, quickly and with a failure that names what
//! happened: a stiff `tanh` law (`c` up to `1e300`) under the explicit method, and a ramp
//! `T_set` so short that the desired trajectory overflows.

use crate::common;

use common::start;
use walker::ode::GaveUp;
use walker::poincare::MapError;
use walker::sim::{FailureKind, SimConfig, WalkLimits, walk, walk_with_stats};

/// A few steps, at most one second of walking (as `walker simulate --duration 1`).
fn limits() -> WalkLimits {
    WalkLimits {
        max_steps: 3,
        duration: 1.0,
        ..WalkLimits::default()
    }
}

/// The active walker with `c = 1e12` and more, integrated with DOP853, used to run for hours
/// (issue 21): the power kink `ydot u` chatters at the start of the stance phase, a segment
/// ends every ~1e-11 s, and each segment had its own budget of 100 000 attempted steps. The
/// budget now covers the whole stance phase, so the walk ends with "too many steps" after
/// exactly 100 000 attempts: 12 evaluations each at most, plus hinit's and the settling steps
/// of the ~3 000 segments' events, 1.2 to 1.33 million evaluations (measured; the bound is 2
/// million). Before the fix, `c = 1e12` had spent 16 000 evaluations on the first 30 of its
/// segments, each ~1e-11 s long.
#[test]
fn a_stiff_tanh_law_ends_with_too_many_steps_within_a_bounded_work() {
    for c in [1e11, 1e12, 1e15, 1e20, 1e50, 1e300] {
        let model = common::active(&[("c", c)]);
        let start = model.start_state();
        let (w, stats) = walk_with_stats(&model, &SimConfig::default(), &start, &limits());
        assert!(w.steps.is_empty(), "c = {c:e}: {} steps", w.steps.len());
        let too_many = FailureKind::Integrator {
            reason: GaveUp::TooManySteps,
        };
        assert_eq!(
            w.failure.as_ref().map(|f| &f.kind),
            Some(&too_many),
            "c = {c:e}: {:?}",
            w.failure
        );
        let Some(failure) = w.failure else { continue };
        assert_eq!(failure.step, 0);
        assert!(
            failure.t > 0.0 && failure.t < 1e-5,
            "c = {c:e}: {failure:?}"
        );
        assert!(failure.state.iter().all(|v| v.is_finite()));
        let attempts = stats.accepted_steps + stats.rejected_steps;
        // The whole stance phase spent the integrator's budget (`Config::max_steps`), no more.
        assert_eq!(attempts, 100_000, "c = {c:e}: {stats:?}");
        assert!(stats.rhs_evals <= 2_000_000, "c = {c:e}: {stats:?}");
    }
}

/// The same walks with the stiff method end at once (RODAS4 is made for them).
#[test]
fn a_stiff_tanh_law_under_rodas4_ends_within_a_bounded_work() {
    let cfg = SimConfig {
        method: walker::ode::Method::Rodas4,
        ..SimConfig::default()
    };
    for c in [1e12, 1e300] {
        let model = common::active(&[("c", c)]);
        let start = model.start_state();
        let (w, stats) = walk_with_stats(&model, &cfg, &start, &limits());
        assert!(
            w.failure.is_some() || !w.steps.is_empty(),
            "c = {c:e}: neither steps nor a failure"
        );
        assert!(stats.rhs_evals <= 5_000_000, "c = {c:e}: {stats:?}");
    }
}

/// `T_set = 1e-300` (and anything below about `1e-154`) overflows the scale `60 alpha / T_set^2`
/// of the desired acceleration, so the kernels get a NaN input at `t = 0`: the failure is
/// `non-finite`, at the start, with the initial state. It used to be `lambda-denominator-zero`
/// with `lambda: null`, though the denominator of `lambda` is regular there. Both the smooth and
/// the Coulomb model.
#[test]
fn an_overflowing_ramp_is_non_finite_not_a_pole() {
    for t_set in [1e-300, 1e-200, 1e-160] {
        let runtime = [("T_set", t_set)];
        for model in [common::active(&runtime), common::active_coulomb(&runtime)] {
            assert!(!model.desired(0, 0.0).iter().all(|v| v.is_finite()));
            let start = model.start_state();
            let w = walk(&model, &SimConfig::default(), &start, &limits());
            assert_eq!(
                w.failure,
                Some(FailureKind::NonFinite.at(0, 0.0, start)),
                "T_set = {t_set:e}"
            );
        }
    }
}

/// The Poincare map integrates the same stance phase with the variational equations appended:
/// under the stiff law it spends the integrator's budget of attempted steps (one budget for the
/// whole stance phase, across the breakpoint `T_set`) and reports it as the integrator's "too
/// many steps", with the time reached, before `T_set` (the budget runs out within `1e-5` s, as
/// the walks above), not a hang or a panic.
#[test]
fn the_poincare_map_of_a_stiff_tanh_law_ends_with_too_many_steps() {
    for c in [1e12, 1e300] {
        let model = common::active(&[("c", c)]);
        let start = model.start_state();
        let err = walker::poincare::poincare_map(&model, &SimConfig::default(), &start);
        let t = match err {
            Err(MapError::Integrator {
                t,
                cause: GaveUp::TooManySteps,
            }) => t,
            _ => f64::NAN,
        };
        assert!(t > 0.0 && t < 1e-5, "c = {c:e}: {err:?}");
    }
}

/// Under exact Coulomb friction a foot at rest chooses its contact from the forces that would
/// hold it; with a spin whose square overflows (`walker simulate --friction coulomb --omega0
/// 1e300`) they are not finite, and the walk is `non-finite` at the start, not
/// `contact-inconsistent` with `null` forces (found by `cli/tests/it/cli_extremes.rs`).
#[test]
fn an_overflowing_spin_under_coulomb_friction_is_non_finite() {
    for omega0 in [1e300, -1e300, f64::MAX] {
        // The walkers of the paper's Table 1 with `mu0 = 0.4` (the passive wheel on level
        // ground, `phi = 0`), not the built-in scenes' `phi = 0.2`, `mu0 = 0.2`.
        for model in [
            common::active_coulomb(&[("mu0", 0.4)]),
            common::passive_coulomb(&[("mu0", 0.4), ("phi", 0.0)]),
        ] {
            let start = start(&model, omega0);
            let w = walk(&model, &SimConfig::default(), &start, &limits());
            assert_eq!(
                w.failure,
                Some(FailureKind::NonFinite.at(0, 0.0, start)),
                "omega0 = {omega0:e}, {}",
                model.spec().name()
            );
        }
    }
}
