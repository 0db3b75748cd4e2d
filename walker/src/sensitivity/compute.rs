//! The sensitivities of a fixed point: the map's parameter columns by differences, the
//! implicit function theorem, and the multipliers' derivatives.

use nalgebra::{Complex, DMatrix, DVector};

use crate::continuation::{ProblemError, WalkerProblem};
use crate::model::Model;
use crate::poincare::{Eigenvectors, FixedPoint, Section, eigenvalues, eigenvectors};
use crate::setup::Setup;
use crate::sim::SimConfig;

use super::difference::{richardson, shifts, step};
use super::error::SensitivityError;
use super::exact::{AtFixedPoint, exact_sensitivity};
use super::result::{Estimate, MultiplierSensitivity, Sensitivity};

/// Checks that each name is a run-time parameter of the setup's walker (one the
/// friction law uses and that is not a start parameter).
///
/// # Errors
/// [`SensitivityError::NotAParameter`] for the first name that is not, with the valid names.
pub fn check_parameters(
    setup: &Setup,
    cfg: &SimConfig,
    names: &[&str],
) -> Result<(), SensitivityError> {
    for name in names {
        problem(setup, cfg, name)?;
    }
    Ok(())
}

/// The walker with `name` free (which validates the name).
fn problem(setup: &Setup, cfg: &SimConfig, name: &str) -> Result<WalkerProblem, SensitivityError> {
    WalkerProblem::new(setup.clone(), name, *cfg).map_err(|e| match e {
        ProblemError::NotAParameter { name, model, known } => {
            SensitivityError::NotAParameter { name, model, known }
        }
        other => SensitivityError::Model {
            name: name.to_owned(),
            value: setup.params.get(name).unwrap_or(f64::NAN),
            message: other.to_string(),
        },
    })
}

/// The tolerances of the sensitivity maps: `rtol = min(rtol, 1e-12)`, `atol = min(atol,
/// 1e-14)` (those of the maps of models other than the Table-1 variants).
fn tight(cfg: &SimConfig) -> SimConfig {
    SimConfig {
        rtol: cfg.rtol.min(1e-12),
        atol: cfg.atol.min(1e-14),
        ..*cfg
    }
}

/// One map evaluation flattened: the image `P_r(r)` (`d`), `T`, `dx`, then the reduced
/// Jacobian row by row (`d * d`).
pub(super) fn sample(
    model: &Model,
    cfg: &SimConfig,
    r: &[f64],
    at: &str,
) -> Result<Vec<f64>, SensitivityError> {
    let section = Section::of(model);
    let m = section
        .map(cfg, r)
        .map_err(|source| SensitivityError::Map {
            at: at.to_owned(),
            source,
        })?;
    let mut out = section.reduce(&m.state_plus);
    out.push(m.period);
    out.push(m.dx);
    for row in section.reduced(&m.jacobian) {
        out.extend(row);
    }
    Ok(out)
}

/// The sensitivities of the fixed point `fp` of `setup`'s walker (found with `cfg`) to each
/// parameter in `names` (module documentation: Richardson-extrapolated central differences in
/// the parameter, the implicit function theorem, left and right eigenvectors).
///
/// # Errors
/// [`SensitivityError`]: a name is not a run-time parameter, a shifted model cannot be built
/// (a parameter within `h` of the end of its range), a map fails, or the fixed point is not
/// isolated.
pub fn sensitivities(
    setup: &Setup,
    cfg: &SimConfig,
    fp: &FixedPoint,
    names: &[&str],
) -> Result<Vec<Sensitivity>, SensitivityError> {
    let problems = names
        .iter()
        .map(|n| problem(setup, cfg, n))
        .collect::<Result<Vec<_>, _>>()?;
    let model = setup.model().map_err(|e| SensitivityError::Model {
        name: names.first().map_or_else(String::new, |n| (*n).to_owned()),
        value: f64::NAN,
        message: e.to_string(),
    })?;
    let tcfg = tight(cfg);
    let section = Section::of(&model);
    let d = section.dim();
    let r0 = section.reduce(&fp.state_plus);
    let base = sample(&model, &tcfg, &r0, "the fixed point")?;
    let jac = DMatrix::from_fn(d, d, |i, j| base[d + 2 + i * d + j]);
    let a = DMatrix::identity(d, d) - &jac;
    let singular = || SensitivityError::NotIsolated {
        name: names.join(", "),
    };
    if fp.structural_unit_multiplier {
        return Err(singular());
    }
    let inv = a.clone().try_inverse().ok_or_else(singular)?;
    // The parameters with exact columns (`exact.rs`); the others by differences below.
    let at = AtFixedPoint {
        model: &model,
        cfg: tcfg,
        section: section.clone(),
        r: r0.clone(),
        jac: jac.clone(),
        inv: inv.clone(),
        period: base[d],
        dx: base[d + 1],
    };
    let mut exact = Vec::with_capacity(names.len());
    for (pr, name) in problems.iter().zip(names) {
        let p0 = setup.params.get(name).unwrap_or(f64::NAN);
        exact.push(exact_sensitivity(&at, pr, name, p0)?);
    }
    let rest: Vec<usize> = (0..names.len()).filter(|&i| exact[i].is_none()).collect();
    let (problems, names): (Vec<&WalkerProblem>, Vec<&str>) =
        rest.iter().map(|&i| (&problems[i], names[i])).unzip();
    // Parameter columns at fixed r*.
    let mut columns = Vec::new();
    for (pr, name) in problems.iter().zip(&names) {
        let p0 = setup.params.get(name).unwrap_or(f64::NAN);
        let h = step(p0);
        let mut vals: [Vec<f64>; 4] = Default::default();
        for (v, s) in vals.iter_mut().zip(shifts(h)) {
            let m = pr.model_at(p0 + s).map_err(|e| SensitivityError::Model {
                name: (*name).to_owned(),
                value: p0 + s,
                message: e.to_string(),
            })?;
            *v = sample(&m, &tcfg, &r0, &format!("{name} = {}", p0 + s))?;
        }
        columns.push((p0, h, richardson(&vals, h)));
    }
    // dr*/dp = (I - J)^{-1} dP_r/dp, with the error propagated by |(I - J)^{-1}|.
    let tangents: Vec<(Vec<f64>, Vec<f64>)> = columns
        .iter()
        .map(|(_, _, c)| {
            let col = DVector::from_fn(d, |i, _| c[i].0);
            let err = DVector::from_fn(d, |i, _| c[i].1);
            let mut v = &inv * col;
            let e = inv.abs() * err;
            for i in 0..d {
                // A coordinate the map holds (a foot at rest after a sticking impact: its row
                // of J and its column entry exactly zero) stays exactly where it is.
                if c[i].0 == 0.0 && (0..d).all(|j| jac[(i, j)] == 0.0) {
                    v[i] = 0.0;
                }
            }
            (v.iter().copied().collect(), e.iter().copied().collect())
        })
        .collect();
    // Derivatives of T, dx and J in the section coordinates the gait moves in.
    let k_len = 2 + d * d;
    let mut in_r: Vec<Option<Vec<(f64, f64)>>> = vec![None; d];
    for (k, slot) in in_r.iter_mut().enumerate() {
        if tangents.iter().all(|(v, _)| v[k] == 0.0) || names.is_empty() {
            continue;
        }
        let h = step(r0[k]);
        let mut vals: [Vec<f64>; 4] = Default::default();
        for (v, s) in vals.iter_mut().zip(shifts(h)) {
            let mut r = r0.clone();
            r[k] += s;
            *v = sample(
                &model,
                &tcfg,
                &r,
                &format!("{} = {}", section.names()[k], r[k]),
            )?;
        }
        *slot = Some(richardson(&vals, h)[d..].to_vec());
    }
    let names_r = section.names();
    let mut differenced = Vec::new();
    for ((name, (p0, h, col)), (v, ev)) in names.iter().zip(&columns).zip(&tangents) {
        // Totals of (T, dx, J entries) along the branch: d/dp + sum_k d/dr_k v_k.
        let total: Vec<Estimate> = (0..k_len)
            .map(|q| {
                let (mut value, mut error) = col[d + q];
                for (k, dk) in in_r.iter().enumerate() {
                    if let Some(dk) = dk {
                        value += dk[q].0 * v[k];
                        error += dk[q].0.abs() * ev[k] + dk[q].1 * v[k].abs();
                    }
                }
                Estimate { value, error }
            })
            .collect();
        let (t, dx) = (base[d], base[d + 1]);
        let (dt, ddx) = (total[0], total[1]);
        let speed = dx / t;
        let d_speed = Estimate {
            value: (ddx.value - speed * dt.value) / t,
            error: (ddx.error + speed.abs() * dt.error) / t,
        };
        let dj = DMatrix::from_fn(d, d, |i, j| total[2 + i * d + j].value);
        let dj_err = DMatrix::from_fn(d, d, |i, j| total[2 + i * d + j].error).norm();
        let d_multipliers = multiplier_derivatives(&jac, &dj, dj_err);
        differenced.push(Sensitivity {
            parameter: (*name).to_owned(),
            value: *p0,
            step: *h,
            d_state: names_r
                .iter()
                .zip(v.iter().zip(ev))
                .map(|(n, (&value, &error))| (n.clone(), Estimate { value, error }))
                .collect(),
            d_period: dt,
            d_speed,
            d_dx: ddx,
            d_multipliers,
            map_d_state: names_r
                .iter()
                .zip(&col[..d])
                .map(|(n, &(value, error))| (n.clone(), Estimate { value, error }))
                .collect(),
            map_d_period: Estimate {
                value: col[d].0,
                error: col[d].1,
            },
        });
    }
    // In the order asked.
    let mut differenced = differenced.into_iter();
    Ok(exact
        .into_iter()
        .filter_map(|e| e.or_else(|| differenced.next()))
        .collect())
}

/// `d lambda / dp` for each eigenvalue of `jac` (in [`eigenvalues`]' order) from `dJ/dp` with
/// its error estimate (Frobenius norm): [`multiplier_derivative`].
pub(super) fn multiplier_derivatives(
    jac: &DMatrix<f64>,
    dj: &DMatrix<f64>,
    dj_err: f64,
) -> Vec<Option<MultiplierSensitivity>> {
    let d = jac.nrows();
    eigenvalues(
        &(0..d)
            .map(|i| jac.row(i).iter().copied().collect())
            .collect::<Vec<_>>(),
    )
    .iter()
    .map(|l| multiplier_derivative(jac, dj, dj_err, Complex::new(l.re, l.im)))
    .collect()
}

/// `d lambda / dp = u^H (dJ/dp) w / (u^H w)` for the simple eigenvalue `lambda` of `jac`, with
/// the error `|E|_F / |u^H w|` (`E` the estimate of `dJ/dp`'s error, unit `u`, `w`); `None`
/// where `lambda` is not simple (`u^H w` below `1e-8`) or not finite.
fn multiplier_derivative(
    jac: &DMatrix<f64>,
    dj: &DMatrix<f64>,
    dj_err: f64,
    lambda: Complex<f64>,
) -> Option<MultiplierSensitivity> {
    let Eigenvectors {
        right: w,
        left: u,
        overlap: uw,
    } = eigenvectors(jac, lambda)?;
    let djc = dj.map(|x| Complex::new(x, 0.0));
    let dl = u.dotc(&(djc * &w)) / uw;
    let error = dj_err / uw.norm();
    (dl.re.is_finite() && dl.im.is_finite() && error.is_finite()).then_some(MultiplierSensitivity {
        re: dl.re,
        im: dl.im,
        error,
    })
}
