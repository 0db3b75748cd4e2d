//! The design's swing-foot clearance (`walker::design`, `docs/design.md`): which walkers have a
//! swing foot, what the clearance the design reports means in a walk of the simulator alone,
//! and why a straight-legged biped has none to give.
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use std::path::Path;

use walker::design::{SAMPLES, clearance_profile, evaluate, rigid_strike_point, swing_height};
use walker::model::{Friction, ImpactLaw};
use walker::setup::{Overrides, Setup};
use walker::sim::{SimConfig, WalkLimits, trajectory};

/// `models/NAME.toml` with exact Coulomb friction in stance and at the impact where `coulomb`.
fn setup(name: &str, coulomb: bool) -> Setup {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../models/{name}.toml"));
    let ov = Overrides {
        friction: coulomb.then_some(Friction::Coulomb),
        impact: coulomb.then_some(ImpactLaw::Coulomb),
        ..Overrides::default()
    };
    Setup::from_model_file(&path, &ov, None).unwrap()
}

#[test]
fn a_walker_whose_striking_point_is_fixed_to_the_stance_foot_has_no_swing_foot() {
    // The rimless wheel's fore spoke and the paper's walker's fore foot stay 2 l sin(alpha / 2)
    // from the stance foot in every posture; the bipeds' swing feet do not.
    for name in ["rimless-wheel", "paper-active", "paper-passive"] {
        let m = setup(name, false).model().unwrap();
        let why = rigid_strike_point(&m).unwrap_or_else(|| panic!("{name}"));
        assert!(why.contains("fore_foot"), "{name}: {why}");
    }
    for name in ["three-link", "compass-gait"] {
        let m = setup(name, false).model().unwrap();
        assert_eq!(rigid_strike_point(&m), None, "{name}");
    }
}

/// The swing foot's height above the level floor at the coordinates `q` of the three-link
/// biped, written out from the model file's `swing_foot` point (not through the design's
/// code): `z + r (cos(th_st) - cos(th_sw))` less the stance foot's `z`.
fn three_link_swing_height(r: f64, q: &[f64]) -> f64 {
    r * (q[2].cos() - q[3].cos())
}

#[test]
fn the_reported_clearance_is_the_simulated_walks_and_a_straight_legged_biped_has_none() {
    // The three-link biped at its defaults (the hand-made gait, held on mu0 = 0.6).
    let s = setup("three-link", true);
    let cfg = SimConfig::default();
    let beta = s.params.get("beta").unwrap();
    let e = evaluate(&s, &cfg, &["beta"], &[beta], None, false, true).unwrap();
    let clearance = e.clearance.unwrap();
    let period = e.fixed_point.period;

    // The simulator alone: one step from the design's fixed point, recorded at the design's
    // sample times `k T / SAMPLES`, the height written out from the model file's geometry.
    let mut held = s.clone();
    held.set("beta", beta).unwrap();
    let model = held.model().unwrap();
    let limits = WalkLimits {
        max_steps: 1,
        ..WalkLimits::default()
    };
    let r = model.param("r");
    let walk = |samples: usize| {
        let dt = period / samples as f64;
        let tr = trajectory(
            &model,
            &cfg,
            &e.fixed_point.state_plus,
            &limits,
            dt,
            samples + 8,
        );
        assert!(tr.walk.failure.is_none());
        tr.frames
            .into_iter()
            .filter(|f| f.step == 0 && f.t > 0.0 && f.t < period)
            .map(|f| {
                let h = three_link_swing_height(r, &f.state.as_slice()[..5]);
                (f.t, h, h / clearance_profile(f.t / period))
            })
            .collect::<Vec<_>>()
    };
    let same = walk(SAMPLES);
    let walked = same.iter().map(|x| x.2).fold(f64::INFINITY, f64::min);
    // The same integration from the same state at the same times: equal up to the rounding of
    // `h / (4 s (1 - s))` near the ends (1e-12 m allows it a thousand-fold).
    assert!(
        (walked - clearance).abs() <= 1e-12,
        "{walked} vs {clearance}"
    );

    // Straight legs: where the swing leg passes the vertical its foot is `r (cos(th_st) - 1)
    // <= 0` from the floor, so no gait of this biped clears the floor over its whole stance,
    // whatever the controller: the clearance it reports is not positive. On a grid ten times
    // finer the smallest height of the stance is at most a few micrometres from the 400
    // samples' (its bound: `(dt / 2)^2 |h''| / 2` with `dt = T / 400` = 2.1 ms and `|h''|` of
    // a few m/s^2, about 5e-6 m).
    assert!(clearance <= 0.0, "{clearance}");
    let min_h = |w: &[(f64, f64, f64)]| w.iter().map(|x| x.1).fold(f64::INFINITY, f64::min);
    let fine = walk(10 * SAMPLES);
    assert!(min_h(&fine) <= 0.0);
    assert!(
        (min_h(&fine) - min_h(&same)).abs() <= 5e-6,
        "{} vs {}",
        min_h(&fine),
        min_h(&same)
    );
}

#[test]
fn on_a_slope_the_height_is_measured_normal_to_the_floor_line() {
    // The compass gait starts just after a strike with both feet on its slope (`th_st + th_sw
    // = 2 phi`): the swing foot, behind and uphill, is above the stance foot vertically but
    // on the floor line, so its height normal to the floor is 0.
    let m = setup("compass-gait", false).model().unwrap();
    let phi = m.phi();
    assert!(phi > 0.0);
    let mut q = m.start_state().as_slice()[..m.n()].to_vec();
    let l = m.param("a") + m.param("b");
    let lift = |q: &[f64]| l * ((q[2]).cos() - (q[3]).cos());
    assert!(lift(&q) > 1e-3, "{}", lift(&q));
    assert!(
        swing_height(&m, &q).abs() <= 1e-12,
        "{}",
        swing_height(&m, &q)
    );
    // The swing leg 0.1 rad more inclined than the stance leg (both feet ahead of the hip):
    // the foot is off the floor by l (cos(th_st - phi) - cos(th_sw - phi)) along the normal
    // (the legs' angles measured from the slope's normal instead of the vertical).
    q[3] = q[2] - 0.1;
    let want = l * ((q[2] - phi).cos() - (q[3] - phi).cos());
    assert!(want > 0.0);
    assert!(
        (swing_height(&m, &q) - want).abs() <= 1e-12,
        "{} vs {want}",
        swing_height(&m, &q)
    );
}
