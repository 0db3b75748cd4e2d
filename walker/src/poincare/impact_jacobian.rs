//! The Jacobian of the impact map with Coulomb friction at the striking foot, within the
//! regime the impact takes.
//!
//! The map is continuous but only piecewise smooth: Stronge's impulse
//! ([`crate::model::plastic_coulomb`]) switches between sticking, slipping one way and
//! reversing where the required impulse reaches the friction cone's edge or the slip stops
//! exactly at the end of compression. Within one regime `qdot+` is linear in the pre-impact
//! velocities at a fixed `th1` (`qdl`, the contact velocities and every phase's impulse are),
//! so the velocities' columns are the map of the regime
//! ([`crate::model::in_regime`]) at unit velocities: exact. The coordinates' columns are central
//! differences of the same regime's map with the step `6e-6` (about the cube root of the
//! machine epsilon; error about `1e-10` relative). On a switch the derivative does not exist;
//! what is returned is the one-sided derivative of the regime found at the point, and the
//! fixed-point search reports the regime and its margin so that a multiplier computed there
//! can be read for what it is.

use crate::model::{ImpactRegime, Model, in_regime};
use crate::vector::Vector;

/// `d qd+_i / d [q, qd]_j` of the impact with friction at the pre-impact state `pre`, in
/// `regime`, row-major (`n` rows of `2n`); `None` where the regime's map is not defined (a
/// phase's denominator vanishes).
pub(crate) fn coulomb_impact_jacobian(
    model: &Model,
    pre: &[f64],
    regime: ImpactRegime,
) -> Option<Vec<f64>> {
    let mu0 = model.mu0();
    let n = model.n();
    let m = 2 * n;
    let map = |s: &Vector| {
        let ing = model.impact_ingredients(s);
        in_regime(&ing, mu0, regime).map(|l| ing.velocity(l))
    };
    let mut out = vec![0.0; n * m];
    // Coordinates: central differences (x and z move nothing: their columns are zero).
    let h = 6e-6;
    for j in 2..n {
        let (mut up, mut down) = (Vector::from_slice(pre), Vector::from_slice(pre));
        up[j] += h;
        down[j] -= h;
        let (qu, qdn) = (map(&up)?, map(&down)?);
        for i in 0..n {
            out[i * m + j] = (qu[i] - qdn[i]) / (up[j] - down[j]);
        }
    }
    // Velocities: the map is linear in them, so a column is the map at a unit velocity.
    for col in n..m {
        let mut unit = Vector::from_slice(pre);
        unit[n..].fill(0.0);
        unit[col] = 1.0;
        let q = map(&unit)?;
        for i in 0..n {
            out[i * m + col] = q[i];
        }
    }
    Some(out)
}
