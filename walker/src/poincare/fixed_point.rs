//! Fixed points of the reduced Poincare map (limit cycles) by Newton's method, with least-norm
//! steps where `D P_r - I` is singular, and their multipliers and validity.

use nalgebra::{DMatrix, DVector, Matrix2, Vector2};
use serde::Serialize;

use crate::model::Model;
use crate::sim::{Failure, SimConfig, WalkLimits, walk};
use crate::vector::Vector;

use super::error::FixedPointError;
use super::finite_difference::{DEFAULT_STEP, finite_difference_map_with_step};
use super::map::poincare_map_with;
use super::multipliers::{Multiplier, UNIT_MULTIPLIER_TOL, eigenvalues};
use super::result::{JacobianMethod, MapResult, StepCheck};
use super::section::Section;
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
    /// The fixed point `[q, qd]` of the map (foot-relative: `x = z = 0`).
    pub state_plus: Vector,
    /// Step period (s).
    #[serde(rename = "T")]
    pub period: f64,
    /// Average walking speed `dx / T` (m/s).
    #[serde(rename = "V")]
    pub speed: f64,
    /// Step length (m).
    pub dx: f64,
    /// The gait's Floquet multipliers: eigenvalues of the map reduced to the section's
    /// independent coordinates (the paper's `(xd, th1d)`), by decreasing modulus.
    pub multipliers: Vec<Multiplier>,
    /// All `2n` eigenvalues of the full foot-relative map (the trivial ones explained in the
    /// module documentation), where [`FixedPointOptions::full_multipliers`] asked for them
    /// (left out of the JSON otherwise).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub full_multipliers: Option<Vec<Multiplier>>,
    /// The section's independent coordinates, by name.
    pub section: Vec<String>,
    /// The reduced Jacobian `D P_r` at the fixed point.
    pub reduced_jacobian: Vec<Vec<f64>>,
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
    /// The start of the warm-up walk (the model's `[start]`: Eq. 33 / (P2b) for the paper's).
    pub start: Vector,
    /// Steps simulated from the initial condition to obtain Newton's initial guess.
    pub warmup_steps: usize,
    /// Largest number of Newton iterations.
    pub max_iter: usize,
    /// Newton stops when `|P_r(r) - r| <= tol`.
    pub tol: f64,
    /// Where the map's Jacobian is by central differences (a phase without a Jacobian
    /// kernel), evaluate it once more at the result at half the step and extrapolate
    /// ([`JacobianMethod::ExtrapolatedDifferences`]): the multipliers to about `1e-8` instead of
    /// `1e-4`, for one more differenced map. Off by default (continuation and design call Newton
    /// many times and need no more than its convergence); `walker fixed-point` turns it on.
    pub refine: bool,
    /// Evaluate the map once more at the result with its full `2n x 2n` Jacobian, for
    /// [`FixedPoint::full_multipliers`]. Newton's method needs only the Jacobian along the
    /// section (`DP E`, [`Section::map`]: `d` sensitivity columns instead of `2n`). Off by
    /// default; `walker fixed-point` turns it on.
    pub full_multipliers: bool,
    /// Whether Newton's maps exist only where the simulator's step does ([`StepCheck::Walk`]:
    /// gait design, whose iterates must walk) or not (the default: a cycle past a boundary is
    /// found, and reported as not a valid gait).
    pub step_check: StepCheck,
}

impl FixedPointOptions {
    /// Defaults for a model: its start, 30 warm-up steps, 30 iterations, `1e-11`.
    pub fn for_model(model: &Model) -> Self {
        Self {
            start: model.start_state(),
            warmup_steps: 30,
            max_iter: 30,
            tol: 1e-11,
            refine: false,
            full_multipliers: false,
            step_check: StepCheck::Through,
        }
    }
}

/// Least-norm solution of `a d = b` by the SVD with singular values below
/// `UNIT_MULTIPLIER_TOL * max(1, sigma_max)` dropped; also whether any was dropped. A 2 x 2
/// system (the paper's walkers) takes nalgebra's closed-form 2 x 2 SVD, any other size its
/// general one.
fn least_norm(a: &[Vec<f64>], b: &[f64]) -> (Vec<f64>, bool) {
    let k = b.len();
    if k == 2 {
        let svd = Matrix2::new(a[0][0], a[0][1], a[1][0], a[1][1]).svd(true, true);
        let eps = UNIT_MULTIPLIER_TOL * svd.singular_values.max().max(1.0);
        let singular = svd.singular_values.iter().any(|&s| s <= eps);
        let d = svd
            .solve(&Vector2::new(b[0], b[1]), eps)
            .map_or_else(|_| vec![0.0; 2], |v| vec![v[0], v[1]]);
        return (d, singular);
    }
    let svd = DMatrix::from_fn(k, k, |i, j| a[i][j]).svd(true, true);
    let eps = UNIT_MULTIPLIER_TOL * svd.singular_values.max().max(1.0);
    let singular = svd.singular_values.iter().any(|&s| s <= eps);
    let d = svd
        .solve(&DVector::from_column_slice(b), eps)
        .map_or_else(|_| vec![0.0; k], |v| v.iter().copied().collect());
    (d, singular)
}

/// Find the limit cycle reached from `opts.start`: simulate `opts.warmup_steps` steps, then
/// Newton's method on `P_r(r) - r` in the section's coordinates (least-norm steps when
/// `D P_r - I` is singular, damped when the map fails), then the multipliers at the result and
/// a validity check of one step of [`crate::sim::walk`] from it.
///
/// # Errors
/// The warm-up walk fails before its first step, or the map fails at the guess.
pub fn fixed_point(
    model: &Model,
    cfg: &SimConfig,
    opts: &FixedPointOptions,
) -> Result<FixedPoint, FixedPointError> {
    let limits = WalkLimits {
        max_steps: opts.warmup_steps.max(1),
        ..WalkLimits::default()
    };
    let w = walk(model, cfg, &opts.start, &limits);
    let s0 = w.last_state().ok_or_else(|| {
        w.failure
            .clone()
            .map_or(FixedPointError::NoWarmupStep, FixedPointError::Warmup)
    })?;
    newton(model, cfg, &Section::of(model).reduce(&s0), opts)
}

/// Newton's method of [`fixed_point`] from the guess `r0` in the section's coordinates (no
/// warm-up walk): for continuation from a neighbouring cycle.
///
/// # Errors
/// The map fails at the guess.
pub fn newton(
    model: &Model,
    cfg: &SimConfig,
    r0: &[f64],
    opts: &FixedPointOptions,
) -> Result<FixedPoint, FixedPointError> {
    let section = Section::of(model);
    let dim = section.dim();
    let n = model.n();
    // The foot's velocity along the floor among the section's coordinates, if it is one.
    let xd = section.free().iter().position(|&i| i == n);
    let mut r = r0.to_vec();
    let map = |r: &[f64]| section.map_with(cfg, r, JacobianMethod::Variational, opts.step_check);
    let mut m = map(&r)?;
    let mut iterations = 0;
    let mut singular = false;
    let (mut res, mut jr) = residual(&section, &m, &r);
    while res > opts.tol && iterations < opts.max_iter {
        iterations += 1;
        let image = section.reduce(&m.state_plus);
        let minus_f: Vec<f64> = image.iter().zip(&r).map(|(p, x)| -(p - x)).collect();
        let a: Vec<Vec<f64>> = (0..dim)
            .map(|i| {
                (0..dim)
                    .map(|j| jr[i][j] - if i == j { 1.0 } else { 0.0 })
                    .collect()
            })
            .collect();
        let (mut d, sing) = least_norm(&a, &minus_f);
        if let Some(k) = xd
            && m.state_plus[n] == 0.0
            && r[k] == 0.0
        {
            // A sticking impact leaves the new foot exactly at rest (`Model::reset`): the
            // cycle lies on `xd = 0`, and a step off it by rounding would start a slide.
            d[k] = 0.0;
        }
        singular |= sing;
        let mut step = 1.0;
        let mut next = None;
        for _ in 0..8 {
            let rn: Vec<f64> = r.iter().zip(&d).map(|(x, dx)| x + step * dx).collect();
            if let Ok(mn) = map(&rn) {
                let (rs, jn) = residual(&section, &mn, &rn);
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
    // The full Jacobian at the result, where asked for or needed for the extrapolation (one
    // more map: Newton's were along the section).
    let differenced = m.method == JacobianMethod::FiniteDifferences;
    let mut full = None;
    if opts.full_multipliers || (opts.refine && differenced) {
        // (It just succeeded along the section; were it to fail now, the full multipliers and
        // the extrapolation are left out, not the fixed point.)
        full = poincare_map_with(model, cfg, &section.embed(&r), m.method)
            .ok()
            .map(|f| f.jacobian);
    }
    if let Some(coarse) = full.as_mut()
        && opts.refine
        && differenced
    {
        // At half the step, extrapolated (a failure there leaves the plain differences).
        let s = section.embed(&r);
        if let Ok(fine) = finite_difference_map_with_step(model, cfg, &s, DEFAULT_STEP / 2.0) {
            *coarse = extrapolate(coarse, &fine.jacobian);
            m.method = JacobianMethod::ExtrapolatedDifferences;
            jr = section.reduced_jacobian(coarse, &r);
        }
    }
    let multipliers = eigenvalues(&jr);
    let full_multipliers = opts
        .full_multipliers
        .then(|| full.as_deref().map(eigenvalues))
        .flatten();
    let structural = singular
        || multipliers
            .iter()
            .any(|l| (l.re - 1.0).hypot(l.im) < UNIT_MULTIPLIER_TOL);
    let state_plus = section.embed(&r);
    let check = walk(
        model,
        cfg,
        &state_plus,
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
        section: section.names(),
        reduced_jacobian: jr,
        jacobian_method: m.method,
        impact: m.impact,
        structural_unit_multiplier: structural,
        residual: res,
        iterations,
        failure,
    })
}

/// Richardson's extrapolation `(4 J(h/2) - J(h)) / 3` of central differences at `h` and `h/2`,
/// entry by entry.
pub(super) fn extrapolate(coarse: &[Vec<f64>], fine: &[Vec<f64>]) -> Vec<Vec<f64>> {
    coarse
        .iter()
        .zip(fine)
        .map(|(a, b)| a.iter().zip(b).map(|(x, y)| (4.0 * y - x) / 3.0).collect())
        .collect()
}

/// `|P_r(r) - r|` and the reduced Jacobian at `r`.
fn residual(section: &Section<'_>, m: &MapResult, r: &[f64]) -> (f64, Vec<Vec<f64>>) {
    let p = section.reduce(&m.state_plus);
    (
        p.iter().zip(r).fold(0.0, |acc, (a, b)| acc.hypot(a - b)),
        section.reduced(&m.jacobian),
    )
}

/// A failure as its name (`"lift-off"`), or `null`.
fn failure_name<S: serde::Serializer>(f: &Option<Failure>, s: S) -> Result<S::Ok, S::Error> {
    match f {
        Some(f) => s.serialize_some(f.name()),
        None => s.serialize_none(),
    }
}
