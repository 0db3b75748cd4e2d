//! The Poincare map on the post-impact section with its Jacobian: the stance phase with the
//! variational equations appended ([`Variational`]), the saltation correction at the strike,
//! and the Jacobians of the impact and of the relabelling.

use crate::jacobian::StanceJacobian;
use crate::model::{ImpactRegime, KernelId, Model};
use crate::sim::SimConfig;
use crate::vector::{MAX_LEN, Vector};

use super::error::MapError;
use super::finite_difference::{finite_difference_map, walked};
use super::impact_jacobian::{
    coulomb_impact_jacobian, coulomb_impact_mu0_rate, frictionless_impact_jacobian,
};
use super::parameter::ParameterRates;
use super::result::{JacobianMethod, MapResult, StepCheck};
use super::variational::{Columns, PhaseError, StanceEnd, field, stance};

/// Evaluates `$body` with `$na` set to the size of the state with `$cols` variational columns
/// appended (`2n` numbers each: the seeds' and the parameter's, `variational.rs`), for the
/// sizes of the models with Jacobian kernels (`n` from 3 to 5); `$other` for any other `n`.
/// The columns are rounded up to 2, 4, `2n` or `2n + 1`: four array sizes per `n` (each a copy
/// of the integrator) serve the reduced Jacobian of every section (`2n x d` for `d` up to 4;
/// `2n x 2` for the paper's walkers), the parameter's column alone, and the full Jacobian with
/// or without it. The unused columns stay zero and out of the error test.
macro_rules! with_columns {
    ($n:expr, $cols:expr, $na:ident => $body:expr, _ => $other:expr) => {{
        let (n, cols): (usize, usize) = ($n, $cols);
        let padded = match cols {
            0..=2 => 2,
            3..=4 => 4,
            c if c <= 2 * n => 2 * n,
            c if c == 2 * n + 1 => c,
            _ => 0,
        };
        match (n, padded) {
            (3, 2) => {
                const $na: usize = 6 * 3;
                $body
            }
            (3, 4) => {
                const $na: usize = 6 * 5;
                $body
            }
            (3, 6) => {
                const $na: usize = 6 * 7;
                $body
            }
            (3, 7) => {
                const $na: usize = 6 * 8;
                $body
            }
            (4, 2) => {
                const $na: usize = 8 * 3;
                $body
            }
            (4, 4) => {
                const $na: usize = 8 * 5;
                $body
            }
            (4, 8) => {
                const $na: usize = 8 * 9;
                $body
            }
            (4, 9) => {
                const $na: usize = 8 * 10;
                $body
            }
            (5, 2) => {
                const $na: usize = 10 * 3;
                $body
            }
            (5, 4) => {
                const $na: usize = 10 * 5;
                $body
            }
            (5, 10) => {
                const $na: usize = 10 * 11;
                $body
            }
            (5, 11) => {
                const $na: usize = 10 * 12;
                $body
            }
            _ => $other,
        }
    }};
}

/// The strike guard's gradient `d g / d [q, qd]` at the coordinates `q` (the model file's
/// guard, or the striking point's distance from the floor, differentiated symbolically and
/// evaluated).
fn guard_gradient(model: &Model, q: &[f64]) -> Vector {
    let spec = model.spec();
    let file = &spec.model;
    let n = model.n();
    let names: Vec<String> = spec.coordinates().map(str::to_owned).collect();
    let params = model.params();
    let value = |name: &str| {
        params.get(name).or_else(|| {
            let i = names.iter().position(|c| c == name)?;
            q.get(i).copied()
        })
    };
    let d = |e: &walker_scene::model::ModelExpr, c: &str| {
        e.expr.derivative(c).eval(&value).unwrap_or(f64::NAN)
    };
    let mut g = Vector::zeros(2 * n);
    let (sphi, cphi) = model.phi().sin_cos();
    for (j, c) in names.iter().enumerate() {
        g[j] = match &file.strike.guard {
            Some(e) => d(e, c),
            None => {
                let p = &file.points[spec.strike_point];
                d(&p.at[1], c) * cphi + d(&p.at[0], c) * sphi
            }
        };
    }
    g
}

/// One step of the hybrid walker from the post-impact state `s` (time 0), with its Jacobian
/// (see the module documentation) by the default method: the variational equations wherever
/// the model's kernels differentiate every phase the step goes through, central differences
/// otherwise ([`poincare_map_with`]). Failures of the stance phase (no strike within
/// [`SimConfig::max_step_time`], one of the model's falls, a ground reaction that blows up,
/// integrator failures, non-finite values) are errors; the physical validity tests of
/// [`crate::sim`] (lift-off, double support) are not applied here.
///
/// # Errors
/// [`MapError`]: the step could not be taken.
pub fn poincare_map(model: &Model, cfg: &SimConfig, s: &[f64]) -> Result<MapResult, MapError> {
    poincare_map_with(model, cfg, s, JacobianMethod::Variational)
}

/// [`poincare_map`] with the Jacobian by `method`: [`JacobianMethod::Variational`] (the
/// default: variational equations, saltation at every event that switches a phase, the
/// impact's Jacobian in its regime; falls back to central differences where a phase has no
/// Jacobian kernel or the model has more than five coordinates) or
/// [`JacobianMethod::FiniteDifferences`] (central differences of one simulated step with the
/// step `1e-4`, `poincare::finite_difference`: the independent check).
///
/// The paper's compiled variants with the tanh law (their Jacobian kernels generated with
/// Table 1 fixed) integrate at the configuration's tolerances, as they always have; every
/// other model integrates at `rtol = min(rtol, 1e-12)`, `atol = min(atol, 1e-14)`, the
/// tolerances its map had by finite differences, so that its fixed points keep their accuracy.
///
/// # Errors
/// [`MapError`]: the step could not be taken.
pub fn poincare_map_with(
    model: &Model,
    cfg: &SimConfig,
    s: &[f64],
    method: JacobianMethod,
) -> Result<MapResult, MapError> {
    let m = 2 * model.n();
    let identity: Vec<Vec<f64>> = (0..m)
        .map(|i| (0..m).map(|j| f64::from(u8::from(i == j))).collect())
        .collect();
    poincare_map_along(model, cfg, s, &identity, method, StepCheck::Through)
}

/// [`poincare_map_with`] with the Jacobian along the columns of `seeds` (`2n` rows of `c`
/// numbers): [`MapResult::jacobian`] is `DP S` (`2n x c`), which the variational equations
/// carry as `c` columns instead of `Phi`'s `2n`. With the section's tangent `E`
/// ([`super::Section::map`]) that is all the reduced Jacobian `Pi DP E` needs, at a fraction
/// of the full Jacobian's cost (the paper's walkers: 2 columns instead of 8). Central
/// differences compute the full Jacobian and multiply (`DP S` summed over `k` in ascending
/// order, as [`super::Section::reduced_jacobian`] does). With [`StepCheck::Walk`] the map exists
/// only where the simulator's step does (the differences' always walk).
///
/// # Errors
/// [`MapError`]: the step could not be taken.
pub fn poincare_map_along(
    model: &Model,
    cfg: &SimConfig,
    s: &[f64],
    seeds: &[Vec<f64>],
    method: JacobianMethod,
    step_check: StepCheck,
) -> Result<MapResult, MapError> {
    let m = 2 * model.n();
    shape("the state", s.len(), m)?;
    shape("the seeds", seeds.len(), m)?;
    let cols = seeds.first().map_or(0, Vec::len);
    for row in seeds {
        shape("a seed row", row.len(), cols)?;
    }
    if !s
        .iter()
        .chain(seeds.iter().flatten())
        .all(|v| v.is_finite())
    {
        return Err(MapError::NonFiniteStart);
    }
    let differences = |cfg: &SimConfig| {
        finite_difference_map(model, cfg, s).map(|mut r| {
            if !is_identity(seeds) {
                r.jacobian = matmul(&r.jacobian, seeds);
            }
            r
        })
    };
    if method == JacobianMethod::FiniteDifferences {
        return differences(cfg);
    }
    let (jac, cfg) = match StanceJacobian::new(model) {
        Ok(jac) => (jac, *cfg),
        Err(_) => (StanceJacobian::any_law(model), tight(cfg)),
    };
    // The seeds' columns one after the other.
    let flat: Vec<f64> = (0..cols)
        .flat_map(|j| seeds.iter().map(move |row| row[j]))
        .collect();
    if step_check == StepCheck::Walk {
        walked(model, &cfg, s)?;
    }
    let columns = Columns {
        seeds: &flat,
        param: None,
    };
    let out = with_columns!(model.n(), cols, NA => variational_map::<NA>(model, &cfg, s, &columns, jac),
        _ => Err(PhaseError::NoKernel));
    match out {
        Ok((r, _)) => Ok(r),
        Err(PhaseError::Map(e)) => Err(e),
        Err(PhaseError::NoKernel) => differences(&cfg),
    }
}

/// [`MapError::Shape`] unless `got == expected`.
fn shape(what: &'static str, got: usize, expected: usize) -> Result<(), MapError> {
    if got == expected {
        Ok(())
    } else {
        Err(MapError::Shape {
            what,
            got,
            expected,
        })
    }
}

/// Whether `a` is the identity matrix.
fn is_identity(a: &[Vec<f64>]) -> bool {
    a.iter().enumerate().all(|(i, row)| {
        row.len() == a.len()
            && row
                .iter()
                .enumerate()
                .all(|(j, &v)| v == f64::from(u8::from(i == j)))
    })
}

/// The Poincare map's exact derivative in one run-time parameter `p` (`parameter.rs`), for a
/// start that moves with `p` at `d s / dp` (`start_rate`).
#[derive(Clone, Debug, PartialEq)]
pub struct ParameterColumn {
    /// `d state_plus / dp` (`2n` numbers, `[q, qd]`).
    pub d_state: Vec<f64>,
    /// `dT / dp`.
    pub d_period: f64,
    /// `d (dx) / dp`.
    pub d_dx: f64,
}

/// The map at `s` ([`poincare_map`], by the variational equations) with its exact derivative in
/// the parameter `name` for a start that moves with it at `start_rate` (`d s / dp`, `2n`
/// numbers: the section's given components' rates, [`super::Section::rate`], plus any direction
/// of a derivative along a curve): one variational integration with the column `psi = ds/dp`
/// beside `Phi`, driven by `d f / dp`, jumping where a ramp's end moves with `p`, through the
/// saltation of every event (with the slip guard's own rate in `mu0`), the strike's time
/// (`dT/dp = -g_y psi / g_y f`), the impact (its rate in `mu0` under Coulomb friction) and the
/// relabelling (`docs/poincare.md`, "Exact parameter columns").
///
/// `Ok(None)` where the column has no exact form here: `name` is not a parameter or enters the
/// mechanics, the model's kernels do not differentiate a phase the step goes through, or it
/// has more than five coordinates (the caller differences the map in `p`).
///
/// # Errors
/// [`MapError`]: the step could not be taken.
pub fn parameter_column(
    model: &Model,
    cfg: &SimConfig,
    s: &[f64],
    name: &str,
    start_rate: &[f64],
) -> Result<Option<(MapResult, ParameterColumn)>, MapError> {
    let m = 2 * model.n();
    shape("the state", s.len(), m)?;
    shape("the start's rate", start_rate.len(), m)?;
    if !s.iter().chain(start_rate).all(|v| v.is_finite()) {
        return Err(MapError::NonFiniteStart);
    }
    let Some(rates) = ParameterRates::of(model, name) else {
        return Ok(None);
    };
    let (jac, cfg) = match StanceJacobian::new(model) {
        Ok(jac) => (jac, *cfg),
        Err(_) => (StanceJacobian::any_law(model), tight(cfg)),
    };
    let columns = Columns {
        seeds: &[],
        param: Some((&rates, start_rate)),
    };
    let out = with_columns!(model.n(), 1, NA => variational_map::<NA>(model, &cfg, s, &columns, jac),
        _ => Err(PhaseError::NoKernel));
    match out {
        Ok((r, Some(c))) => Ok(Some((r, c))),
        Ok((_, None)) | Err(PhaseError::NoKernel) => Ok(None),
        Err(PhaseError::Map(e)) => Err(e),
    }
}

/// The tolerances of the maps of models other than the Table-1 variants (see
/// [`poincare_map_with`]).
pub(super) fn tight(cfg: &SimConfig) -> SimConfig {
    SimConfig {
        rtol: cfg.rtol.min(1e-12),
        atol: cfg.atol.min(1e-14),
        ..*cfg
    }
}

/// [`poincare_map_along`] by the variational equations, along the seeds' columns of `columns`,
/// with the parameter's column if it has one.
fn variational_map<const NA: usize>(
    model: &Model,
    cfg: &SimConfig,
    s: &[f64],
    columns: &Columns<'_>,
    jac: StanceJacobian<'_>,
) -> Result<(MapResult, Option<ParameterColumn>), PhaseError> {
    let n = model.n();
    let m = 2 * n;
    let cols = columns.seeds.len() / m;
    let param = columns.param;
    let StanceEnd {
        t: te,
        y: ye,
        contact,
    } = stance::<NA>(model, cfg, s, columns, jac)?;
    let pre = Vector::from_slice(&ye[..m]);
    // `Phi S` by rows (`m x cols`) from its columns.
    let mut phi: Vec<Vec<f64>> = (0..m)
        .map(|i| (0..cols).map(|j| ye[m + m * j + i]).collect())
        .collect();
    // Saltation: Phi+ = (I - f g_y^T / (g_y . f)) Phi for the guard g.
    let mut f = [0.0; MAX_LEN];
    field(model, te, &ye, contact, &mut f[..m]);
    let g = guard_gradient(model, &pre[..n]);
    let gf: f64 = (0..m).map(|k| g[k] * f[k]).sum();
    if gf.abs() < 1e-12 {
        return Err(MapError::GrazingHeelStrike { t: te }.into());
    }
    let g_row: Vec<f64> = (0..cols)
        .map(|j| (0..m).map(|k| g[k] * phi[k][j]).sum())
        .collect();
    for i in 0..m {
        for j in 0..cols {
            phi[i][j] -= f[i] * g_row[j] / gf;
        }
    }
    // The parameter's column: the strike moves by dT = -g_y psi / (g_y f), psi <- psi + f dT.
    let psi_at = m + m * cols;
    let strike = param.map(|_| {
        let psi = &ye[psi_at..psi_at + m];
        let d_period = -(0..m).map(|k| g[k] * psi[k]).sum::<f64>() / gf;
        let psi: Vec<f64> = (0..m).map(|i| psi[i] + f[i] * d_period).collect();
        (psi, d_period)
    });
    // Impact: positions unchanged, velocities from the impact.
    let imp = model
        .impact(&pre)
        .map_err(|_| MapError::NonFiniteImpact { t: te })?;
    let k = match imp.regime {
        ImpactRegime::Frictionless if model.kernels().has(KernelId::ImpactJacobian) => {
            let mut k = vec![0.0; n * m];
            model.kernels().eval(
                KernelId::ImpactJacobian,
                &crate::model::Args::state(&pre[..n], &pre[n..]),
                &mut k,
            );
            k
        }
        ImpactRegime::Frictionless => frictionless_impact_jacobian(model, &pre),
        regime => coulomb_impact_jacobian(model, &pre, regime)
            .ok_or(MapError::NonFiniteImpact { t: te })?,
    };
    let mut dimp = vec![vec![0.0; m]; m];
    for (i, row) in dimp.iter_mut().enumerate().take(n) {
        row[i] = 1.0;
    }
    for i in 0..n {
        dimp[n + i].copy_from_slice(&k[i * m..(i + 1) * m]);
    }
    // Relabelling to the new stance leg (the simulator's own, `Model::reset`), then measured
    // from the new foot: `x` and `z` are cyclic and reduced to zero.
    let post = model.reset(&pre, &imp);
    let (dres, x_row) = relabel_jacobian(model, &pre, &imp.qd);
    let mut product = matmul(&dres, &matmul(&dimp, &phi));
    let column = match (strike, param) {
        (Some((psi, d_period)), Some((rates, start_rate))) => {
            // Through the impact (with its own rate in mu0 under Coulomb friction) and the
            // relabelling; the step's length from the new foot's x.
            let mut psi_imp: Vec<f64> = dimp
                .iter()
                .map(|row| row.iter().zip(&psi).map(|(a, b)| a * b).sum())
                .collect();
            if !matches!(imp.regime, ImpactRegime::Frictionless) && rates.d_mu0 != 0.0 {
                let d = coulomb_impact_mu0_rate(model, &pre, imp.regime)
                    .ok_or(MapError::NonFiniteImpact { t: te })?;
                for i in 0..n {
                    psi_imp[n + i] += d[i] * rates.d_mu0;
                }
            }
            let x_rate: f64 = x_row.iter().zip(&psi_imp).map(|(a, b)| a * b).sum();
            let mut d_state: Vec<f64> = dres
                .iter()
                .map(|row| row.iter().zip(&psi_imp).map(|(a, b)| a * b).sum())
                .collect();
            if imp.regime == ImpactRegime::Stick {
                d_state[n] = 0.0;
                d_state[n + 1] = 0.0;
            }
            Some(ParameterColumn {
                d_state,
                d_period,
                d_dx: (x_rate - start_rate[0]) / model.phi().cos(),
            })
        }
        _ => None,
    };
    if imp.regime == ImpactRegime::Stick {
        // The new foot is at rest exactly (`Model::reset`): its velocity's rows are zero, not
        // the rounding of the regime's `v_t+ = v_n+ = 0`.
        product[n].fill(0.0);
        product[n + 1].fill(0.0);
    }
    let mut state_plus = Vector::concat(&post.q_plus, &post.qd_plus);
    (state_plus[0], state_plus[1]) = (0.0, 0.0);
    let dx = (post.q_plus[0] - s[0]) / model.phi().cos();
    let ok = state_plus
        .iter()
        .chain(product.iter().flatten())
        .chain(column.iter().flat_map(|c| c.d_state.iter()))
        .chain(column.iter().flat_map(|c| [&c.d_period, &c.d_dx]))
        .all(|v| v.is_finite());
    if !ok || !dx.is_finite() {
        return Err(MapError::NonFiniteImpact { t: te }.into());
    }
    let map = MapResult {
        state_plus,
        period: te,
        dx,
        jacobian: product,
        method: JacobianMethod::Variational,
        impact: imp.regime,
    };
    Ok((map, column))
}

/// `a b`, each entry summed over `k` in ascending order (as the fixed-size product it
/// replaced).
pub(super) fn matmul(a: &[Vec<f64>], b: &[Vec<f64>]) -> Vec<Vec<f64>> {
    let cols = b.first().map_or(0, Vec::len);
    a.iter()
        .map(|row| {
            (0..cols)
                .map(|j| {
                    let mut s = 0.0;
                    for (k, bk) in b.iter().enumerate() {
                        s += row[k] * bk[j];
                    }
                    s
                })
                .collect()
        })
        .collect()
}

/// The Jacobian of the relabelling `[q+, qd+] = R(q-, qd)` at the pre-impact coordinates and
/// the post-impact velocities of the old coordinates, with the rows of `x` and `z` zero (the
/// map measures from the new foot): the `relabel_jacobian` kernel where the model has it, else
/// central differences of `relabel`. Also the row of `x` itself (the new foot's position,
/// for the step length's rate).
fn relabel_jacobian(model: &Model, pre: &[f64], qd: &[f64]) -> (Vec<Vec<f64>>, Vec<f64>) {
    let n = model.n();
    let m = 2 * n;
    let mut out = vec![vec![0.0; m]; m];
    let kernels = model.kernels();
    let q = &pre[..n];
    if kernels.has(KernelId::RelabelJacobian) {
        let mut flat = vec![0.0; m * m];
        kernels.eval(
            KernelId::RelabelJacobian,
            &crate::model::Args::state(q, qd),
            &mut flat,
        );
        for i in 2..m {
            out[i].copy_from_slice(&flat[i * m..(i + 1) * m]);
        }
        return (out, flat[..m].to_vec());
    }
    let relabel = |s: &[f64]| {
        let mut o = vec![0.0; m];
        kernels.eval(
            KernelId::Relabel,
            &crate::model::Args::state(&s[..n], &s[n..]),
            &mut o,
        );
        o
    };
    let base: Vec<f64> = q.iter().chain(qd).copied().collect();
    let mut x_row = vec![0.0; m];
    for j in 0..m {
        let h = 6e-6 * base[j].abs().max(1.0);
        let (mut up, mut down) = (base.clone(), base.clone());
        up[j] += h;
        down[j] -= h;
        let (a, b) = (relabel(&up), relabel(&down));
        for i in 2..m {
            out[i][j] = (a[i] - b[i]) / (up[j] - down[j]);
        }
        x_row[j] = (a[0] - b[0]) / (up[j] - down[j]);
    }
    (out, x_row)
}
