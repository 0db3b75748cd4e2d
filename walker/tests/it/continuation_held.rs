//! Continuation under exact Coulomb friction with the stance foot held (issue 32): the
//! compass gait over the slope and over `mu0`, its period doubling against an independent
//! reference, its period-two branch, and the rimless wheel over the slope. Each branch starts
//! at the first value of its range and ends there or at a physical reason, never at a failure
//! of the map at `t = 0` of a point that walks.
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use std::path::Path;

use walker::continuation::{
    Branch, ContinuationOptions, EndReason, LabelKind, WalkerProblem, continuation, period_two,
};
use walker::model::{Friction, ImpactLaw};
use walker::setup::{Overrides, Setup};
use walker::sim::SimConfig;

/// The model file `name` under exact Coulomb friction in stance and at the impact with
/// `mu0`, the parameter `param` free.
fn held(name: &str, mu0: f64, param: &str) -> WalkerProblem {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../models/{name}.toml"));
    let ov = Overrides {
        friction: Some(Friction::Coulomb),
        impact: Some(ImpactLaw::Coulomb),
        set: vec![("mu0".into(), mu0)],
        ..Overrides::default()
    };
    let setup = Setup::from_model_file(&path, &ov, None).unwrap();
    WalkerProblem::new(setup, param, SimConfig::default()).unwrap()
}

fn follow(w: &WalkerProblem, from: f64, to: f64) -> Branch {
    continuation(w, from, to, &ContinuationOptions::default()).unwrap()
}

/// Both ends of `b` are the ends of the asked range, and the first point is `from`.
fn spans(b: &Branch, from: f64, to: f64) {
    assert_eq!(
        b.ends,
        [EndReason::ParameterBound, EndReason::ParameterBound],
        "{:?}",
        b.ends
    );
    assert_eq!(b.points[0].parameter, from);
    assert_eq!(b.points[b.points.len() - 1].parameter, to);
}

#[test]
fn the_held_compass_gait_starts_at_its_first_slope_and_keeps_its_foot_at_rest() {
    // Issue 32: this range could not start ("contact-inconsistent at t = 0"): rounding in the
    // corrector's solve set the foot sliding at 1e-17 m/s, which Painleve's paradox forbids at
    // mu0 = 5. The foot's velocity (section coordinate 1, `xd`) is now exactly zero.
    let w = held("compass-gait", 5.0, "phi");
    let b = follow(&w, 0.05, 0.054);
    spans(&b, 0.05, 0.054);
    assert!(b.points.iter().all(|p| p.state[1] == 0.0 && p.physical));
}

/// Goswami, Thuilot and Espiau's first period doubling (m = 5, m_H = 10, a = b = 0.5, the
/// model file's defaults) by the independent SciPy reference
/// `sympy_ref/compass_gait_period_doubling.py`: the smallest multiplier is -0.902882 at 4.3
/// degrees and -1.009221 at 4.4, so the crossing of -1 is at 4.391 degrees by linear
/// interpolation, whose error the multiplier's second difference (0.02 over 0.1 degrees)
/// bounds by 0.003 degrees.
const REFERENCE_PD_DEG: f64 = 4.391;

#[test]
fn the_compass_gait_doubles_its_period_where_the_independent_reference_says() {
    let w = held("compass-gait", 5.0, "phi");
    let (from, to) = (2f64.to_radians(), 5.5f64.to_radians());
    let b = follow(&w, from, to);
    spans(&b, from, to);
    let pds: Vec<_> = b.labelled(LabelKind::PeriodDoubling).collect();
    assert_eq!(pds.len(), 1, "one period doubling on the period-one branch");
    // 0.005 degrees: the reference's 0.003 and the finite-difference multipliers' error
    // (about 1e-8, a shift of 1e-7 degrees) with a margin.
    let deg = pds[0].parameter.to_degrees();
    assert!((deg - REFERENCE_PD_DEG).abs() < 0.005, "{deg}");
    // Stable before, unstable after.
    assert!(b.points[0].multipliers.iter().all(|m| m.modulus() < 1.0));
    assert!(
        b.points[b.points.len() - 1]
            .multipliers
            .iter()
            .any(|m| m.modulus() > 1.0)
    );

    // The period-two branch is born there, walks both steps (twice the period) and doubles
    // again before 5.5 degrees (Goswami et al.'s cascade).
    let two = period_two(&w, pds[0], from, to, &ContinuationOptions::default()).unwrap();
    assert_eq!(two.period, 2);
    assert_eq!(two.ends[0], EndReason::BranchSwitch);
    let pd2: Vec<_> = two.labelled(LabelKind::PeriodDoubling).collect();
    assert!(pd2.len() >= 2, "the birth and a second doubling");
    let second = pd2[pd2.len() - 1].parameter.to_degrees();
    assert!(second > deg + 0.1 && second < 5.5, "{second}");
    let last = &two.points[two.points.len() - 1];
    assert!(
        last.state[1] == 0.0,
        "the foot stays held on the period-two branch"
    );
}

#[test]
fn the_held_compass_gait_follows_mu0_from_its_lowest_held_gait_to_5() {
    // Issue 32: this branch ended at mu0 = 0.5351 with `lambda-denominator-zero` at t = 0.
    // The gallery's lowest held gait is at mu0 = 0.2742; a held gait does not depend on mu0
    // (the foot never slides), so every point is the same gait.
    let w = held("compass-gait", 5.0, "mu0");
    let b = follow(&w, 0.28, 5.0);
    spans(&b, 0.28, 5.0);
    let v0 = b.points[0].cycle.speed;
    assert!(
        b.points
            .iter()
            .all(|p| (p.cycle.speed - v0).abs() < 1e-9 && p.state[1] == 0.0)
    );
}

#[test]
fn the_held_rimless_wheel_starts_at_phi_0_02_and_ends_at_lift_off() {
    // Issue 32: this branch could not start (lift-off at t = 0.069 from a seed at the middle
    // of the range). It starts at the first value and ends where the wheel, ever faster,
    // leaves the floor during stance: a physical boundary, not a failure at t = 0.
    let w = held("rimless-wheel", 3.0, "phi");
    let b = follow(&w, 0.02, 0.3);
    assert_eq!(b.points[0].parameter, 0.02);
    assert_eq!(b.ends[0], EndReason::ParameterBound);
    match &b.ends[1] {
        EndReason::ParameterBound => {}
        EndReason::MapFailed { error, physical_at } => {
            assert!(error.contains("lift-off"), "{error}");
            assert!(!error.contains("t = 0:"), "{error}");
            // The typed reading of the same end: a physical failure, after the step began.
            assert!(physical_at.is_some_and(|t| t > 0.0), "{physical_at:?}");
        }
        e => panic!("{e:?}"),
    }
    assert!(b.points.iter().all(|p| p.state[0] == 0.0));
}

#[test]
fn options_out_of_their_ranges_are_a_typed_error_not_a_panic() {
    // Issue 35: a largest step below the smallest panicked in `f64::clamp`.
    let w = held("rimless-wheel", 3.0, "phi");
    for opts in [
        ContinuationOptions {
            max_step: 1e-7,
            ..ContinuationOptions::default()
        },
        ContinuationOptions {
            initial_step: 0.5,
            ..ContinuationOptions::default()
        },
        ContinuationOptions {
            tol: f64::NAN,
            ..ContinuationOptions::default()
        },
        ContinuationOptions {
            min_step: 0.0,
            ..ContinuationOptions::default()
        },
    ] {
        let e = continuation(&w, 0.1, 0.2, &opts).unwrap_err();
        assert!(
            matches!(
                e,
                walker::continuation::ContinuationError::InvalidOptions { .. }
            ),
            "{e:?}"
        );
    }
}
