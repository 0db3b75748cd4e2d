//! The sensitivities of a fixed point to a parameter with an exact column
//! ([`crate::poincare::parameter_column`]: the friction law's parameters, the desired
//! trajectories', the gains): the first-order quantities from variational integrations, the
//! multipliers' derivatives from one Richardson difference along the branch.
//!
//! - `dP_r/dp` and `dT/dp` at fixed `r*`: the column with the start moving as the section's
//!   given components do (`Section::rate`);
//! - `dr*/dp = (I - J)^{-1} dP_r/dp`;
//! - the totals `dT/dp`, `d(dx)/dp` along the branch: the column again, the start moving along
//!   the branch (`Section::rate + E dr*/dp`), so that no difference in `r` is needed;
//! - `dJ/dp` along the branch, for the multipliers: central differences of `J(r* + s dr*/dp,
//!   p + s)` at `s = +-h, +-h/2`, extrapolated (`difference.rs`); the second derivatives of the
//!   map that it stands for have no variational form here.
//!
//! Each exact value's error is estimated as the Jacobian's is (`poincare/accuracy.rs`): the
//! column again at a tenth of the tolerances, `2 |c - c'| + 10 rtol |c|`.

use nalgebra::{DMatrix, DVector};

use crate::continuation::WalkerProblem;
use crate::model::Model;
use crate::poincare::{ParameterColumn, Section, error_estimate, parameter_column};
use crate::sim::SimConfig;

use super::difference::{richardson, shifts, step};
use super::error::SensitivityError;
use super::result::{Estimate, Sensitivity};

/// What the fixed point gives every parameter's sensitivities: the model, the maps' tolerances,
/// the section, `r*`, `J = D P_r` and its inverse `(I - J)^{-1}`, `T` and `dx`.
pub(super) struct AtFixedPoint<'a> {
    pub(super) model: &'a Model,
    pub(super) cfg: SimConfig,
    pub(super) section: Section<'a>,
    pub(super) r: Vec<f64>,
    pub(super) jac: DMatrix<f64>,
    pub(super) inv: DMatrix<f64>,
    pub(super) period: f64,
    pub(super) dx: f64,
}

/// An exact column with its error estimate: `(d state_plus, dT, d(dx))` as values and errors.
struct Estimated {
    value: ParameterColumn,
    error: ParameterColumn,
}

/// The column of `name` at `at`'s fixed point for the start moving at `start_rate`, evaluated
/// at the tolerances and at a tenth of them; `None` where it has no exact form.
fn estimated(
    at: &AtFixedPoint<'_>,
    name: &str,
    start_rate: &[f64],
) -> Result<Option<Estimated>, SensitivityError> {
    let s = at.section.embed(&at.r);
    let fine = SimConfig {
        rtol: at.cfg.rtol / 10.0,
        atol: at.cfg.atol / 10.0,
        ..at.cfg
    };
    let column = |cfg: &SimConfig| {
        parameter_column(at.model, cfg, &s, name, start_rate).map_err(|source| {
            SensitivityError::Map {
                at: format!("the fixed point (the column of {name})"),
                source,
            }
        })
    };
    let (Some((_, a)), Some((_, b))) = (column(&at.cfg)?, column(&fine)?) else {
        return Ok(None);
    };
    let err = |x: f64, y: f64| error_estimate(x, y, at.cfg.rtol);
    let error = ParameterColumn {
        d_state: a
            .d_state
            .iter()
            .zip(&b.d_state)
            .map(|(x, y)| err(*x, *y))
            .collect(),
        d_period: err(a.d_period, b.d_period),
        d_dx: err(a.d_dx, b.d_dx),
    };
    Ok(Some(Estimated { value: a, error }))
}

/// The sensitivities to `name` (of `problem`, which shifts it) by exact columns, or `None`
/// where the parameter has none (module documentation).
///
/// # Errors
/// [`SensitivityError`]: a map fails, or the model at a shifted value cannot be built.
pub(super) fn exact_sensitivity(
    at: &AtFixedPoint<'_>,
    problem: &WalkerProblem,
    name: &str,
    p0: f64,
) -> Result<Option<Sensitivity>, SensitivityError> {
    let d = at.section.dim();
    let rate = at.section.rate(&at.r, name);
    let Some(fixed_r) = estimated(at, name, &rate)? else {
        return Ok(None);
    };
    let c = DVector::from_vec(at.section.reduce(&fixed_r.value.d_state));
    let c_err = DVector::from_vec(at.section.reduce(&fixed_r.error.d_state));
    let mut v = &at.inv * &c;
    let v_err = at.inv.abs() * &c_err;
    for i in 0..d {
        // A coordinate the map holds (a foot at rest after a sticking impact) stays put.
        if c[i] == 0.0 && (0..d).all(|j| at.jac[(i, j)] == 0.0) {
            v[i] = 0.0;
        }
    }
    // Along the branch: the start moves at rate + E v.
    let tangent = at.section.tangent(&at.r);
    let along: Vec<f64> = (0..rate.len())
        .map(|i| rate[i] + (0..d).map(|k| tangent[i][k] * v[k]).sum::<f64>())
        .collect();
    let Some(total) = estimated(at, name, &along)? else {
        return Ok(None);
    };
    // Along the same direction, J's derivative by differences.
    let h = step(p0);
    let mut vals: [Vec<f64>; 4] = Default::default();
    for (out, s) in vals.iter_mut().zip(shifts(h)) {
        let model = problem
            .model_at(p0 + s)
            .map_err(|e| SensitivityError::Model {
                name: name.to_owned(),
                value: p0 + s,
                message: e.to_string(),
            })?;
        let r: Vec<f64> = at.r.iter().zip(v.iter()).map(|(r, v)| r + s * v).collect();
        *out = super::compute::sample(&model, &at.cfg, &r, &format!("{name} = {}", p0 + s))?;
    }
    let dj = richardson(&vals, h);
    let estimate = |value: f64, error: f64| Estimate { value, error };
    let dt = estimate(total.value.d_period, total.error.d_period);
    let ddx = estimate(total.value.d_dx, total.error.d_dx);
    let speed = at.dx / at.period;
    let d_speed = estimate(
        (ddx.value - speed * dt.value) / at.period,
        (ddx.error + speed.abs() * dt.error) / at.period,
    );
    let dj_value = DMatrix::from_fn(d, d, |i, j| dj[d + 2 + i * d + j].0);
    let dj_err = DMatrix::from_fn(d, d, |i, j| dj[d + 2 + i * d + j].1).norm();
    let names = at.section.names();
    Ok(Some(Sensitivity {
        parameter: name.to_owned(),
        value: p0,
        step: h,
        d_state: names
            .iter()
            .zip(v.iter().zip(v_err.iter()))
            .map(|(n, (&value, &error))| (n.clone(), estimate(value, error)))
            .collect(),
        d_period: dt,
        d_speed,
        d_dx: ddx,
        d_multipliers: super::compute::multiplier_derivatives(&at.jac, &dj_value, dj_err),
        map_d_state: names
            .iter()
            .zip(c.iter().zip(c_err.iter()))
            .map(|(n, (&value, &error))| (n.clone(), estimate(value, error)))
            .collect(),
        map_d_period: estimate(fixed_r.value.d_period, fixed_r.error.d_period),
    }))
}
