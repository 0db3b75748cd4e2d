//! Continuation of the paper's walkers: the corrector's Jacobians against finite differences,
//! the branches against the simulated steady gaits (Figs. 8 and 10), the lift-off boundary of
//! Fig. 8 against the simulator's own lift-off test, the `mu0 = 0` family, and the held
//! passive wheel's branch over the slope against the rimless wheel's closed form.
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use crate::common;

use common::start;
use walker::continuation::{
    Branch, ContinuationError, ContinuationOptions, EndReason, GaitProblem, LabelKind, Stability,
    WalkerProblem, continuation,
};
use walker::model::{Friction, ImpactLaw};
use walker::poincare::Section;
use walker::sim::{SimConfig, WalkLimits, trajectory, walk};

fn active(t_set: f64, param: &str) -> WalkerProblem {
    let setup = common::setup("active-level", &[("T_set", t_set)]);
    WalkerProblem::new(setup, param, SimConfig::default()).unwrap()
}

fn passive(phi: f64, mu0: f64, param: &str) -> WalkerProblem {
    let setup = common::setup("passive-slope", &[("phi", phi), ("mu0", mu0)]);
    WalkerProblem::new(setup, param, SimConfig::default()).unwrap()
}

#[test]
fn the_corrector_jacobians_match_central_differences_of_the_map() {
    // Central differences with h = 1e-5: truncation h^2 |P'''| / 6, about 1e-10 for this map
    // of order-one derivatives, and the map's own error (integrated to rtol 1e-10, smooth in
    // its inputs to about 1e-13) divided by h: 1e-8. So 1e-6 of the matrix's size bounds both
    // with a margin of 100.
    for (w, r, p) in [
        (active(0.3, "mu0"), [0.0, 2.0], 0.4),
        (passive(0.15, 0.5, "mu0"), [0.05, 3.0], 0.5),
        (active(0.3, "T_set"), [0.01, 2.0], 0.3),
    ] {
        let h = 1e-5;
        let j = w.jacobian(&r, p).unwrap();
        let scale = j.amax().max(1.0);
        for k in 0..2 {
            let (mut rp, mut rm) = (r, r);
            rp[k] += h;
            rm[k] -= h;
            let (ip, im) = (w.map(&rp, p).unwrap().image, w.map(&rm, p).unwrap().image);
            for i in 0..2 {
                let fd = (ip[i] - im[i]) / (2.0 * h);
                assert!(
                    (j[(i, k)] - fd).abs() < 1e-6 * scale,
                    "{i}{k}: {} {fd}",
                    j[(i, k)]
                );
            }
        }
        // The parameter derivative (one-sided, h = 1e-6 p) against central differences.
        let image = w.map(&r, p).unwrap().image;
        let dp = w.parameter_derivative(&r, p, &image, 1.0).unwrap();
        let (ip, im) = (
            w.map(&r, p + h).unwrap().image,
            w.map(&r, p - h).unwrap().image,
        );
        for i in 0..2 {
            let fd = (ip[i] - im[i]) / (2.0 * h);
            // The one-sided difference's truncation error is h |P_pp| / 2 with h = 1e-6:
            // below 1e-5 for |P_pp| up to 20.
            assert!(
                (dp[i] - fd).abs() < 1e-5 * fd.abs().max(1.0),
                "{i}: {} {fd}",
                dp[i]
            );
        }
    }
}

/// The steady gait of the paper's protocol: 100 s of walking from `omega0 = 0.8` (P3a, P3b).
fn steady(w: &WalkerProblem, p: f64) -> walker::sim::StepResult {
    let model = w.model_at(p).unwrap();
    let limits = WalkLimits {
        max_steps: usize::MAX,
        duration: 100.0,
        ..WalkLimits::default()
    };
    let walked = walk(&model, w.config(), &start(&model, 0.8), &limits);
    assert!(walked.failure.is_none(), "{p}: {:?}", walked.failure);
    *walked.steps.last().unwrap()
}

/// Compare the branch's user points with the simulated steady gaits.
fn agrees_with_simulation(w: &WalkerProblem, b: &Branch, ps: &[f64]) {
    let uz: Vec<_> = b.labelled(LabelKind::UserPoint).collect();
    assert_eq!(uz.len(), ps.len(), "{:?}", b.special().collect::<Vec<_>>());
    for (pt, &p) in uz.iter().zip(ps) {
        assert!((pt.parameter - p).abs() < 1e-12);
        assert_eq!(pt.stability, Stability::Stable);
        let s = steady(w, p);
        // The corrector leaves |P(r) - r| <= 1e-11, so the fixed point is within
        // 1e-11 / (1 - |multiplier|) <= 1e-10 of the exact one (multipliers below 0.9 here);
        // 100 s of walking contract the start's distance by at least 0.9^190 = 2e-9 of an
        // order-one start... and the walk and the map share the integrator and its tolerance
        // (rtol 1e-10), whose error per step differs between them by the variational
        // components' part in the error norm only through the step sizes, at most about that
        // tolerance. 1e-8 (the target) covers these with a margin of 10.
        for (a, b, what) in [
            (pt.cycle.speed, s.speed, "V"),
            (pt.cycle.period, s.period, "T"),
            (pt.cycle.dx, s.dx, "dx"),
        ] {
            assert!((a - b).abs() < 1e-8 * b.abs(), "{p} {what}: {a} {b}");
        }
    }
}

#[test]
fn fig8_branches_agree_with_the_simulated_steady_gaits() {
    for t_set in [0.3, 0.4] {
        let w = active(t_set, "mu0");
        let ps = [0.1, 0.4, 0.8];
        let opts = ContinuationOptions {
            user_points: ps.to_vec(),
            ..ContinuationOptions::default()
        };
        let b = continuation(&w, 0.0, 1.0, &opts).unwrap();
        agrees_with_simulation(&w, &b, &ps);
    }
}

#[test]
fn fig10_branches_agree_with_the_simulated_steady_gaits_over_mu0_and_over_phi() {
    let ps = [0.3, 0.6];
    let opts = ContinuationOptions {
        user_points: ps.to_vec(),
        ..ContinuationOptions::default()
    };
    let w = passive(0.15, 0.4, "mu0");
    agrees_with_simulation(&w, &continuation(&w, 0.25, 0.7, &opts).unwrap(), &ps);
    let ps = [0.12, 0.18];
    let opts = ContinuationOptions {
        user_points: ps.to_vec(),
        ..ContinuationOptions::default()
    };
    let w = passive(0.15, 0.5, "phi");
    agrees_with_simulation(&w, &continuation(&w, 0.1, 0.2, &opts).unwrap(), &ps);
}

#[test]
fn the_lift_off_boundary_of_t_set_0_2_is_where_the_normal_force_dips_below_zero() {
    let w = active(0.2, "mu0");
    let b = continuation(&w, 0.3, 0.7, &ContinuationOptions::default()).unwrap();
    let lo: Vec<_> = b.labelled(LabelKind::LiftOff).collect();
    assert_eq!(lo.len(), 1);
    let mu_lo = lo[0].parameter;
    // Fig. 8: T_set = 0.2 lifts off at small mu0; our sweep's walks lift off up to 0.45. The
    // located boundary lies above (0.4729): between 0.46 and 0.47 the normal force dips below
    // zero for about 5 ms inside one integrator step, which the walk's sign-change guard does
    // not see (an even number of crossings between two checked points, `ode::Event`).
    assert!((0.45..0.48).contains(&mu_lo), "{mu_lo}");
    assert!(lo[0].tests.min_normal_force.unwrap().abs() < 1e-6);
    assert!(
        !b.points
            .iter()
            .any(|p| p.parameter < mu_lo - 1e-6 && p.physical)
    );
    // The branch's smallest normal force against the simulator's own motion sampled every
    // 1e-5 s (`trajectory`), 2e-3 on either side of the boundary: the same sign, and the same
    // value to 1e-5 (sampling misses the minimum by at most |lambda''| dt^2 / 8, about
    // 4e4 * 1e-10 / 8 = 5e-7 with the curvature of the dip; the located minimum is exact to
    // the integrator's tolerance).
    for p in [mu_lo - 2e-3, mu_lo + 2e-3] {
        let opts = ContinuationOptions {
            user_points: vec![p],
            ..ContinuationOptions::default()
        };
        let b2 = continuation(&w, p - 0.05, p + 0.05, &opts).unwrap();
        let pt = b2.labelled(LabelKind::UserPoint).next().unwrap();
        let model = w.model_at(p).unwrap();
        let s = Section::of(&model).embed(&[pt.state[0], pt.state[1]]);
        let one = WalkLimits {
            max_steps: 1,
            ..WalkLimits::default()
        };
        let tr = trajectory(&model, w.config(), &s, &one, 1e-5, 1_000_000);
        let sampled = tr
            .frames
            .iter()
            .map(|f| f.reaction.normal)
            .fold(f64::INFINITY, f64::min);
        let located = pt.tests.min_normal_force.unwrap();
        assert!((sampled - located).abs() < 1e-5, "{p}: {sampled} {located}");
        assert_eq!(located < 0.0, p < mu_lo);
        assert_eq!(pt.physical, p > mu_lo);
    }
}

#[test]
fn mu0_zero_ends_the_branch_on_the_family_of_cycles() {
    let w = active(0.3, "mu0");
    let b = continuation(&w, 0.0, 0.2, &ContinuationOptions::default()).unwrap();
    assert_eq!(b.ends[0], EndReason::Family);
    let first = &b.points[0];
    assert_eq!(first.label.unwrap().kind, LabelKind::Family);
    assert_eq!(first.parameter, 0.0);
    assert_eq!(first.stability, Stability::Neutral);
    // The structural multiplier is 1 to within the fixed-point search's tolerance.
    assert!(
        first
            .multipliers
            .iter()
            .any(|m| (m.re - 1.0).hypot(m.im) < 1e-6)
    );
    // Every number of every point is finite: no NaN from the singular end.
    for pt in &b.points {
        assert!(
            pt.state
                .iter()
                .chain([&pt.cycle.speed, &pt.cycle.period])
                .all(|v| v.is_finite())
        );
    }
    // The last ordinary point sits 1e-4 of the range from the family, stable.
    assert!(
        (b.points[1].parameter - 2e-5).abs() < 1e-12,
        "{}",
        b.points[1].parameter
    );
    assert_eq!(b.points[1].stability, Stability::Stable);
    // Continuing in T_set at mu0 = 0 finds a family everywhere: an error that says so.
    let setup = common::setup("active-level", &[("mu0", 0.0)]);
    let w = WalkerProblem::new(setup, "T_set", SimConfig::default()).unwrap();
    let e = continuation(&w, 0.25, 0.35, &ContinuationOptions::default()).unwrap_err();
    assert!(
        matches!(e, ContinuationError::FamilyEverywhere { .. }),
        "{e}"
    );
}

#[test]
fn the_held_wheel_over_the_slope_is_the_rimless_wheel_closed_form() {
    // Exact Coulomb friction in stance and at the impact with mu0 = 3 hold the foot: McGeer's
    // rimless wheel (see `rimless_wheel.rs` for the derivation): w0 = eta w1 with
    // w1^2 = K 2 sin(phi) sin(alpha/2) / (1 - eta^2).
    let mut setup = common::setup("passive-slope", &[("mu0", 3.0)]);
    setup.friction = Friction::Coulomb;
    setup.impact = ImpactLaw::Coulomb;
    let w = WalkerProblem::new(setup.clone(), "phi", SimConfig::default()).unwrap();
    let ps = [0.08, 0.12];
    let opts = ContinuationOptions {
        user_points: ps.to_vec(),
        ..ContinuationOptions::default()
    };
    let b = continuation(&w, 0.06, 0.14, &opts).unwrap();
    let p = |name: &str| setup.params.get(name).unwrap();
    let (m, l, i1, g, alpha) = (p("m1") + p("m2"), p("l"), p("I1"), p("g"), p("alpha"));
    let j = i1 + m * l * l;
    let eta = (i1 + m * l * l * alpha.cos()) / j;
    let k = 2.0 * m * g * l / j;
    for (pt, &phi) in b.labelled(LabelKind::UserPoint).zip(&ps) {
        let w1 = (k * 2.0 * phi.sin() * (alpha / 2.0).sin() / (1.0 - eta * eta)).sqrt();
        // The walk-based map integrates to rtol 1e-10; the corrector stops at 1e-11 and the
        // multiplier eta^2 = 0.83 amplifies it by 1 / (1 - 0.83) = 6: 1e-9 as in
        // `rimless_wheel.rs`.
        assert!(
            (pt.state[1] - eta * w1).abs() < 1e-9,
            "{phi}: {} {}",
            pt.state[1],
            eta * w1
        );
        assert!((pt.multipliers[0].modulus() - eta * eta).abs() < 1e-6);
    }
}
