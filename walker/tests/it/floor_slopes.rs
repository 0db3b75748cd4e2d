//! Walks on a slope per step (`walker::floor`, `docs/floors.md`, "A slope per step"): step
//! `k` walks on the line of slope `phi_k` through its stance foot, computed as the model's step
//! at `phi = phi_k` from the state moved so that the foot is at the origin. A floor of one
//! slope is the plain walk bit for bit; a walk on changing slopes is the same walk run one
//! step at a time; each strike lands on its step's line; a sliding foot meeting a new slope
//! ends the walk by name; a slope the walker cannot take is refused by name.

use walker::floor::{FloorError, FloorPlan, FloorSpec, FloorWalker};
use walker::model::{Friction, ImpactLaw};
use walker::setup::{Overrides, Setup};
use walker::sim::{SimConfig, StepResult, Walk, WalkLimits, walk};

fn limits(max_steps: usize) -> WalkLimits {
    WalkLimits {
        max_steps,
        ..WalkLimits::default()
    }
}

/// The passive rimless wheel of `models/rimless-wheel.toml` on its slope 0.2 under exact
/// Coulomb friction in stance and at the strike with `mu0 = 0.8`: its strikes stick (the new
/// foot is at rest), so a change of slope meets no sliding foot.
fn wheel(impact: ImpactLaw) -> Setup {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../models/rimless-wheel.toml");
    let ov = Overrides {
        friction: Some(Friction::Coulomb),
        impact: Some(impact),
        set: vec![("mu0".into(), 0.8), ("omega0".into(), 1.5)],
        ..Overrides::default()
    };
    Setup::from_model_file(&path, &ov, None).expect("the shipped model")
}

/// The compass gait of `models/compass-gait.toml` on its 3 degree slope under exact Coulomb
/// friction in stance and at the strike with `mu0 = 0.8` (its strikes stick there).
fn compass() -> Setup {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../models/compass-gait.toml");
    let ov = Overrides {
        friction: Some(Friction::Coulomb),
        impact: Some(ImpactLaw::Coulomb),
        set: vec![("mu0".into(), 0.8)],
        ..Overrides::default()
    };
    Setup::from_model_file(&path, &ov, None).expect("the shipped model")
}

fn on(setup: &Setup, floor: FloorPlan, steps: usize) -> Walk {
    let start = setup.model().expect("model").start_state();
    FloorWalker::new(setup, floor)
        .expect("a floor the walker takes")
        .walk(0, &SimConfig::default(), &start, &limits(steps))
        .expect("the walk's models")
}

fn slopes(phi: &[f64]) -> FloorPlan {
    FloorPlan {
        mu0: None,
        phi: Some(FloorSpec::Steps { mu0: phi.to_vec() }),
    }
}

fn json(w: &Walk) -> String {
    let mut w = w.clone();
    for s in &mut w.steps {
        s.floor = None;
    }
    serde_json::to_string(&w).expect("a walk serialises")
}

#[test]
fn a_floor_of_one_slope_is_the_plain_walk_at_that_slope_bit_for_bit() {
    // The walker's own slope, and another one: in both the step's floor stays the line
    // through the origin (the start's foot), so nothing is moved and the arithmetic is the
    // plain walk's.
    let setup = wheel(ImpactLaw::Coulomb);
    for phi in [0.2, 0.23] {
        let at = setup.with("phi", phi).expect("phi");
        let model = at.model().expect("model");
        let start = setup.model().expect("model").start_state();
        let plain = walk(&model, &SimConfig::default(), &start, &limits(12));
        let floored = on(&setup, slopes(&[phi]), 12);
        assert_eq!(plain.steps.len(), 12, "{:?}", plain.failure);
        assert_eq!(json(&floored), json(&plain), "phi = {phi}");
        assert!(
            floored
                .steps
                .iter()
                .all(|s| s.floor.and_then(|f| f.phi) == Some(phi))
        );
    }
}

/// The point step `k` is seen from, as `docs/floors.md` states it: the stance foot where the
/// slope changes, else the point of the step before (the origin before the first change).
fn pieces(setup: &Setup, phi: &[f64], mu0: &[f64]) -> Vec<StepResult> {
    let mut state = setup.model().expect("model").start_state();
    let (mut before, mut point) = (setup.params.get("phi").expect("phi"), [0.0, 0.0]);
    let mut steps = Vec::new();
    for (&p, &m) in phi.iter().zip(mu0) {
        if p.to_bits() != before.to_bits() {
            point = [state[0], state[1]];
            before = p;
        }
        let model = setup
            .with("phi", p)
            .and_then(|s| s.with("mu0", m))
            .expect("values in range")
            .model()
            .expect("model");
        let mut moved = state;
        moved[0] -= point[0];
        moved[1] -= point[1];
        let w = walk(&model, &SimConfig::default(), &moved, &limits(1));
        let mut step = w.steps[0];
        step.q_plus[0] += point[0];
        step.q_plus[1] += point[1];
        state = step.state_plus();
        steps.push(step);
    }
    steps
}

#[test]
fn a_walk_on_changing_slopes_is_the_same_walk_run_one_step_at_a_time() {
    let setup = wheel(ImpactLaw::Coulomb);
    let phi = [0.2, 0.24, 0.17, 0.17, 0.22, 0.2, 0.26, 0.19];
    let mu0 = [0.8, 0.8, 0.7, 0.9, 0.9, 0.8, 0.75, 0.8];
    let floor = FloorPlan {
        mu0: Some(FloorSpec::Steps { mu0: mu0.to_vec() }),
        phi: Some(FloorSpec::Steps { mu0: phi.to_vec() }),
    };
    let floored = on(&setup, floor, phi.len());
    assert_eq!(floored.steps.len(), phi.len(), "{:?}", floored.failure);
    let alone = pieces(&setup, &phi, &mu0);
    for (k, (a, b)) in floored.steps.iter().zip(&alone).enumerate() {
        // The same arithmetic (the integrator starts each step afresh); the bound
        // 1e-12 relative to the state's size (a few metres after some steps) is what is
        // promised.
        let (sa, sb) = (a.state_plus(), b.state_plus());
        let scale = sa.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
        for (x, y) in sa.iter().zip(sb.iter()) {
            assert!((x - y).abs() <= 1e-12 * scale, "step {k}: {sa:?} vs {sb:?}");
        }
        assert_eq!(a.period.to_bits(), b.period.to_bits(), "step {k}");
        let f = a.floor.expect("a floor step");
        assert_eq!((f.mu0, f.phi), (mu0[k], Some(phi[k])));
    }
}

#[test]
fn the_compass_gait_on_changing_slopes_is_the_same_walk_run_one_step_at_a_time() {
    // Four coordinates and a fall that watches a point (the hip's height above the floor):
    // the same construction, the same bound as for the wheel.
    let setup = compass();
    let phi = [0.0524, 0.056, 0.05, 0.05, 0.054, 0.0524];
    let mu0 = [0.8; 6];
    let floored = on(&setup, slopes(&phi), phi.len());
    assert_eq!(floored.steps.len(), phi.len(), "{:?}", floored.failure);
    for (k, (a, b)) in floored
        .steps
        .iter()
        .zip(&pieces(&setup, &phi, &mu0))
        .enumerate()
    {
        let (sa, sb) = (a.state_plus(), b.state_plus());
        let scale = sa.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
        for (x, y) in sa.iter().zip(sb.iter()) {
            assert!((x - y).abs() <= 1e-12 * scale, "step {k}: {sa:?} vs {sb:?}");
        }
    }
}

#[test]
fn each_strike_lands_on_the_line_of_its_steps_slope_through_its_stance_foot() {
    // Independent of how a step is computed: the new foot is on step k's floor. The wheel's
    // strike guard puts the fore spoke's end on the slope exactly; event location and
    // rounding leave it within 1e-9 m.
    let setup = wheel(ImpactLaw::Coulomb);
    let phi = [0.2, 0.25, 0.15, 0.15, 0.3, 0.1];
    let w = on(&setup, slopes(&phi), phi.len());
    assert_eq!(w.steps.len(), phi.len(), "{:?}", w.failure);
    let mut foot = [0.0, 0.0];
    for (k, s) in w.steps.iter().enumerate() {
        let next = [s.q_plus[0], s.q_plus[1]];
        let (dx, dz) = (next[0] - foot[0], next[1] - foot[1]);
        // Off the line of slope phi_k through the foot: the normal distance.
        let off = dx * phi[k].sin() + dz * phi[k].cos();
        assert!(off.abs() < 1e-9, "step {k}: {off:e} m off its floor");
        assert!(dx > 0.1, "step {k} walks forward: {dx}");
        foot = next;
    }
}

#[test]
fn a_foot_sliding_onto_a_new_slope_ends_the_walk_by_name_without_nan() {
    // The paper's frictionless strike leaves the new foot sliding: a change of slope is then a
    // kink the model has no impact for, and the walk ends there, its state finite.
    let setup = wheel(ImpactLaw::Frictionless);
    let w = on(&setup, slopes(&[0.2, 0.2, 0.2, 0.25]), 6);
    let f = w.failure.as_ref().expect("the kink ends the walk");
    assert_eq!((f.name(), f.step, w.steps.len()), ("slope-kink", 3, 3));
    assert!(f.state.iter().all(|x| x.is_finite()));
    let j = serde_json::to_value(f).expect("json");
    assert_eq!(
        (j["from"].as_f64(), j["to"].as_f64()),
        (Some(0.2), Some(0.25))
    );
    assert!(
        j["speed"]
            .as_f64()
            .is_some_and(|v| v > 0.0 && v.is_finite())
    );
    // The same slope throughout is no kink.
    assert_eq!(on(&setup, slopes(&[0.2]), 6).failure, None);
}

#[test]
fn a_slope_the_walker_cannot_take_is_refused_naming_the_field_and_the_range() {
    let setup = wheel(ImpactLaw::Coulomb);
    let e = FloorWalker::new(&setup, slopes(&[0.2, -0.1])).expect_err("below the range");
    assert_eq!(
        e.to_string(),
        "floor field `phi[1]` = -0.1: outside the range [0, pi/2) of `phi` in model \
         `rimless-wheel`"
    );
    let random = FloorPlan {
        mu0: None,
        phi: Some(FloorSpec::Random {
            seed: 1,
            mu0: walker::floor::Distribution::Uniform { lo: 0.1, hi: 1.7 },
        }),
    };
    let e = FloorWalker::new(&setup, random).expect_err("above the range");
    assert!(
        e.to_string()
            .starts_with("floor field `phi.hi` = 1.7: outside"),
        "{e}"
    );
    // A level walker has no slope to set.
    let level = Setup::active_level().expect("the built-in scene");
    let e = FloorWalker::new(&level, slopes(&[0.1])).expect_err("no slope");
    assert!(matches!(e, FloorError::NoSlope { .. }), "{e}");
    assert!(
        e.to_string().contains("no slope angle (`[floor] slope`)"),
        "{e}"
    );
    // A scene that fixes the slope at generation (as `compass-gait-3deg` does; here the
    // wheel's setup says so itself).
    let mut fixed = setup.clone();
    fixed.fixed.push(("phi".into(), 0.2));
    let e = FloorWalker::new(&fixed, slopes(&[0.05])).expect_err("fixed");
    assert!(
        e.to_string()
            .starts_with("the scene fixes `phi` = 0.2 at generation ([fix]); a floor sets `phi`"),
        "{e}"
    );
}
