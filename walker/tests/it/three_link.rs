//! The three-link biped with torso of Grizzle, Abba and Plestan (`models/three-link.toml`: legs
//! `r = 1 m` with `m = 5 kg` at `r/2`, hip `M_H = 15 kg`, torso `M_T = 10 kg` at `l = 0.5 m`,
//! two hip torques, outputs `y_torso = th_t` held at `th_T = pi/6` and `y_legs = th_st + th_sw`
//! brought to 0, the strike at `th_st = beta = pi/8`) on a level floor with Coulomb friction.
//!
//! Sources (no one here wrote them):
//!
//! - J. W. Grizzle, G. Abba, F. Plestan, "Asymptotically stable walking for biped robots:
//!   analysis via systems with impulse effects", IEEE TAC 46(1), 2001, and the three-link example
//!   code of E. R. Westervelt et al., *Feedback Control of Dynamic Bipedal Robot Locomotion*,
//!   CRC Press 2007 (the model, its parameters, the outputs and `th3d = pi/6`, `th1d = pi/8`).
//! - Reference values of this model with the foot held (`g = 9.81`, outputs `th_t - pi/6` and
//!   `th_st + th_sw`, strike at `pi/8`), computed independently by a colleague with SymPy and
//!   SciPy (rtol 1e-12, derivatives by finite differences, about 1e-6) and not published:
//!   pre-impact stance rate about 1.6016 rad/s, step period 0.8283 s, speed 0.924 m/s, step
//!   length about 0.765 m, and a heel strike that needs a friction ratio
//!   `|Lambda_t| / Lambda_n` of about 0.575. The reference does not state the controller's
//!   gains; see `with_the_foot_held_the_gait_is_the_references` for what that allows.
//! - Stronge's incremental impact with Coulomb friction as `docs/impacts.md` states it: a foot
//!   that arrives sliding sticks if the friction it can draw makes it press into the floor
//!   (`mu0 >= W_nn / |W_tn|`), and slides on otherwise.
//!
//! What walks and why (the model file's comments say the same): exact Coulomb friction in
//! stance and at the impact, `mu0 >= 0.575`. With `y_legs` near 0 the swing foot skims the
//! floor and strikes it grazing, moving forward at `2 r cos(beta) th_std`, about 2.95 m/s: the
//! impact has to stop a sliding foot, which only friction can do, and only with
//! `mu0 >= W_nn / |W_tn| = 0.5747` (the sticking impulse's ratio). The tanh law never lets the
//! stance foot stick, and the controller of the sliding stance has a singular `A` in every
//! stance.
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use std::path::Path;

use walker::model::{Contact, Friction, ImpactLaw, ImpactRegime, Model, Slide};
use walker::poincare::{FixedPoint, FixedPointOptions, Status, fixed_point};
use walker::setup::{Overrides, Setup};
use walker::sim::{FailureKind, SimConfig, Walk, WalkLimits, control_input, walk};
use walker::vector::Vector;

/// `models/three-link.toml` with the laws `laws` (the file's defaults where `None`) and the
/// parameters `set`.
fn setup(laws: Option<(Friction, ImpactLaw)>, set: &[(&str, f64)]) -> Setup {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../models/three-link.toml");
    let ov = Overrides {
        friction: laws.map(|l| l.0),
        impact: laws.map(|l| l.1),
        set: set.iter().map(|&(n, v)| (n.to_owned(), v)).collect(),
        ..Overrides::default()
    };
    Setup::from_model_file(&path, &ov, None).unwrap()
}

fn model(laws: Option<(Friction, ImpactLaw)>, set: &[(&str, f64)]) -> Model {
    setup(laws, set).model().unwrap()
}

/// Exact Coulomb friction in stance and at the impact.
const COULOMB: Option<(Friction, ImpactLaw)> = Some((Friction::Coulomb, ImpactLaw::Coulomb));

/// The integrator at `rtol = atol = 1e-12`, as the fixed points of the other gait tests.
fn tight() -> SimConfig {
    SimConfig {
        rtol: 1e-12,
        atol: 1e-12,
        ..SimConfig::default()
    }
}

/// The converged period-one gait of `model`, from its start.
fn gait(model: &Model) -> FixedPoint {
    let fp = fixed_point(model, &tight(), &FixedPointOptions::for_model(model)).unwrap();
    assert_eq!(fp.status, Status::Converged, "{fp:?}");
    fp
}

/// A walk of `model` from its start with the default integrator and limits.
fn walk_from_start(model: &Model) -> Walk {
    walk(
        model,
        &SimConfig::default(),
        &model.start_state(),
        &WalkLimits::default(),
    )
}

/// `steps` steps of `model` from `start`, the motion recorded.
fn recorded(model: &Model, cfg: &SimConfig, start: &[f64], steps: usize) -> Walk {
    let limits = WalkLimits {
        max_steps: steps,
        record: true,
        ..WalkLimits::default()
    };
    walk(model, cfg, start, &limits)
}

/// The state `[q, qd]` just before the heel strike that ends step `k` of a recorded walk: the
/// step's last sample, at the end of the integrator's last step, which the strike's event ends
/// (its time is the step's start plus its period, checked).
fn pre_impact(w: &Walk, k: usize) -> Vector {
    let s = w.samples.iter().rev().find(|s| s.step == k).unwrap();
    let end: f64 = w.steps[..=k].iter().map(|s| s.period).sum();
    assert!((s.time - end).abs() < 1e-12, "{} vs {end}", s.time);
    s.state
}

// State indices: q = (x, z, th_st, th_sw, th_t), then their rates.
const TH_ST: usize = 2;
const TH_SW: usize = 3;
const XD: usize = 5;
const TH_STD: usize = 7;
const TH_SWD: usize = 8;
const TH_TD: usize = 9;

/// The swing foot's velocity normal to the floor, `d/dt r (cos th_st - cos th_sw)`, with
/// `r = 1`.
fn swing_foot_normal_velocity(s: &Vector) -> f64 {
    -s[TH_ST].sin() * s[TH_STD] + s[TH_SW].sin() * s[TH_SWD]
}

#[test]
fn at_its_defaults_it_walks_forty_steps_with_exact_coulomb_friction() {
    let s = setup(None, &[]);
    assert_eq!(
        (s.friction, s.impact),
        (Friction::Coulomb, ImpactLaw::Coulomb)
    );
    assert_eq!(s.params.get("mu0"), Some(0.6));
    let m = s.model().unwrap();
    let w = recorded(&m, &SimConfig::default(), &m.start_state(), 40);
    assert!(w.failure.is_none(), "{:?}", w.failure);
    assert_eq!(w.steps.len(), 40);
    for (k, st) in w.steps.iter().enumerate() {
        // Every heel strike stops the new foot (the impulse ratio it needs is 0.5747 < 0.6),
        // and the foot never slips in stance (the stance needs at most 0.49, at its end).
        assert_eq!(st.impact, ImpactRegime::Stick, "step {k}");
        assert_eq!(st.stuck_time, st.period, "step {k}");
        // A heel strike: the swing foot comes down on the floor (y_legs returns to 0 from
        // below, the model's y_lift ramp). At the cycle it approaches at 1.7e-4 m/s: below
        // zero, and grazing (its forward speed is four orders larger).
        let vn = swing_foot_normal_velocity(&pre_impact(&w, k));
        assert!(vn < 0.0 && vn > -1e-2, "step {k}: v_n = {vn}");
    }
}

#[test]
fn the_gait_is_a_stable_period_one_cycle() {
    let m = model(None, &[]);
    let fp = gait(&m);
    println!(
        "T = {:.10} s, V = {:.10} m/s, dx = {:.10} m, largest multiplier modulus {:.6}, \
         impact {:?}",
        fp.period,
        fp.speed,
        fp.dx,
        fp.max_modulus(),
        fp.impact
    );
    assert_eq!(fp.impact, ImpactRegime::Stick);
    // Stable: every multiplier of the reduced map inside the unit circle. It is 0.548; the
    // finite-difference Jacobian (exact Coulomb friction has no Jacobian kernels) is good to
    // about 1e-8 (docs/impacts.md), so the margin of 0.45 is not in doubt.
    assert!(fp.max_modulus() < 1.0, "{:?}", fp.multipliers);
    // The descriptors the model file's comments quote (T = 0.8410 s, V = 0.9102 m/s, 0.548),
    // to their last digit.
    assert!((fp.period - 0.8410).abs() < 1e-4, "T = {}", fp.period);
    assert!((fp.speed - 0.9102).abs() < 1e-4, "V = {}", fp.speed);
    assert!((fp.max_modulus() - 0.548).abs() < 1e-3);
    // The walk from the model's start (the rates rounded to three digits) converges to it: the
    // start is 1e-3 off and contracts by 0.548 a step, 40 steps leave 1e-13; the walk's own
    // integration at rtol 1e-10 leaves about 1e-10 in the period. 1e-8 leaves a margin of 100.
    let w = walk(
        &m,
        &SimConfig::default(),
        &m.start_state(),
        &WalkLimits {
            max_steps: 40,
            ..WalkLimits::default()
        },
    );
    let last = w.steps.last().unwrap();
    assert!(
        (last.period - fp.period).abs() < 1e-8 * fp.period,
        "{} vs {}",
        last.period,
        fp.period
    );
}

/// The pre-impact stance rate, period, speed and step length of the held-foot gait with gains
/// `(kp, kd)` and the outputs held (`y_lift = 0`).
fn held(kp: f64, kd: f64) -> (f64, f64, f64, f64) {
    let m = model(
        COULOMB,
        &[("mu0", 5.0), ("y_lift", 0.0), ("K_P", kp), ("K_D", kd)],
    );
    let fp = gait(&m);
    // The foot is held: after the impact it is at rest.
    assert_eq!(fp.impact, ImpactRegime::Stick);
    assert_eq!(fp.state_plus[XD], 0.0);
    let w = recorded(&m, &tight(), &fp.state_plus, 1);
    (pre_impact(&w, 0)[TH_STD], fp.period, fp.speed, fp.dx)
}

#[test]
fn with_the_foot_held_the_gait_is_the_references() {
    // The reference's settings: the foot held (exact Coulomb friction in stance and at the
    // impact, mu0 = 5), the outputs held at pi/6 and 0 (y_lift = 0: the quintic from 0 to 0 is
    // the hold), the strike at pi/8, g = 9.81. Its gains are not stated, and they matter: the
    // impact is not invariant for these outputs (it leaves them moving, th_std + th_swd at
    // 0.66 rad/s and the torso at 2.03 rad/s), and how the controller brings them back shapes
    // the step. Compare the model's gains (K_P = 100, K_D = 20, critically damped at 10 rad/s)
    // with nearly instantaneous tracking (K_P = 2500, K_D = 100, critically damped at 50
    // rad/s; T changes by 2e-4 relative from there to 800 rad/s).
    let (w_pre, t, v, dx) = held(100.0, 20.0);
    let (w_fast, t_fast, v_fast, dx_fast) = held(2500.0, 100.0);
    println!("K_P = 100:  pre-impact th_std = {w_pre:.7}, T = {t:.7}, V = {v:.7}, dx = {dx:.7}");
    println!(
        "K_P = 2500: pre-impact th_std = {w_fast:.7}, T = {t_fast:.7}, V = {v_fast:.7}, \
         dx = {dx_fast:.7}"
    );
    // The reference lies between the two, in every number: its gait is one of this family,
    // with gains between them. (A model that differed from the reference's in a mass, a
    // length, g or the impact would move the whole family; the family spans 1.0 % in T and
    // 0.45 % in the stance rate, and the reference falls inside both.)
    let between = |x: f64, a: f64, b: f64| x > a.min(b) && x < a.max(b);
    assert!(between(1.6016, w_pre, w_fast), "{w_pre} {w_fast}");
    assert!(between(0.8283, t, t_fast), "{t} {t_fast}");
    assert!(between(0.924, v, v_fast), "{v} {v_fast}");
    // At the model's gains, within the family's spread of the reference: T to 0.6 % (it is
    // 0.51 % off), the stance rate to 0.3 % (0.17 %), V to 0.6 % (0.52 %).
    let rel = |a: f64, b: f64| (a - b).abs() / b;
    assert!(rel(t, 0.8283) < 6e-3, "T = {t}");
    assert!(rel(w_pre, 1.6016) < 3e-3, "th_std- = {w_pre}");
    assert!(rel(v, 0.924) < 6e-3, "V = {v}");
    // The step length does not depend on the gains to the reference's three digits: the legs
    // are symmetric at the strike up to the tracking error (1.3e-4 rad at K_P = 100), so the
    // step is the chord 2 r sin(pi/8) = 0.765367 to 1.3e-4 m.
    let chord = 2.0 * (std::f64::consts::PI / 8.0).sin();
    for d in [dx, dx_fast] {
        assert!(
            (d - chord).abs() < 2e-4 && (d - 0.765).abs() < 5e-4,
            "dx = {d}"
        );
    }
}

/// The first point of `[lo, hi]` (to `tol`) where `walks(mu0)` turns true, `walks(lo)` false and
/// `walks(hi)` true.
fn boundary(mut lo: f64, mut hi: f64, tol: f64, walks: impl Fn(f64) -> bool) -> f64 {
    assert!(!walks(lo) && walks(hi));
    while hi - lo > tol {
        let mid = 0.5 * (lo + hi);
        if walks(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

#[test]
fn it_walks_down_to_the_friction_the_heel_strike_needs() {
    let limits = WalkLimits {
        max_steps: 20,
        ..WalkLimits::default()
    };
    let walk_at = |mu0: f64| {
        let m = model(None, &[("mu0", mu0)]);
        walk(&m, &SimConfig::default(), &m.start_state(), &limits)
    };
    // The sweep of the issue, mu0 from 0 to 1.5 by 0.05, each value from the model's start:
    // it walks from 0.60 on, and fails in the first two steps below.
    for k in 0..=30 {
        let mu0 = 0.05 * f64::from(k);
        let w = walk_at(mu0);
        if k >= 12 {
            assert!(w.failure.is_none(), "mu0 = {mu0}: {:?}", w.failure);
        } else {
            let f = w.failure.unwrap_or_else(|| panic!("mu0 = {mu0} walks"));
            assert!(f.step <= 1, "mu0 = {mu0}: {f:?}");
        }
    }
    // From 0.30 to 0.55 the first step is completed and its heel strike cannot stop the new
    // foot: it slides on forward at about 2.9 m/s (the swing foot arrives grazing, moving at
    // 2 r cos(beta) th_std), and the walker fails right after (lift-off at 0.30,
    // contact-inconsistent from 0.35 to 0.50, where the slide has stopped and the stuck foot
    // needs more than mu0; at 0.55 the torques blow up in the sliding stance).
    for (mu0, name) in [
        (0.30, "lift-off"),
        (0.35, "contact-inconsistent"),
        (0.50, "contact-inconsistent"),
        (0.55, "lambda-numerator-huge"),
    ] {
        let w = walk_at(mu0);
        assert_eq!(w.steps.len(), 1, "mu0 = {mu0}");
        assert_eq!(w.steps[0].impact, ImpactRegime::Slide(Slide::Forward));
        assert!(w.steps[0].qd_plus[0] > 2.5, "mu0 = {mu0}: {:?}", w.steps[0]);
        let f = w.failure.unwrap();
        assert_eq!((f.name(), f.step), (name, 1), "mu0 = {mu0}: {f:?}");
    }
    // The boundary, by bisection to 1e-5: where the first heel strike starts to stick. The
    // reference's ratio, 0.575 to its three digits (0.5745 to 0.5755), is the same threshold:
    // for a foot that arrives grazing, sticking needs mu0 >= W_nn / |W_tn|, which is the
    // sticking impulse's |Lambda_t| / Lambda_n. Our strike posture differs from the
    // reference's by the tracking error (1e-4 rad), which moves the ratio by about 1.5e-4
    // (0.57460 with the outputs held, 0.57475 with the y_lift ramp): 1e-3 covers both.
    let mu_star = boundary(0.55, 0.60, 1e-5, |mu0| {
        walk_at(mu0).steps.first().map(|s| s.impact) == Some(ImpactRegime::Stick)
    });
    println!("the first heel strike sticks from mu0 = {mu_star:.5}");
    assert!((mu_star - 0.575).abs() < 1e-3, "{mu_star}");
    // And that is where walking starts: just above it the walker walks, just below it fails.
    assert!(walk_at(mu_star + 2e-5).failure.is_none());
    assert!(walk_at(mu_star - 2e-5).failure.is_some());
    // The impulse a sticking strike draws is that ratio: the step's reported impulse at the
    // defaults (the first stance holds the foot for every mu0 >= 0.49, so the strike's posture
    // does not depend on mu0) has |Lambda_t| / Lambda_n = mu_star, to the bisection's 1e-5.
    let [lt, ln] = walk_at(0.6).steps[0].foot_impulse;
    assert!(
        ln > 0.0 && lt < 0.0,
        "backward on the forward-sliding foot: {lt} {ln}"
    );
    assert!(
        (lt.abs() / ln - mu_star).abs() < 2e-5,
        "{} vs {mu_star}",
        lt.abs() / ln
    );
}

#[test]
fn the_tanh_law_and_the_frictionless_impact_cannot_walk_it() {
    // The tanh law (c = 100, even with mu0 = 1): the foot creeps, the controller's A is the
    // sliding stance's, and it is singular within the first stance, before mid-stance. At the
    // failure the inputs' sensitivity to the outputs' command, |du| / |dv| for a change of the
    // torso rate by 1e-7 rad/s (dv = K_D 1e-7), is huge with the foot sliding and ordinary
    // with the same state's foot stuck.
    let m = model(Some((Friction::Tanh, ImpactLaw::Coulomb)), &[("mu0", 1.0)]);
    let w = walk_from_start(&m);
    let f = w.failure.unwrap();
    assert_eq!(f.step, 0, "{f:?}");
    assert!(f.state[TH_ST] < 0.0, "before mid-stance: {f:?}");
    let held = model(COULOMB, &[("mu0", 1.0)]);
    let sensitivity = |m: &Model, t: f64, s: &Vector, contact: Contact| {
        let mut ds = *s;
        ds[TH_TD] += 1e-7;
        let (u, du) = (
            control_input(m, t, &s[..], contact),
            control_input(m, t, &ds[..], contact),
        );
        (du[0] - u[0]).hypot(du[1] - u[1]) / (20.0 * 1e-7)
    };
    let sliding = sensitivity(&m, f.t, &f.state, Contact::Smooth);
    let stuck = sensitivity(&held, f.t, &f.state, Contact::Stuck);
    let start = sensitivity(&m, 0.0, &m.start_state(), Contact::Smooth);
    println!(
        "tanh: {} at t = {} s; |du|/|dv| there {sliding:.3e} (the foot stuck: {stuck:.3e}), \
         at the start {start:.3e}",
        f.name(),
        f.t
    );
    assert!(
        sliding > 1e3 * stuck.max(start),
        "{sliding} {stuck} {start}"
    );
    // The paper's frictionless impact: the grazing strike needs almost no normal impulse, and
    // the old stance foot would stay on the floor (its test impulse is 7e-5 N s, not negative):
    // double support at the first strike.
    let m = model(
        Some((Friction::Coulomb, ImpactLaw::Frictionless)),
        &[("mu0", 1.0)],
    );
    let w = walk_from_start(&m);
    let f = w.failure.unwrap();
    assert_eq!((f.name(), f.step), ("double-support", 0), "{f:?}");
    // With the outputs held (y_lift = 0) the swing foot is rising at the 'strike' (v_n > 0):
    // the frictionless map, which stops the normal velocity whatever its sign, would pull it
    // onto the floor with a tiny negative impulse (the sticking impact's is 24.6 N s). That is
    // no impact, and the walk ends there, named; it is why the model ramps y_legs from y_lift,
    // so that its foot comes down.
    let m = model(
        Some((Friction::Coulomb, ImpactLaw::Frictionless)),
        &[("mu0", 1.0), ("y_lift", 0.0)],
    );
    let f = walk_from_start(&m).failure.unwrap();
    assert_eq!((f.name(), f.step), ("impact-pulls", 0), "{f:?}");
    let FailureKind::ImpactPulls { normal_impulse } = f.kind else {
        panic!("{f:?}")
    };
    assert!(
        normal_impulse < 0.0 && normal_impulse > -0.01,
        "{normal_impulse}"
    );
}
