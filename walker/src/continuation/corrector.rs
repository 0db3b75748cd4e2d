//! The corrector of the pseudo-arclength method and what a converged point carries.
//!
//! Internally a point is `z = (r, q)` with the parameter scaled to the asked range,
//! `p = from + q (to - from)`, so that `q` runs over `[0, 1]` whatever the parameter's unit and
//! the arclength weighs the state and the parameter alike ([`Frame`]). The corrector solves
//! `F(z) = P(r, p(q)) - r = 0` together with one scalar condition `n . (z - a) = 0`: the
//! arclength hyperplane of Keller's method (`n` the tangent, `a` the predicted point), or
//! `q = const` (`n = e_q`) at the ends of the range. It is a quasi-Newton method: the matrix
//! `[D_r P - I | dP/dq; n^T]` starts as that of the last converged point and is corrected by
//! Broyden's rank-one updates, and only `F` is evaluated at the iterates, by the problem's
//! cheap map. The converged point does not depend on the
//! matrix, only the number of iterations does; singular values below
//! [`UNIT_MULTIPLIER_TOL`] times the largest are dropped (least-norm steps), so that on a
//! family of cycles the corrector goes to the nearest member instead of dividing by zero.

use nalgebra::{DMatrix, DVector};

use crate::poincare::UNIT_MULTIPLIER_TOL;

use super::problem::{GaitProblem, MapValue, ProblemError};

/// The scaling of the parameter: `p = from + q span`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Frame {
    /// The parameter at `q = 0`.
    pub(super) from: f64,
    /// `to - from`.
    pub(super) span: f64,
}

impl Frame {
    /// The parameter at `q`.
    pub(super) fn p(&self, q: f64) -> f64 {
        self.from + q * self.span
    }

    /// The sign of the parameter step pointing from `q` into the range (for one-sided
    /// differences).
    fn inward(&self, q: f64) -> f64 {
        if q < 0.5 {
            self.span.signum()
        } else {
            -self.span.signum()
        }
    }
}

/// A converged point with its map value, Jacobians and tangent.
#[derive(Clone, Debug)]
pub(super) struct Solved {
    /// `(r, q)`.
    pub(super) z: DVector<f64>,
    /// The map at `z`.
    pub(super) value: MapValue,
    /// `D_r P` at `z`.
    pub(super) jac: DMatrix<f64>,
    /// `dP/dq` at `z`.
    pub(super) fq: DVector<f64>,
    /// The unit tangent of the branch, oriented along the continuation.
    pub(super) tangent: DVector<f64>,
    /// `|P(r) - r|` (infinity norm).
    pub(super) residual: f64,
}

impl Solved {
    /// The scaled parameter `q`.
    pub(super) fn q(&self) -> f64 {
        self.z[self.z.len() - 1]
    }

    /// The state `r`.
    pub(super) fn r(&self) -> Vec<f64> {
        self.z.rows(0, self.z.len() - 1).iter().copied().collect()
    }
}

/// Why the corrector stopped without a point.
#[derive(Clone, Debug)]
pub(super) enum CorrectError {
    /// The map failed at an iterate.
    Map(ProblemError),
    /// The residual did not fall below the tolerance.
    NoConvergence,
}

/// A held coordinate ([`GaitProblem::held_coordinate`]) within this of zero at the start of a
/// correction is zero: the linear algebra's rounding (a tangent component of `1e-17` times a
/// step), not a motion. A foot sliding at `1e-12` m/s would move `1e-12` m in a step.
const HELD_ROUNDING: f64 = 1e-12;

/// Whether `z`'s held coordinate `k` is exactly zero together with its image's (`f[k] = P_k -
/// r_k`): a sticking impact, whose fixed points all have it zero.
pub(super) fn held_at(k: Option<usize>, z: &DVector<f64>, f: &DVector<f64>) -> Option<usize> {
    k.filter(|&k| z[k] == 0.0 && f[k] == 0.0)
}

/// Largest number of chord iterations.
const MAX_ITER: usize = 12;

/// `P(r, p(q)) - r` at `z`, from the image alone ([`GaitProblem::image`]).
fn residual<G: GaitProblem + ?Sized>(
    problem: &G,
    frame: &Frame,
    z: &DVector<f64>,
) -> Result<DVector<f64>, ProblemError> {
    let n = z.len() - 1;
    let r: Vec<f64> = z.rows(0, n).iter().copied().collect();
    let image = problem.image(&r, frame.p(z[n]))?;
    Ok(DVector::from_fn(n, |i, _| image[i] - r[i]))
}

/// The map's full value (descriptors and tests) at the accepted iterate `z`.
fn value_at<G: GaitProblem + ?Sized>(
    problem: &G,
    frame: &Frame,
    z: &DVector<f64>,
) -> Result<MapValue, ProblemError> {
    let n = z.len() - 1;
    let r: Vec<f64> = z.rows(0, n).iter().copied().collect();
    problem.map(&r, frame.p(z[n]))
}

/// The bordered matrix `[D_r P - I | dP/dq; n^T]`.
pub(super) fn bordered(
    jac: &DMatrix<f64>,
    fq: &DVector<f64>,
    normal: &DVector<f64>,
) -> DMatrix<f64> {
    let n = jac.nrows();
    DMatrix::from_fn(n + 1, n + 1, |i, j| {
        if i == n {
            normal[j]
        } else if j == n {
            fq[i]
        } else {
            jac[(i, j)] - if i == j { 1.0 } else { 0.0 }
        }
    })
}

/// Least-norm solution of `m x = b` with singular values below `UNIT_MULTIPLIER_TOL` times the
/// largest (at least 1) dropped; `None` if the SVD fails.
fn solve(m: DMatrix<f64>, b: &DVector<f64>) -> Option<DVector<f64>> {
    let svd = m.svd(true, true);
    let eps = UNIT_MULTIPLIER_TOL * svd.singular_values.max().max(1.0);
    svd.solve(b, eps).ok()
}

/// The quasi-Newton corrector from `z0` on `F = 0`, `normal . (z - anchor) = 0`, with the matrix
/// of `jac` and `fq`. Returns the point, its map value, `|F|` and the iterations taken.
///
/// # Errors
/// The map failed at an iterate, or the residual did not reach `tol` in 12 iterations (or
/// grew a thousandfold).
#[allow(
    clippy::too_many_arguments,
    reason = "the pieces of one bordered system"
)]
pub(super) fn correct<G: GaitProblem + ?Sized>(
    problem: &G,
    frame: &Frame,
    z0: DVector<f64>,
    normal: &DVector<f64>,
    anchor: &DVector<f64>,
    jac: &DMatrix<f64>,
    fq: &DVector<f64>,
    tol: f64,
) -> Result<(DVector<f64>, MapValue, f64, usize), CorrectError> {
    let n = jac.nrows();
    let mut m = bordered(jac, fq, normal);
    let fixes_q = normal[n] == 1.0 && normal.rows(0, n).iter().all(|v| *v == 0.0);
    let mut z = z0;
    let held = problem.held_coordinate();
    if let Some(k) = held
        && z[k].abs() <= HELD_ROUNDING
    {
        z[k] = 0.0;
    }
    let mut f = residual(problem, frame, &z).map_err(CorrectError::Map)?;
    // On a sticking impact the held coordinate's fixed-point equation is `0 - r_k = 0`: it
    // stays at zero, whatever rounding the bordered solve puts into its step.
    let pinned = held_at(held, &z, &f);
    // The full map value at `z` where it was evaluated instead of the image alone.
    let mut value: Option<MapValue> = None;
    let first = f.amax();
    let mut previous = f64::INFINITY;
    for it in 0..=MAX_ITER {
        let res = f.amax();

        if res <= tol {
            let value = match value {
                Some(v) => v,
                None => value_at(problem, frame, &z).map_err(CorrectError::Map)?,
            };
            return Ok((z, value, res, it));
        }
        if it == MAX_ITER || !res.is_finite() || res > 1e3 * first.max(tol) {
            break;
        }
        let mut b = DVector::zeros(n + 1);
        for i in 0..n {
            b[i] = -f[i];
        }
        b[n] = -normal.dot(&(&z - anchor));
        let mut dz = solve(m.clone(), &b).ok_or(CorrectError::NoConvergence)?;
        if let Some(k) = pinned {
            dz[k] = 0.0;
        }
        z += &dz;
        if fixes_q {
            // Exactly on the asked parameter (an end of the range, a user point): rounding in
            // the solve must not move it.
            z[n] = anchor[n];
        }
        let f_old = f;
        // The iterate that is expected to be accepted gets the full map at once: the residual
        // falls superlinearly near the end, so the next one is about `res^2 / previous`.
        let expected = if previous.is_finite() {
            res * (res / previous)
        } else {
            f64::INFINITY
        };
        previous = res;
        if expected <= tol {
            let v = value_at(problem, frame, &z).map_err(CorrectError::Map)?;
            f = DVector::from_fn(n, |i, _| v.image[i] - z[i]);
            value = Some(v);
        } else {
            f = residual(problem, frame, &z).map_err(CorrectError::Map)?;
            value = None;
        }
        // Broyden's update of the rows of `F`: `M += (dF - M dz) dz^T / |dz|^2`. The bordering
        // row is linear and exact, so its update would be zero.
        let dd = dz.norm_squared();
        if dd > 0.0 {
            let md = &m * &dz;
            for i in 0..n {
                let c = (f[i] - f_old[i] - md[i]) / dd;
                for j in 0..=n {
                    m[(i, j)] += c * dz[j];
                }
            }
        }
    }
    Err(CorrectError::NoConvergence)
}

/// The unit tangent `t` with `[D_r P - I | dP/dq] t = 0`, oriented so that `t . previous > 0`;
/// `previous` itself where the bordered matrix is singular (a family of cycles).
pub(super) fn tangent(
    jac: &DMatrix<f64>,
    fq: &DVector<f64>,
    previous: &DVector<f64>,
) -> DVector<f64> {
    let n = jac.nrows();
    let m = bordered(jac, fq, previous);
    let mut e = DVector::zeros(n + 1);
    e[n] = 1.0;
    match m.lu().solve(&e) {
        Some(t) if t.iter().all(|v| v.is_finite()) && t.norm() > 0.0 => {
            let t = t.normalize();
            if t.dot(previous) < 0.0 { -t } else { t }
        }
        _ => previous.clone(),
    }
}

/// The converged point at `z` with map value `value`: its Jacobian `D_r P`, `dP/dq` (the
/// problem's parameter derivative times the span) and its tangent oriented along `previous`.
///
/// # Errors
/// The Jacobian or the parameter derivative could not be evaluated.
pub(super) fn complete<G: GaitProblem + ?Sized>(
    problem: &G,
    frame: &Frame,
    z: DVector<f64>,
    value: MapValue,
    residual: f64,
    previous: &DVector<f64>,
) -> Result<Solved, ProblemError> {
    let n = z.len() - 1;
    let q = z[n];
    let r: Vec<f64> = z.rows(0, n).iter().copied().collect();
    let p = frame.p(q);
    let jac = problem.jacobian(&r, p)?;
    let dp = problem.parameter_derivative(&r, p, &value.image, frame.inward(q))?;
    let fq = DVector::from_fn(n, |i, _| dp[i] * frame.span);
    let mut tangent = tangent(&jac, &fq, previous);
    let f = DVector::from_fn(n, |i, _| value.image[i] - z[i]);
    if let Some(k) = held_at(problem.held_coordinate(), &z, &f) {
        // The branch of sticking impacts stays at `r_k = 0`; a tangent component there is the
        // finite differences' mixing of regimes or rounding, and a predictor along it would
        // start a slide.
        tangent[k] = 0.0;
        if tangent.norm() > 0.0 {
            tangent = tangent.normalize();
        }
    }
    Ok(Solved {
        z,
        value,
        jac,
        fq,
        tangent,
        residual,
    })
}
