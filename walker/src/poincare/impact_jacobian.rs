//! The Jacobian of the impact map with Coulomb friction at the striking foot, within the
//! regime the impact takes.
//!
//! The map is continuous but only piecewise smooth: Stronge's impulse
//! ([`crate::model::plastic_coulomb`]) switches between sticking, slipping one way and
//! reversing where the required impulse reaches the friction cone's edge or the slip stops
//! exactly at the end of compression. Within one regime `qdot+` is linear in the pre-impact
//! velocities at a fixed `th1` (`qdl`, the contact velocities and every phase's impulse are),
//! so the columns for `(xd, zd, th1d, th2d)` are the map of the regime
//! ([`crate::model::in_regime`]) at unit velocities: exact. The column for `th1` is a central
//! difference of the same regime's map with the step `6e-6` (about the cube root of the
//! machine epsilon; error about `1e-10` relative). On a switch the derivative does not exist;
//! what is returned is the one-sided derivative of the regime found at the point, and the
//! fixed-point search reports the regime and its margin so that a multiplier computed there
//! can be read for what it is.

use crate::model::{ImpactRegime, Model, in_regime};

/// `d qd+_i / d (th1, xd, zd, th1d, th2d)` of the impact with friction at the pre-impact state
/// `pre`, in `regime`; `None` where the regime's map is not defined (a phase's denominator
/// vanishes).
pub(crate) fn coulomb_impact_jacobian(
    model: &Model,
    pre: &[f64; 8],
    regime: ImpactRegime,
) -> Option<[[f64; 5]; 4]> {
    let mu0 = model.runtime.mu0;
    let map = |s: &[f64; 8]| {
        let ing = model.impact_ingredients(s);
        in_regime(&ing, mu0, regime).map(|l| ing.velocity(l))
    };
    let mut out = [[0.0; 5]; 4];
    // th1: central difference.
    let h = 6e-6;
    let (mut up, mut down) = (*pre, *pre);
    up[2] += h;
    down[2] -= h;
    let (qu, qdn) = (map(&up)?, map(&down)?);
    for i in 0..4 {
        out[i][0] = (qu[i] - qdn[i]) / (up[2] - down[2]);
    }
    // Velocities: the map is linear in them, so a column is the map at a unit velocity.
    for (c, col) in [4, 5, 6, 7].into_iter().enumerate() {
        let mut unit = *pre;
        unit[4..].fill(0.0);
        unit[col] = 1.0;
        let q = map(&unit)?;
        for i in 0..4 {
            out[i][c + 1] = q[i];
        }
    }
    Some(out)
}
