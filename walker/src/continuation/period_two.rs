//! Period-two gaits: the second iterate `P o P` as a [`GaitProblem`] of its own, and the switch
//! from a period doubling of a period-one branch to the branch of period-two cycles born there.
//!
//! At a period doubling `(r*, p*)` the multiplier -1 of `D_r P` has an eigenvector `v`; the
//! period-two branch leaves `r*` along `v` with the parameter stationary, `p - p* = O(eps^2)`
//! for `r - r* = eps v + O(eps^2)`, while the period-one branch (also a branch of fixed points of
//! `P o P`) crosses the hyperplane `v . (r - r*) = eps` at a parameter distance of order `eps`.
//! The corrector on `P o P` in that hyperplane from `(r* + eps v, p*)` therefore lands on the
//! period-two branch for small `eps`; the point is accepted when it is not a fixed point of `P`
//! (`|P(r) - r|` at least `eps / 10`), and continued away from the period doubling.

use nalgebra::{DMatrix, DVector};

use super::arclength::{ContinuationError, ContinuationOptions, Node, assemble, run};
use super::branch::{Branch, EndReason, LabelKind, Point};
use super::corrector::{Frame, complete, correct};
use super::problem::{Cycle, GaitProblem, MapValue, ProblemError, Tests};

/// The second iterate `r -> P(P(r, p), p)` of a problem: its fixed points that are not fixed
/// points of `P` are the period-two cycles. Its cycle describes both steps (`T = T_1 + T_2`,
/// `dx = dx_1 + dx_2`); its tests are the smaller of the two steps' values (the first step's
/// stick-slip structure).
#[derive(Clone, Copy, Debug)]
pub struct SecondIterate<'a, G: GaitProblem + ?Sized> {
    /// The problem whose map is iterated.
    pub inner: &'a G,
}

/// The smaller of two optional test values.
fn min_opt(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    match (a, b) {
        (Some(x), Some(y)) => Some(x.min(y)),
        (x, y) => x.or(y),
    }
}

impl<G: GaitProblem + ?Sized> GaitProblem for SecondIterate<'_, G> {
    fn dim(&self) -> usize {
        self.inner.dim()
    }

    fn parameter_name(&self) -> &str {
        self.inner.parameter_name()
    }

    fn map(&self, r: &[f64], p: f64) -> Result<MapValue, ProblemError> {
        let first = self.inner.map(r, p)?;
        let second = self.inner.map(&first.image, p)?;
        let (t1, t2) = (first.tests, second.tests);
        let period = first.cycle.period + second.cycle.period;
        let dx = first.cycle.dx + second.cycle.dx;
        Ok(MapValue {
            image: second.image,
            cycle: Cycle {
                period,
                dx,
                speed: dx / period,
            },
            tests: Tests {
                min_normal_force: min_opt(t1.min_normal_force, t2.min_normal_force),
                rear_release: min_opt(t1.rear_release, t2.rear_release),
                strike_after_t_set: min_opt(t1.strike_after_t_set, t2.strike_after_t_set),
                structure: t1.structure,
            },
        })
    }

    fn image(&self, r: &[f64], p: f64) -> Result<Vec<f64>, ProblemError> {
        self.inner.image(&self.inner.image(r, p)?, p)
    }

    fn jacobian(&self, r: &[f64], p: f64) -> Result<DMatrix<f64>, ProblemError> {
        let first = self.inner.map(r, p)?;
        Ok(self.inner.jacobian(&first.image, p)? * self.inner.jacobian(r, p)?)
    }

    fn has_family_at(&self, p: f64) -> bool {
        self.inner.has_family_at(p)
    }

    fn held_coordinate(&self) -> Option<usize> {
        self.inner.held_coordinate()
    }

    fn guess(&self, _p: f64) -> Option<Vec<f64>> {
        None
    }
}

/// Offsets `eps` along the critical eigenvector tried, relative to `max(1, |r*|)`.
const OFFSETS: [f64; 4] = [1e-3, 3e-3, 1e-2, 3e-2];

/// The branch of period-two cycles born at the period doubling `pd` (a point of a period-one
/// branch of `problem` labelled [`LabelKind::PeriodDoubling`]), followed within `[from, to]`
/// away from the period doubling. The first point is the period doubling itself (labelled
/// `PD`; there the period-two cycle is the period-one cycle walked twice); the branch's first
/// end reason is [`EndReason::BranchSwitch`].
///
/// # Errors
/// [`ContinuationError::InvalidOptions`] for invalid options; [`ContinuationError::NoSeed`]
/// when no offset along the critical eigenvector gives a period-two cycle, or the map fails at
/// the period doubling.
pub fn period_two<G: GaitProblem + ?Sized>(
    problem: &G,
    pd: &Point,
    from: f64,
    to: f64,
    opts: &ContinuationOptions,
) -> Result<Branch, ContinuationError> {
    opts.validate()?;
    let parameter = problem.parameter_name().to_owned();
    let no_seed = |last| ContinuationError::NoSeed {
        parameter: parameter.clone(),
        tried: vec![pd.parameter],
        last,
        tries: Vec::new(),
    };
    if !(from.is_finite() && to.is_finite()) || from == to {
        return Err(ContinuationError::EmptyRange {
            parameter,
            from,
            to,
        });
    }
    let frame = Frame {
        from,
        span: to - from,
    };
    let n = pd.state.len();
    let q = (pd.parameter - from) / frame.span;
    let jac = problem
        .jacobian(&pd.state, pd.parameter)
        .map_err(|e| no_seed(Some(e)))?;
    let a = &jac + DMatrix::identity(n, n);
    let svd = a.svd(false, true);
    let Some(v_t) = svd.v_t else {
        return Err(no_seed(None));
    };
    let k = svd.singular_values.imin();
    let v = DVector::from_fn(n, |i, _| v_t[(k, i)]);
    let twice = SecondIterate { inner: problem };
    let z_pd = DVector::from_fn(n + 1, |i, _| if i < n { pd.state[i] } else { q });
    let mut dir = DVector::zeros(n + 1);
    for i in 0..n {
        dir[i] = v[i];
    }
    if let Some(k) = problem.held_coordinate()
        && pd.state[k] == 0.0
    {
        // A held foot stays held on the period-two branch born here: the eigenvector's
        // component along its velocity is rounding (that row of `D_r P` is zero), and an
        // offset along it would start a slide.
        dir[k] = 0.0;
        if dir.norm() > 0.0 {
            dir = dir.normalize();
        }
    }
    let value = twice
        .map(&pd.state, pd.parameter)
        .map_err(|e| no_seed(Some(e)))?;
    let at_pd = complete(&twice, &frame, z_pd.clone(), value, pd.residual, &dir)
        .map_err(|e| no_seed(Some(e)))?;
    let scale = pd.state.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
    for eps in OFFSETS.map(|e| e * scale) {
        let pred = &z_pd + &dir * eps;
        // The period doubling is a singular point of `P o P - r` (its Jacobian in `r` and in
        // `p` vanish along `v`): the corrector's matrix is taken at the predicted point.
        let r_pred: Vec<f64> = pred.rows(0, n).iter().copied().collect();
        let Ok(v_pred) = twice.map(&r_pred, pd.parameter) else {
            continue;
        };
        let Ok(start) = complete(&twice, &frame, pred.clone(), v_pred, f64::NAN, &dir) else {
            continue;
        };
        let Ok((z, value, res, _)) = correct(
            &twice,
            &frame,
            pred.clone(),
            &dir,
            &pred,
            &start.jac,
            &start.fq,
            opts.tol,
        ) else {
            continue;
        };
        let r: Vec<f64> = z.rows(0, n).iter().copied().collect();
        let Ok(once) = problem.map(&r, frame.p(z[n])) else {
            continue;
        };
        let off = once
            .image
            .iter()
            .zip(&r)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        if off < eps / 10.0 {
            continue;
        }
        let Ok(seed) = complete(&twice, &frame, z, value, res, &dir) else {
            continue;
        };
        let (nodes, end) = run(&twice, &frame, seed, opts);
        let mut all = vec![Node {
            s: at_pd,
            label: Some((LabelKind::PeriodDoubling, 0.0)),
        }];
        all.extend(nodes);
        return Ok(assemble(
            &twice,
            &frame,
            all,
            [EndReason::BranchSwitch, end],
            2,
        ));
    }
    Err(no_seed(None))
}
