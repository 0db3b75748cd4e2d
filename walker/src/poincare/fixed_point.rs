//! Fixed points of the reduced Poincare map (limit cycles) by Newton's method, with least-norm
//! steps where `D P_r - I` is singular, and their multipliers and validity.

use nalgebra::{Matrix2, Vector2};
use serde::Serialize;

use crate::model::Model;
use crate::sim::{Failure, SimConfig, WalkLimits, walk};

use super::error::FixedPointError;
use super::map::{JacobianMethod, MapResult, poincare_map};
use super::multipliers::{Multiplier, UNIT_MULTIPLIER_TOL, eigenvalues};
use super::section::{embed, reduce, reduced_jacobian};
use crate::model::ImpactRegime;

/// Outcome of the fixed-point search.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Status {
    /// Newton's method converged to an isolated cycle.
    Converged,
    /// Converged to a member of a family of cycles (structural multiplier at 1, `mu0 = 0`).
    Family,
    /// The residual did not reach the tolerance.
    NotConverged,
    /// The cycle was found but is not a valid gait (a failure of [`crate::sim::walk`] on it).
    InvalidGait,
}

/// A limit cycle: its post-impact state, descriptors and multipliers.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FixedPoint {
    /// Outcome.
    pub status: Status,
    /// The fixed point `[x, z, th1, th2, xd, zd, th1d, th2d]` of the map (foot-relative).
    pub state_plus: [f64; 8],
    /// Step period (s).
    #[serde(rename = "T")]
    pub period: f64,
    /// Average walking speed `dx / T` (m/s).
    #[serde(rename = "V")]
    pub speed: f64,
    /// Step length (m).
    pub dx: f64,
    /// The gait's Floquet multipliers: eigenvalues of the reduced map in `(xd, th1d)`, by
    /// decreasing modulus.
    pub multipliers: Vec<Multiplier>,
    /// All eight eigenvalues of the full foot-relative map (the trivial ones explained in the
    /// module documentation).
    pub full_multipliers: Vec<Multiplier>,
    /// The reduced Jacobian `D P_r` at the fixed point.
    pub reduced_jacobian: [[f64; 2]; 2],
    /// How the map's Jacobian was computed.
    pub jacobian_method: JacobianMethod,
    /// How the striking foot ends the cycle's impact (left out of the JSON for the paper's
    /// frictionless impact). With friction the map is only piecewise smooth; the multipliers
    /// are those of this regime (`docs/impacts.md`).
    #[serde(skip_serializing_if = "ImpactRegime::is_frictionless")]
    pub impact: ImpactRegime,
    /// A multiplier of the reduced map lies within [`UNIT_MULTIPLIER_TOL`] of 1: a family of
    /// cycles (conserved horizontal momentum for `mu0 = 0`), not a loss of stability.
    pub structural_unit_multiplier: bool,
    /// `|P_r(r) - r|` at the returned point.
    pub residual: f64,
    /// Newton iterations taken.
    pub iterations: usize,
    /// The failure of [`crate::sim::walk`] on the cycle, if any (see [`Status::InvalidGait`]).
    /// Serialised as its name (`"lift-off"`, ...), as the JSON of `walker fixed-point` has it.
    #[serde(serialize_with = "failure_name")]
    pub failure: Option<Failure>,
}

impl FixedPoint {
    /// The largest multiplier modulus of the gait (0 if none).
    pub fn max_modulus(&self) -> f64 {
        self.multipliers
            .iter()
            .map(Multiplier::modulus)
            .fold(0.0, f64::max)
    }
}

/// Settings of [`fixed_point`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FixedPointOptions {
    /// Initial angular velocity of the warm-up walk (Eq. 33 / (P2b)).
    pub omega0: f64,
    /// Steps simulated from the initial condition to obtain Newton's initial guess.
    pub warmup_steps: usize,
    /// Largest number of Newton iterations.
    pub max_iter: usize,
    /// Newton stops when `|P_r(r) - r| <= tol`.
    pub tol: f64,
}

impl FixedPointOptions {
    /// Defaults for a model: its default `omega0`, 30 warm-up steps, 30 iterations, `1e-11`.
    pub fn for_model(model: &Model) -> Self {
        Self {
            omega0: model.default_omega0(),
            warmup_steps: 30,
            max_iter: 30,
            tol: 1e-11,
        }
    }
}

/// Least-norm solution of `a d = b` by the SVD with singular values below
/// `UNIT_MULTIPLIER_TOL * max(1, sigma_max)` dropped; also whether any was dropped.
fn least_norm(a: [[f64; 2]; 2], b: [f64; 2]) -> ([f64; 2], bool) {
    let m = Matrix2::new(a[0][0], a[0][1], a[1][0], a[1][1]);
    let svd = m.svd(true, true);
    let smax = svd.singular_values.max();
    let eps = UNIT_MULTIPLIER_TOL * smax.max(1.0);
    let singular = svd.singular_values.iter().any(|&s| s <= eps);
    let d = svd
        .solve(&Vector2::new(b[0], b[1]), eps)
        .map(|v| [v[0], v[1]])
        .unwrap_or([0.0, 0.0]);
    (d, singular)
}

/// Find the limit cycle reached from the model's initial condition with `opts.omega0`:
/// simulate `opts.warmup_steps` steps, then Newton's method on `P_r(r) - r` in the reduced
/// coordinates (least-norm steps when `D P_r - I` is singular, damped when the map fails),
/// then the multipliers at the result and a validity check of one step of
/// [`crate::sim::walk`] from it.
pub fn fixed_point(
    model: &Model,
    cfg: &SimConfig,
    opts: &FixedPointOptions,
) -> Result<FixedPoint, FixedPointError> {
    let limits = WalkLimits {
        max_steps: opts.warmup_steps.max(1),
        ..WalkLimits::default()
    };
    let w = walk(model, cfg, model.initial_state(opts.omega0), &limits);
    let s0 = w.last_state().ok_or_else(|| {
        w.failure
            .clone()
            .map_or(FixedPointError::NoWarmupStep, FixedPointError::Warmup)
    })?;
    newton(model, cfg, reduce(&s0), opts)
}

/// Newton's method of [`fixed_point`] from the reduced guess `r0 = (xd+, th1d+)` (no warm-up
/// walk): for continuation from a neighbouring cycle.
pub fn newton(
    model: &Model,
    cfg: &SimConfig,
    r0: [f64; 2],
    opts: &FixedPointOptions,
) -> Result<FixedPoint, FixedPointError> {
    let mut r = r0;
    let mut m = poincare_map(model, cfg, &embed(model, r))?;
    let mut iterations = 0;
    let mut singular = false;
    let (mut res, mut jr) = residual(model, &m, r);
    while res > opts.tol && iterations < opts.max_iter {
        iterations += 1;
        let fr = [
            reduce(&m.state_plus)[0] - r[0],
            reduce(&m.state_plus)[1] - r[1],
        ];
        let a = [[jr[0][0] - 1.0, jr[0][1]], [jr[1][0], jr[1][1] - 1.0]];
        let (mut d, sing) = least_norm(a, [-fr[0], -fr[1]]);
        if m.state_plus[4] == 0.0 && r[0] == 0.0 {
            // A sticking impact leaves the new foot exactly at rest (`Model::reset`): the
            // cycle lies on `xd = 0`, and a step off it by rounding would start a slide.
            d[0] = 0.0;
        }
        singular |= sing;
        let mut step = 1.0;
        let mut next = None;
        for _ in 0..8 {
            let rn = [r[0] + step * d[0], r[1] + step * d[1]];
            if let Ok(mn) = poincare_map(model, cfg, &embed(model, rn)) {
                let (rs, jn) = residual(model, &mn, rn);
                if rs < res || step < 0.01 {
                    next = Some((rn, mn, rs, jn));
                    break;
                }
            }
            step *= 0.5;
        }
        let Some((rn, mn, rs, jn)) = next else {
            break;
        };
        r = rn;
        m = mn;
        res = rs;
        jr = jn;
    }
    let multipliers = eigenvalues(&jr.map(|row| row.to_vec()));
    let full_multipliers = eigenvalues(&m.jacobian.map(|row| row.to_vec()));
    let structural = singular
        || multipliers
            .iter()
            .any(|l| (l.re - 1.0).hypot(l.im) < UNIT_MULTIPLIER_TOL);
    let state_plus = embed(model, r);
    let check = walk(
        model,
        cfg,
        state_plus,
        &WalkLimits {
            max_steps: 1,
            ..WalkLimits::default()
        },
    );
    let failure = check.failure;
    let status = if failure.is_some() {
        Status::InvalidGait
    } else if res > opts.tol {
        Status::NotConverged
    } else if structural {
        Status::Family
    } else {
        Status::Converged
    };
    Ok(FixedPoint {
        status,
        state_plus,
        period: m.period,
        speed: m.dx / m.period,
        dx: m.dx,
        multipliers,
        full_multipliers,
        reduced_jacobian: jr,
        jacobian_method: m.method,
        impact: m.impact,
        structural_unit_multiplier: structural,
        residual: res,
        iterations,
        failure,
    })
}

fn residual(model: &Model, m: &MapResult, r: [f64; 2]) -> (f64, [[f64; 2]; 2]) {
    let p = reduce(&m.state_plus);
    (
        (p[0] - r[0]).hypot(p[1] - r[1]),
        reduced_jacobian(model, &m.jacobian),
    )
}

/// A failure as its name (`"lift-off"`), or `null`.
fn failure_name<S: serde::Serializer>(f: &Option<Failure>, s: S) -> Result<S::Ok, S::Error> {
    match f {
        Some(f) => s.serialize_some(f.name()),
        None => s.serialize_none(),
    }
}
