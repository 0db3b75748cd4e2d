//! The Poincare map's Jacobian covers the impact with friction: within the impact's regime
//! (stick, slide or reverse) the variational Jacobian, with the impact's derivative of
//! `poincare::impact_jacobian` (exact in the velocities, a central difference in `th1`),
//! agrees with central differences of the map itself.
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use crate::common;

use walker::model::{ImpactLaw, ImpactRegime, Model, Slide};
use walker::poincare::{FixedPointOptions, fixed_point, poincare_map};
use walker::sim::SimConfig;

fn passive(mu0: f64) -> Model {
    common::passive(&[("phi", 0.1), ("mu0", mu0)]).with_impact_law(ImpactLaw::Coulomb)
}

fn active(mu0: f64) -> Model {
    common::active(&[("mu0", mu0), ("T_set", 0.3)]).with_impact_law(ImpactLaw::Coulomb)
}

/// Largest difference between the map's Jacobian and central differences of the map at its
/// fixed point, over the columns `th1 .. th2d` (those of `x`, `z` are zero), scaled by
/// `max(1, |entry|)`; and the regime of the cycle's impact.
fn jacobian_error(model: &Model) -> (f64, ImpactRegime) {
    // Steps integrated to 1e-12 and a difference step of 1e-4: the differences are good to
    // about 1e-12 / 1e-4 + (1e-4)^2 = 1e-8.
    let cfg = SimConfig {
        rtol: 1e-12,
        atol: 1e-14,
        ..SimConfig::default()
    };
    let fp = fixed_point(model, &cfg, &FixedPointOptions::for_model(model)).unwrap();
    let s = fp.state_plus;
    let m = poincare_map(model, &cfg, &s).unwrap();
    let mut worst: f64 = 0.0;
    for j in 2..8 {
        let h = 1e-4;
        let (mut up, mut down) = (s, s);
        up[j] += h;
        down[j] -= h;
        let (pu, pd) = (
            poincare_map(model, &cfg, &up).unwrap(),
            poincare_map(model, &cfg, &down).unwrap(),
        );
        assert_eq!(
            (pu.impact, pd.impact),
            (m.impact, m.impact),
            "column {j} stays in the regime"
        );
        for i in 0..8 {
            let fd = (pu.state_plus[i] - pd.state_plus[i]) / (2.0 * h);
            let e = (fd - m.jacobian[i][j]).abs() / m.jacobian[i][j].abs().max(1.0);
            worst = worst.max(e);
        }
    }
    (worst, m.impact)
}

#[test]
fn the_maps_jacobian_covers_a_sticking_impact() {
    for model in [passive(0.7), active(0.4)] {
        let (err, regime) = jacobian_error(&model);
        assert_eq!(regime, ImpactRegime::Stick);
        // 1e-8 expected from the differences (see `jacobian_error`); 1e-6 is a margin of 100.
        assert!(err < 1e-6, "{regime:?}: {err:e}");
    }
}

#[test]
fn the_maps_jacobian_covers_an_impact_whose_slip_reverses() {
    // At small mu0 the fore foot strikes slipping backwards, stops within the impact and slips
    // forwards until it ends (Stronge's third phase).
    for model in [passive(0.2), active(0.1)] {
        let (err, regime) = jacobian_error(&model);
        assert_eq!(regime, ImpactRegime::Reverse(Slide::Backward));
        assert!(err < 1e-6, "{regime:?}: {err:e}");
    }
}
