//! How far each multiplier of a fixed point may lie from the exact map's: a bound from the
//! reduced Jacobian's own error and each eigenvalue's condition number.
//!
//! # The Jacobian's error
//!
//! The reduced Jacobian `J = D P_r` at a fixed point carries an error `E`, which
//! [`jacobian_error`] estimates by a second evaluation that is an order more accurate, at the
//! same state:
//!
//! - **variational equations** (`Phi` under the state's error control): the map again at a
//!   tenth of the tolerances the map uses (`rtol = min(rtol, 1e-12) / 10`, `atol = min(atol,
//!   1e-14) / 10`; the paper's Table-1 variants use the configuration's `rtol = 1e-10`, so theirs
//!   is a thousandth). The global error of DOP853 falls about in proportion to the tolerance, so
//!   the second Jacobian's error is about a tenth of the first's and `J - J'` is `E` to about 10 %;
//! - **central differences** (the fallback where a phase has no Jacobian kernel) of step `h`: the
//!   error is `h^2 P''' / 6` plus the map's noise over `h`; at `h / 2` the first part is a
//!   quarter, so `J_h - J_{h/2}` is three quarters of the truncation error of `J_h`;
//! - **extrapolated differences** `R(h) = (4 J_{h/2} - J_h) / 3` (`walker fixed-point`'s
//!   refinement of the fallback): the error is `O(h^4)` plus the noise over `h` amplified by up
//!   to `5/3`; `R(h/2)` from `J_{h/2}` and `J_{h/4}` has a sixteenth of the first part, so
//!   `R(h) - R(h/2)` is fifteen sixteenths of `R(h)`'s truncation error, and the noise at the
//!   smaller step is at most twice `R(h)`'s.
//!
//! Either way the estimate is `E = 2 (J - J') + 10 rtol |J|` entry by entry, `rtol = min(rtol,
//! 1e-12)`: the factor two covers the 10 % and the 4/3 above with room (and a noise term that the
//! two evaluations do not share); the second term is a floor, the integration's relative
//! tolerance with the usual factor ten between a step's local error and a stance's global one,
//! so that no entry is claimed more accurate than the integration can make it, and it covers
//! the rounding of parts the two evaluations share (the impact's coordinate columns under
//! Coulomb friction are extrapolated differences in both, `impact_jacobian.rs`).
//!
//! # The eigenvalues' error
//!
//! A simple eigenvalue `lambda` of `J` with unit right and left eigenvectors `w`, `u` moves
//! under `J + E` by `u^H E w / (u^H w)` to first order (Wilkinson, *The Algebraic Eigenvalue
//! Problem*, 1965, 2.9), at most `|E|_2 / |u^H w| <= |E|_F / |u^H w|`: [`multiplier_bounds`]
//! reports that bound per multiplier. A multiplier that is not simple to `|u^H w| >= 1e-8` (a
//! double eigenvalue, a Jordan block) gets none: its error is of order `|E|^(1/k)` and no
//! first-order bound holds.
//!
//! Not in the bound: the fixed point's own error (Newton's residual, about `1e-12`, moves `J`
//! by the map's second derivative times that), and the model itself.

use nalgebra::{Complex, DMatrix};
use serde::Serialize;

use crate::model::Model;
use crate::sim::SimConfig;

use super::error::MapError;
use super::finite_difference::{DEFAULT_STEP, finite_difference_map_with_step};
use super::fixed_point::{FixedPoint, extrapolate};
use super::multipliers::{Multiplier, eigenvalues, eigenvectors};
use super::result::{JacobianMethod, StepCheck};
use super::section::Section;

/// The reduced Jacobian `D P_r` at a section point with the estimate of its error.
#[derive(Clone, Debug, PartialEq)]
pub struct EstimatedJacobian {
    /// `D P_r`, `d x d` row by row.
    pub jacobian: Vec<Vec<f64>>,
    /// The estimate `E` of its error, entry by entry (module documentation).
    pub error: Vec<Vec<f64>>,
}

/// A multiplier of the reduced map with the bound on its error.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct MultiplierBound {
    /// The multiplier `lambda`.
    #[serde(flatten)]
    pub multiplier: Multiplier,
    /// The bound on `|lambda - lambda_exact|`, `|E|_F / |u^H w|` (module documentation);
    /// `None` (JSON `null`) where the multiplier is not simple.
    pub error: Option<f64>,
}

/// The reduced Jacobian `D P_r` at the section point `r` by `method`, and an estimate `E` of its
/// error (module documentation).
///
/// # Errors
/// [`MapError`]: a step of either evaluation could not be taken.
pub fn jacobian_error(
    model: &Model,
    cfg: &SimConfig,
    r: &[f64],
    method: JacobianMethod,
) -> Result<EstimatedJacobian, MapError> {
    let section = Section::of(model);
    let s = section.embed(r);
    // Differences give the full Jacobian.
    let reduce = |full: &[Vec<f64>]| section.reduced_jacobian(full, r);
    let (j, j_fine) = match method {
        JacobianMethod::Variational => {
            let finer = SimConfig {
                rtol: cfg.rtol.min(1e-12) / 10.0,
                atol: cfg.atol.min(1e-14) / 10.0,
                ..*cfg
            };
            // Along the section: `DP E`, whose free rows are the reduced Jacobian.
            (
                section.reduced(
                    &section
                        .map_with(cfg, r, method, StepCheck::Through)?
                        .jacobian,
                ),
                section.reduced(
                    &section
                        .map_with(&finer, r, method, StepCheck::Through)?
                        .jacobian,
                ),
            )
        }
        JacobianMethod::FiniteDifferences => {
            let at = |k: f64| finite_difference_map_with_step(model, cfg, &s, DEFAULT_STEP / k);
            (reduce(&at(1.0)?.jacobian), reduce(&at(2.0)?.jacobian))
        }
        JacobianMethod::ExtrapolatedDifferences => {
            let at = |k: f64| finite_difference_map_with_step(model, cfg, &s, DEFAULT_STEP / k);
            let (h, half, quarter) = (at(1.0)?, at(2.0)?, at(4.0)?);
            (
                reduce(&extrapolate(&h.jacobian, &half.jacobian)),
                reduce(&extrapolate(&half.jacobian, &quarter.jacobian)),
            )
        }
    };
    let e = j
        .iter()
        .zip(&j_fine)
        .map(|(a, b)| {
            a.iter()
                .zip(b)
                .map(|(x, y)| error_estimate(*x, *y, cfg.rtol))
                .collect()
        })
        .collect();
    Ok(EstimatedJacobian {
        jacobian: j,
        error: e,
    })
}

/// The error estimate of a value `x` from a second evaluation `y` an order more accurate (module
/// documentation): `2 |x - y| + 10 min(rtol, 1e-12) |x|`.
#[must_use]
pub(crate) fn error_estimate(x: f64, y: f64, rtol: f64) -> f64 {
    2.0 * (x - y).abs() + 10.0 * rtol.min(1e-12) * x.abs()
}

/// The eigenvalues of `jac` by decreasing modulus (as [`eigenvalues`] orders them), each with
/// the first-order bound `|err|_F / |u^H w|` on its change under an error of the size of `err`
/// (module documentation).
#[must_use]
pub fn multiplier_bounds(jac: &[Vec<f64>], err: &[Vec<f64>]) -> Vec<MultiplierBound> {
    let d = jac.len();
    let m = DMatrix::from_fn(d, d, |i, j| jac[i][j]);
    let e_norm = err.iter().flatten().fold(0.0_f64, |acc, x| acc.hypot(*x));
    eigenvalues(jac)
        .into_iter()
        .map(|l| MultiplierBound {
            multiplier: l,
            error: eigenvectors(&m, Complex::new(l.re, l.im))
                .map(|v| e_norm / v.overlap.norm())
                .filter(|b| b.is_finite()),
        })
        .collect()
}

/// The multipliers of the fixed point `fp` (of `model` under `cfg`, as
/// [`super::fixed_point`] found it), each with its error bound: the fixed point's reduced
/// Jacobian evaluated again, and once more an order more accurately (module documentation).
///
/// # Errors
/// [`MapError`]: a step at the fixed point could not be taken.
pub fn multiplier_errors(
    model: &Model,
    cfg: &SimConfig,
    fp: &FixedPoint,
) -> Result<Vec<MultiplierBound>, MapError> {
    let r = Section::of(model).reduce(&fp.state_plus);
    let estimated = jacobian_error(model, cfg, &r, fp.jacobian_method)?;
    Ok(multiplier_bounds(&estimated.jacobian, &estimated.error))
}
