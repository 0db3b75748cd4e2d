//! The Jacobian of the impact map with Coulomb friction at the striking foot, within the
//! regime the impact takes.
//!
//! The map is continuous but only piecewise smooth: Stronge's impulse
//! ([`crate::model::plastic_coulomb`]) switches between sticking, slipping one way and
//! reversing where the required impulse reaches the friction cone's edge or the slip stops
//! exactly at the end of compression. Within one regime `qdot+` is linear in the pre-impact
//! velocities at a fixed `th1` (`qdl`, the contact velocities and every phase's impulse are),
//! so the velocities' columns are the map of the regime
//! ([`crate::model::in_regime`]) at unit velocities: exact. The coordinates' columns are
//! Richardson-extrapolated central differences of the same regime's map (steps `1e-3` and
//! `2e-3`, [`COORDINATE_STEP`]; error about `2e-10`). Plain central differences with the step
//! `6e-6` lost four digits on the simplest walking model, whose light feet make the impact's
//! Delassus matrix ill-conditioned (its multipliers were off by `2e-8`); a derived Jacobian of
//! the ingredients (`impact_coulomb`) would make these columns exact too. On a switch the derivative does not exist;
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
    // Coordinates: extrapolated central differences (x and z move nothing: their columns are
    // zero).
    for j in 2..n {
        let col = coordinate_column(&map, pre, j)?;
        for i in 0..n {
            out[i * m + j] = col[i];
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

/// `d qd+ / d mu0` of the impact with friction at the pre-impact state `pre`, in `regime` (`n`
/// numbers): Richardson-extrapolated central differences of the regime's map in `mu0` (the
/// algebraic map of [`crate::model::in_regime`], as for the coordinates' columns above: error
/// about `2e-10`); `None` where the regime's map is not defined at a point of the stencil.
pub(crate) fn coulomb_impact_mu0_rate(
    model: &Model,
    pre: &[f64],
    regime: ImpactRegime,
) -> Option<Vec<f64>> {
    let ing = model.impact_ingredients(&Vector::from_slice(pre));
    let map = |mu0: &Vector| in_regime(&ing, mu0[0], regime).map(|l| ing.velocity(l));
    coordinate_column(&map, &[model.mu0()], 0)
}

/// `d qd+_i / d [q, qd]_j` of the frictionless impact map ([`Model::impact`]) at the pre-impact
/// state `pre`, for a model without the `impact_jacobian` kernel (no closed form): the map is
/// linear in the velocities at fixed coordinates (`qd+ = (I - M^-1 J^T (J M^-1 J^T)^-1 J) qd`),
/// so the velocities' columns are the map at unit velocities (exact), and the coordinates'
/// columns extrapolated central differences as above; row-major, `n` rows of `2n`.
pub(crate) fn frictionless_impact_jacobian(model: &Model, pre: &[f64]) -> Vec<f64> {
    let n = model.n();
    let m = 2 * n;
    let map = |s: &Vector| {
        model
            .impact(s)
            .map_or_else(|_| Vector::from_slice(&vec![f64::NAN; n]), |r| r.qd)
    };
    let mut out = vec![0.0; n * m];
    for j in 2..n {
        let col = coordinate_column(&|s: &Vector| Some(map(s)), pre, j).unwrap_or_default();
        for (i, c) in col.iter().enumerate() {
            out[i * m + j] = *c;
        }
    }
    for col in n..m {
        let mut unit = Vector::from_slice(pre);
        unit[n..].fill(0.0);
        unit[col] = 1.0;
        let q = map(&unit);
        for i in 0..n {
            out[i * m + col] = q[i];
        }
    }
    out
}

/// The step of [`coordinate_column`]'s differences (radians): the map is evaluated to about
/// `1e-13` (with light feet the impact's Delassus matrix is ill-conditioned: `m = 1e-4` loses
/// about three digits), so the rounding part of the error is about `2e-13 / h`, `2e-10`; the
/// truncation error of the extrapolated difference is `O(h^4)`, below `1e-12` for the
/// derivatives of order one the impacts have.
const COORDINATE_STEP: f64 = 1e-3;

/// `d map / d s_j` at `pre` for a coordinate `j`, by Richardson's extrapolation of central
/// differences with the steps `h` and `2h` ([`COORDINATE_STEP`]): `(4 D(h) - D(2h)) / 3`.
/// `None` where the map is not defined at a point of the stencil.
fn coordinate_column(
    map: &impl Fn(&Vector) -> Option<Vector>,
    pre: &[f64],
    j: usize,
) -> Option<Vec<f64>> {
    let h = COORDINATE_STEP;
    let central = |h: f64| -> Option<Vec<f64>> {
        let (mut up, mut down) = (Vector::from_slice(pre), Vector::from_slice(pre));
        up[j] += h;
        down[j] -= h;
        let (a, b) = (map(&up)?, map(&down)?);
        let width = up[j] - down[j];
        Some(
            a.iter()
                .zip(b.iter())
                .map(|(a, b)| (a - b) / width)
                .collect(),
        )
    };
    let (d1, d2) = (central(h)?, central(2.0 * h)?);
    Some(
        d1.iter()
            .zip(&d2)
            .map(|(a, b)| (4.0 * a - b) / 3.0)
            .collect(),
    )
}
