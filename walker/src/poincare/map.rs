//! The Poincare map on the post-impact section with its Jacobian: the stance phase with the
//! variational equations appended ([`Variational`]), the saltation correction at the strike,
//! and the Jacobians of the impact and of the relabelling.

use crate::jacobian::StanceJacobian;
use crate::model::{Contact, ImpactRegime, KernelId, Model};
use crate::ode::{
    Direction, Event, GaveUp, Integrator, NoObserver, OdeSystem, Outcome, Tolerances,
};
use crate::sim::SimConfig;
use crate::vector::{MAX_LEN, Vector};

use super::error::MapError;
use super::finite_difference::finite_difference_map;
use super::impact_jacobian::coulomb_impact_jacobian;
use super::result::{JacobianMethod, MapResult};

/// Evaluates `$body` with `$na` set to the size `2n + (2n)^2` of the state with the
/// variational equations, for the sizes of the models with Jacobian kernels (`n` from 3 to 5);
/// `$other` for any other `n`.
macro_rules! with_variational_size {
    ($n:expr, $na:ident => $body:expr, _ => $other:expr) => {
        match $n {
            3 => {
                const $na: usize = 6 + 36;
                $body
            }
            4 => {
                const $na: usize = 8 + 64;
                $body
            }
            5 => {
                const $na: usize = 10 + 100;
                $body
            }
            _ => $other,
        }
    };
}

/// The stance phase with the variational equations appended: `[s, Phi]`, `s = [q, qd]` (`2n`
/// numbers) and the `2n x 2n` sensitivity `Phi` row-major.
struct Variational<'a> {
    model: &'a Model,
    jac: StanceJacobian<'a>,
}

impl Variational<'_> {
    /// `[qd, qdd]` at `(t, y)`.
    fn mech_rhs(&self, t: f64, y: &[f64], out: &mut [f64]) {
        let n = self.model.n();
        let mut a = [0.0; Model::STANCE_LEN];
        self.model.stance(t, y, Contact::Smooth, &mut a);
        out[..n].copy_from_slice(&y[n..2 * n]);
        out[n..2 * n].copy_from_slice(&a[..n]);
    }
}

impl<const NA: usize> OdeSystem<NA> for Variational<'_> {
    fn rhs(&mut self, t: f64, y: &[f64; NA], dy: &mut [f64; NA]) {
        let n = self.model.n();
        let m = 2 * n;
        self.mech_rhs(t, y, &mut dy[..m]);
        let mut a = [0.0; MAX_LEN * MAX_LEN];
        self.jac
            .accel(t, y, &mut a[..(n + self.model.inputs()) * m]);
        for j in 0..m {
            for i in 0..n {
                dy[m + m * i + j] = y[m + m * (i + n) + j];
                let mut s = 0.0;
                for k in 0..m {
                    s += a[i * m + k] * y[m + m * k + j];
                }
                dy[m + m * (i + n) + j] = s;
            }
        }
    }

    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        self.model.next_breakpoint(t)
    }
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
/// (see the module documentation). Failures of the stance phase (no strike within
/// [`SimConfig::max_step_time`], integrator failures, non-finite values) are errors; the
/// physical validity tests of [`crate::sim`] (lift-off, double support) are not applied here.
/// Models without Jacobian kernels (exact Coulomb friction in stance, parameters at run time,
/// models without closed forms) take one step of the simulator instead and their Jacobian by
/// central differences (`poincare::finite_difference`).
///
/// # Errors
/// [`MapError`]: the step could not be taken.
pub fn poincare_map(model: &Model, cfg: &SimConfig, s: &[f64]) -> Result<MapResult, MapError> {
    if s.len() != 2 * model.n() || !s.iter().all(|v| v.is_finite()) {
        return Err(MapError::NonFiniteStart);
    }
    let Ok(jac) = StanceJacobian::new(model) else {
        return finite_difference_map(model, cfg, s);
    };
    with_variational_size!(model.n(), NA => variational_map::<NA>(model, cfg, s, jac),
        _ => finite_difference_map(model, cfg, s))
}

/// [`poincare_map`] by the variational equations.
fn variational_map<const NA: usize>(
    model: &Model,
    cfg: &SimConfig,
    s: &[f64],
    jac: StanceJacobian<'_>,
) -> Result<MapResult, MapError> {
    let n = model.n();
    let m = 2 * n;
    let mut y = [0.0; NA];
    y[..m].copy_from_slice(s);
    for i in 0..m {
        y[m + (m + 1) * i] = 1.0;
    }
    let mut guard_values = [0.0; 1 + crate::sim::MAX_FALLS];
    let k = model.event_count().min(guard_values.len());
    let mut events = [Event::terminal(
        Direction::Falling,
        move |_, y: &[f64; NA]| {
            model.events(&y[..n], &mut guard_values[..k]);
            guard_values[0]
        },
    )];
    let mut sys = Variational { model, jac };
    let mut integ = Integrator::<NA>::new(cfg.method, Tolerances::new(cfg.rtol, cfg.atol));
    let mut t = 0.0;
    // One budget of attempted steps for the whole stance phase, as in the simulation
    // (`sim/step.rs`): each call after a breakpoint gets what the earlier ones left, and every
    // call spends at least one attempt, so the loop ends with `TooManySteps` at the latest.
    let budget = integ.config().max_steps;
    let (te, ye) = loop {
        let spent = integ.stats().accepted_steps + integ.stats().rejected_steps;
        integ.config_mut().max_steps =
            budget.saturating_sub(usize::try_from(spent).unwrap_or(usize::MAX));
        match integ.integrate(
            &mut sys,
            t,
            &y,
            cfg.max_step_time,
            &mut events,
            &mut NoObserver,
        ) {
            Outcome::Breakpoint { t: tb, y: yb } => {
                t = tb;
                y = yb;
            }
            // A zero of the guard with the striking point behind the stance foot is no strike.
            Outcome::Event { t: te, y: ye, .. } if !model.strike_ahead(&ye[..n]) => {
                t = te;
                y = ye;
            }
            Outcome::Event { t, y, .. } => break (t, y),
            Outcome::Reached { t, .. } => return Err(MapError::NoHeelStrike { t }),
            Outcome::NonFinite { t, .. } => return Err(MapError::NonFinite { t }),
            Outcome::StepSizeTooSmall { t, h, .. } => {
                let cause = GaveUp::StepSizeTooSmall { h };
                return Err(MapError::Integrator { t, cause });
            }
            Outcome::MaxSteps { t, .. } => {
                let cause = GaveUp::TooManySteps;
                return Err(MapError::Integrator { t, cause });
            }
            Outcome::InvalidInput { t, reason, .. } => {
                let cause = GaveUp::InvalidInput(reason);
                return Err(MapError::Integrator { t, cause });
            }
        }
    };
    let pre = Vector::from_slice(&ye[..m]);
    let mut phi: Vec<Vec<f64>> = (0..m)
        .map(|i| ye[m + m * i..m + m * (i + 1)].to_vec())
        .collect();
    // Saltation: Phi+ = (I - f g_y^T / (g_y . f)) Phi for the guard g.
    let mut f = [0.0; MAX_LEN];
    sys.mech_rhs(te, &ye, &mut f[..m]);
    let g = guard_gradient(model, &pre[..n]);
    let gf: f64 = (0..m).map(|k| g[k] * f[k]).sum();
    if gf.abs() < 1e-12 {
        return Err(MapError::GrazingHeelStrike { t: te });
    }
    let g_row: Vec<f64> = (0..m)
        .map(|j| (0..m).map(|k| g[k] * phi[k][j]).sum())
        .collect();
    for i in 0..m {
        for j in 0..m {
            phi[i][j] -= f[i] * g_row[j] / gf;
        }
    }
    // Impact: positions unchanged, velocities from the impact.
    let imp = model
        .impact(&pre)
        .map_err(|_| MapError::NonFiniteImpact { t: te })?;
    let mut k = vec![0.0; n * m];
    match imp.regime {
        ImpactRegime::Frictionless => sys.jac.impact(&pre, &mut k),
        regime => {
            k = coulomb_impact_jacobian(model, &pre, regime)
                .ok_or(MapError::NonFiniteImpact { t: te })?;
        }
    }
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
    let dres = relabel_jacobian(model, &pre, &imp.qd);
    let product = matmul(&dres, &matmul(&dimp, &phi));
    let mut state_plus = Vector::concat(&post.q_plus, &post.qd_plus);
    (state_plus[0], state_plus[1]) = (0.0, 0.0);
    let dx = (post.q_plus[0] - s[0]) / model.phi().cos();
    let ok = state_plus
        .iter()
        .chain(product.iter().flatten())
        .all(|v| v.is_finite());
    if !ok || !dx.is_finite() {
        return Err(MapError::NonFiniteImpact { t: te });
    }
    Ok(MapResult {
        state_plus,
        period: te,
        dx,
        jacobian: product,
        method: JacobianMethod::Variational,
        impact: imp.regime,
    })
}

/// `a b`, each entry summed over `k` in ascending order (as the fixed-size product it
/// replaced).
fn matmul(a: &[Vec<f64>], b: &[Vec<f64>]) -> Vec<Vec<f64>> {
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
/// central differences of `relabel`.
fn relabel_jacobian(model: &Model, pre: &[f64], qd: &[f64]) -> Vec<Vec<f64>> {
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
        return out;
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
    for j in 0..m {
        let h = 6e-6 * base[j].abs().max(1.0);
        let (mut up, mut down) = (base.clone(), base.clone());
        up[j] += h;
        down[j] -= h;
        let (a, b) = (relabel(&up), relabel(&down));
        for i in 2..m {
            out[i][j] = (a[i] - b[i]) / (up[j] - down[j]);
        }
    }
    out
}
