//! Pseudo-arclength continuation (Keller): from a seed, tangent predictor, the corrector of
//! `corrector.rs`, step-size control, detection and location of special points between
//! consecutive points (`detect.rs`), and the ends of the range placed exactly.
//!
//! Step control, in the scaled arclength of [`super::corrector`]: a step is accepted when the
//! corrector converges, the tangent turns by less than `acos(0.9)` (26 degrees) and the
//! corrected point lies within [`MAX_PREDICTOR_DISTANCE`] of the predicted one; it grows after a
//! correction of at most three iterations (by 1.5, by up to 4 where the predictor was far more
//! accurate than [`PREDICTOR_TARGET`]), shrinks by 2 after more than eight, and is halved and
//! retried after a failed correction, a sharp turn or a far miss, down to the minimum step.

use nalgebra::DVector;
use serde::Serialize;

use super::branch::{Branch, EndReason, Label, LabelKind, Point, Stability};
use super::corrector::{CorrectError, Frame, Solved, complete, correct};
use super::detect::{self, Locator, SIGN_TESTS};
use super::problem::{GaitProblem, ProblemError};
use crate::poincare::UNIT_MULTIPLIER_TOL;

/// Settings of a continuation. Steps are in the scaled arclength, where the whole parameter
/// range has length 1 and the state is in its own units.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ContinuationOptions {
    /// The first step.
    pub initial_step: f64,
    /// The smallest step before the branch is given up on that side.
    pub min_step: f64,
    /// The largest step.
    pub max_step: f64,
    /// The corrector stops when `|P(r, p) - r|` (infinity norm) is at most this.
    pub tol: f64,
    /// Special points are located to a bracket of this width in the scaled arclength (so the
    /// parameter to this times the range, at most).
    pub locate_tol: f64,
    /// The largest number of continuation steps on each side of the seed.
    pub max_points: usize,
    /// Parameter values at which a point is placed exactly (labelled `UZ`).
    pub user_points: Vec<f64>,
    /// The branch ends where a coordinate of the state exceeds this in modulus (a branch
    /// that runs off to ever faster gaits).
    pub max_state: f64,
}

impl Default for ContinuationOptions {
    /// Steps from `1e-6` to `0.2` starting at `0.05`, the corrector to `1e-11` (the
    /// fixed-point search's tolerance, [`crate::poincare::FixedPointOptions`]), special points
    /// to `1e-9`, 400 steps a side, no user points, states up to 20 (m/s, rad/s).
    fn default() -> Self {
        Self {
            initial_step: 0.05,
            min_step: 1e-6,
            max_step: 0.2,
            tol: 1e-11,
            locate_tol: 1e-9,
            max_points: 400,
            user_points: Vec::new(),
            max_state: 20.0,
        }
    }
}

impl ContinuationOptions {
    /// Check the settings: the steps finite and positive with
    /// `min_step <= initial_step <= max_step`, the tolerances finite and positive, the state
    /// bound positive (infinite allowed) and the user points finite.
    ///
    /// # Errors
    /// [`ContinuationError::InvalidOptions`] naming the first field out of its range.
    pub fn validate(&self) -> Result<(), ContinuationError> {
        let bad = |field: &'static str, value: f64, expected: String| {
            Err(ContinuationError::InvalidOptions {
                field,
                value,
                expected,
            })
        };
        let positive = |v: f64| v.is_finite() && v > 0.0;
        for (field, v) in [
            ("min_step", self.min_step),
            ("initial_step", self.initial_step),
            ("max_step", self.max_step),
            ("tol", self.tol),
            ("locate_tol", self.locate_tol),
        ] {
            if !positive(v) {
                return bad(field, v, "finite and positive".to_owned());
            }
        }
        if self.min_step > self.max_step {
            return bad(
                "min_step",
                self.min_step,
                format!("at most max_step = {}", self.max_step),
            );
        }
        if !(self.min_step..=self.max_step).contains(&self.initial_step) {
            return bad(
                "initial_step",
                self.initial_step,
                format!(
                    "in [min_step, max_step] = [{}, {}]",
                    self.min_step, self.max_step
                ),
            );
        }
        if self.max_state.is_nan() || self.max_state <= 0.0 {
            return bad("max_state", self.max_state, "positive".to_owned());
        }
        if let Some(&p) = self.user_points.iter().find(|p| !p.is_finite()) {
            return bad("user_points", p, "finite".to_owned());
        }
        Ok(())
    }
}

/// Why no branch could be computed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ContinuationError {
    /// A setting of [`ContinuationOptions`] is out of its range.
    #[error("continuation option {field} = {value}: must be {expected}")]
    InvalidOptions {
        /// The field of [`ContinuationOptions`].
        field: &'static str,
        /// Its value.
        value: f64,
        /// What it must be.
        expected: String,
    },
    /// `from` and `to` are equal or not finite.
    #[error("the range of {parameter} is empty or not finite: from {from} to {to}")]
    EmptyRange {
        /// The parameter.
        parameter: String,
        /// Start of the range.
        from: f64,
        /// End of the range.
        to: f64,
    },
    /// Every parameter value of the range has a family of cycles (a structural multiplier at
    /// 1, the paper's walkers with `mu0 = 0`): there is no isolated branch to follow.
    #[error(
        "every cycle for {parameter} in the range belongs to a family (multiplier 1: mu0 = 0 conserves the horizontal momentum); set mu0 > 0 or continue in mu0"
    )]
    FamilyEverywhere {
        /// The parameter.
        parameter: String,
    },
    /// No fixed point was found at any of the seed values.
    #[error("no fixed point found to start from at {parameter} = {tried:?}{}{}", .last.as_ref().map(|e| format!(" (last: {e})")).unwrap_or_default(), seed_tries(.tries))]
    NoSeed {
        /// The parameter.
        parameter: String,
        /// The values tried.
        tried: Vec<f64>,
        /// The last failure of the map, if any.
        #[source]
        last: Option<ProblemError>,
        /// Every try: where, from which guess, and why it failed.
        tries: Vec<SeedTry>,
    },
}

/// One failed try to start a branch: a parameter value and a guess of the problem's.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SeedTry {
    /// The parameter value.
    pub parameter: f64,
    /// Which guess ([`GaitProblem::guesses`]: `warm-up walk`, `start`, ...; empty where the
    /// problem had none).
    pub guess: String,
    /// Why it gave no seed: the map's failure, or `None` where Newton's method did not
    /// converge (or the problem had no such guess there).
    pub failure: Option<String>,
}

/// The tries as a list for the message of [`ContinuationError::NoSeed`].
fn seed_tries(tries: &[SeedTry]) -> String {
    if tries.is_empty() {
        return String::new();
    }
    let each: Vec<String> = tries
        .iter()
        .map(|t| {
            if t.guess.is_empty() {
                return format!(
                    "{}: {}",
                    t.parameter,
                    t.failure.as_deref().unwrap_or("no guess")
                );
            }
            format!(
                "{} from the {} guess: {}",
                t.parameter,
                t.guess,
                t.failure
                    .as_deref()
                    .unwrap_or("Newton's method did not converge")
            )
        })
        .collect();
    format!("; tried {}", each.join("; "))
}

/// The distance in the scaled parameter from a family end at which the last ordinary point
/// is placed.
const FAMILY_APPROACH: f64 = 1e-4;

/// The parameter component of the unit tangent below which its sign is not trusted: on a
/// branch that stands vertical over many points (the passive wheel's family of sliding gaits at
/// one `mu0`, where every speed is a cycle) it is rounding noise, not a fold.
const FOLD_NOISE: f64 = 1e-8;

/// The predictor's distance from the branch (scaled arclength) that the growth of a quickly
/// converged step aims at ([`growth`]): a polyline through the points stays within a quarter
/// of it (the sagitta of a chord is a quarter of the predictor's distance for the same step),
/// 2.5e-4 of the range, well inside a plotted line's width.
const PREDICTOR_TARGET: f64 = 1e-3;

/// The largest distance (scaled arclength) between the predictor and the corrected point of an
/// accepted step: the polyline through the points then stays within a quarter of it, about
/// 9e-3 of the range, of the curve. The largest distance the step control accepted on Figs. 8
/// and 10 before this bound existed was 3.2e-2; without it, faster growth let one step of 0.2
/// cut across the turn of `T_set = 0.4` near `mu0 = 0.14` (a distance of 6e-2).
const MAX_PREDICTOR_DISTANCE: f64 = 3.5e-2;

/// The largest growth of the step after one accepted step.
const MAX_GROWTH: f64 = 4.0;

/// The scaled parameter values tried as seeds, in order.
const SEEDS: [f64; 7] = [0.0, 1.0, 0.5, 0.25, 0.75, 0.125, 0.875];

/// A point of a run with the label found for it (kind and bracket in the parameter).
pub(super) struct Node {
    /// The point.
    pub(super) s: Solved,
    /// Its label.
    pub(super) label: Option<(LabelKind, f64)>,
}

/// Newton's method at fixed `q` from `guess` with the Jacobian refreshed every iteration.
fn seed_at<G: GaitProblem + ?Sized>(
    problem: &G,
    frame: &Frame,
    q: f64,
    guess: Vec<f64>,
    tol: f64,
    direction: f64,
) -> Result<Option<Solved>, ProblemError> {
    let n = guess.len();
    let mut z = DVector::from_fn(n + 1, |i, _| if i < n { guess[i] } else { q });
    let mut normal = DVector::zeros(n + 1);
    normal[n] = 1.0;
    let previous = &normal * direction;
    for _ in 0..6 {
        let r: Vec<f64> = z.rows(0, n).iter().copied().collect();
        let p = frame.p(q);
        let jac = problem.jacobian(&r, p)?;
        let fq = DVector::zeros(n);
        match correct(problem, frame, z.clone(), &normal, &z, &jac, &fq, tol) {
            Ok((zc, value, res, _)) => {
                return complete(problem, frame, zc, value, res, &previous).map(Some);
            }
            Err(CorrectError::Map(e)) => return Err(e),
            Err(CorrectError::NoConvergence) => {
                // One plain Newton step with this Jacobian, then a fresh chord.
                let image = problem.image(&r, p)?;
                let f = DVector::from_fn(n, |i, _| image[i] - r[i]);
                let a = &jac - nalgebra::DMatrix::identity(n, n);
                let Some(mut d) = a.lu().solve(&(-f)) else {
                    return Ok(None);
                };
                if let Some(k) = problem.held_coordinate()
                    && r[k] == 0.0
                    && image[k] == 0.0
                {
                    d[k] = 0.0;
                }
                for i in 0..n {
                    z[i] += d[i];
                }
            }
        }
    }
    Ok(None)
}

/// Follow the branch of period-one fixed points of `problem` for its parameter from `from` to
/// `to`: a seed (a warm-up walk and Newton's method at the first of `from`, `to`, the middle,
/// the quarters, ... where that converges to an isolated cycle), then pseudo-arclength
/// continuation from it towards both ends.
///
/// # Errors
/// Invalid options, an empty range, a range that is a family of cycles throughout, or no
/// seed.
pub fn continuation<G: GaitProblem + ?Sized>(
    problem: &G,
    from: f64,
    to: f64,
    opts: &ContinuationOptions,
) -> Result<Branch, ContinuationError> {
    opts.validate()?;
    let parameter = problem.parameter_name().to_owned();
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
    if SEEDS.iter().all(|&q| problem.has_family_at(frame.p(q))) {
        return Err(ContinuationError::FamilyEverywhere { parameter });
    }
    let mut tried = Vec::new();
    let mut last = None;
    let mut tries = Vec::new();
    for q in SEEDS {
        let p = frame.p(q);
        if problem.has_family_at(p) {
            continue;
        }
        tried.push(p);
        let guesses = problem.guesses(p);
        if guesses.is_empty() {
            tries.push(SeedTry {
                parameter: p,
                guess: String::new(),
                failure: Some(
                    "no guess (the warm-up walk failed before its first step)".to_owned(),
                ),
            });
        }
        let direction = if q < 1.0 { 1.0 } else { -1.0 };
        for (name, guess) in guesses {
            let failure = match seed_at(problem, &frame, q, guess, opts.tol, direction) {
                Ok(Some(seed)) => return Ok(from_seed(problem, &frame, seed, opts, 1)),
                Ok(None) => None,
                Err(e) => {
                    let text = e.to_string();
                    last = Some(e);
                    Some(text)
                }
            };
            tries.push(SeedTry {
                parameter: p,
                guess: name,
                failure,
            });
        }
    }
    Err(ContinuationError::NoSeed {
        parameter,
        tried,
        last,
        tries,
    })
}

/// The branch through the converged point `seed` towards both ends of the range.
pub(super) fn from_seed<G: GaitProblem + ?Sized>(
    problem: &G,
    frame: &Frame,
    seed: Solved,
    opts: &ContinuationOptions,
    period: usize,
) -> Branch {
    let q = seed.q();
    let (forward, end_f) = if q < 1.0 {
        let mut s = seed.clone();
        if s.tangent[s.z.len() - 1] < 0.0 {
            s.tangent = -s.tangent;
        }
        run(problem, frame, s, opts)
    } else {
        (Vec::new(), EndReason::ParameterBound)
    };
    let (backward, end_b) = if q > 0.0 {
        let mut s = seed.clone();
        if s.tangent[s.z.len() - 1] > 0.0 {
            s.tangent = -s.tangent;
        }
        run(problem, frame, s, opts)
    } else {
        (Vec::new(), EndReason::ParameterBound)
    };
    let mut nodes: Vec<Node> = backward.into_iter().skip(1).rev().collect();
    if forward.is_empty() {
        nodes.push(Node {
            s: seed,
            label: None,
        });
    } else {
        nodes.extend(forward);
    }
    assemble(problem, frame, nodes, [end_b, end_f], period)
}

/// Continue from `seed` (its tangent gives the direction) until the end of the range, a
/// failure, or the largest number of points. The first node is the seed.
pub(super) fn run<G: GaitProblem + ?Sized>(
    problem: &G,
    frame: &Frame,
    seed: Solved,
    opts: &ContinuationOptions,
) -> (Vec<Node>, EndReason) {
    let n = seed.z.len() - 1;
    let locator = Locator {
        problem,
        frame: *frame,
        tol: opts.tol,
        locate_tol: opts.locate_tol,
    };
    let mut e_q = DVector::zeros(n + 1);
    e_q[n] = 1.0;
    let mut nodes = vec![Node {
        s: seed,
        label: None,
    }];
    let mut h = opts.initial_step;
    let mut last_error: Option<ProblemError> = None;
    for _ in 0..opts.max_points {
        let Some(a) = nodes.iter().rev().find(|n| n.label.is_none()).map(|n| &n.s) else {
            break;
        };
        let a = a.clone();
        let tq = a.tangent[n];
        // The end of the range ahead (after a fold, the other one).
        let bound = if tq > 0.0 { 1.0 } else { 0.0 };
        let to_bound = if (bound - a.q()) * tq > 0.0 {
            (bound - a.q()) / tq
        } else {
            f64::INFINITY
        };
        let at_bound = to_bound <= h;
        let family_end = at_bound && problem.has_family_at(frame.p(bound));
        // Before a family end, a point at `FAMILY_APPROACH` from it, so that the predictor
        // lands within its square of the branch's own end on the family.
        let approach = family_end && (bound - a.q()).abs() > 1.5 * FAMILY_APPROACH;
        let target = if approach {
            bound - FAMILY_APPROACH * (bound - a.q()).signum()
        } else {
            bound
        };
        let (at_bound, family_end) = (at_bound && !approach, family_end && !approach);
        let step = if at_bound || approach {
            (target - a.q()) / tq
        } else {
            h
        };
        let pred = &a.z + &a.tangent * step;
        let (normal, anchor) = if at_bound || approach {
            let mut anchor = pred.clone();
            anchor[n] = target;
            (e_q.clone(), anchor)
        } else {
            (a.tangent.clone(), pred.clone())
        };
        // On a family of cycles the fixed-`q` problem is singular: the chord matrix of a point
        // off the family converges slowly, so the matrix is taken at the predicted point,
        // whose singular direction the least-norm steps then drop.
        let fresh = if family_end {
            let r: Vec<f64> = anchor.rows(0, n).iter().copied().collect();
            problem.jacobian(&r, frame.p(bound)).ok()
        } else {
            None
        };
        let jac = fresh.as_ref().unwrap_or(&a.jac);
        let corrected = correct(
            problem,
            frame,
            anchor.clone(),
            &normal,
            &anchor,
            jac,
            &a.fq,
            opts.tol,
        )
        .map_err(|e| match e {
            CorrectError::Map(e) => Some(e),
            CorrectError::NoConvergence => None,
        });
        // Too far a miss of the predictor: the polyline through the points would cut the curve.
        // Checked before the point's Jacobian is computed. Also for the steps onto the end of
        // the range or onto the point before a family end, which are as long as the distance
        // left.
        let shortcut = step > 2.0 * opts.min_step && !family_end;
        if shortcut
            && let Ok((z, ..)) = &corrected
            && (z - &pred).norm() > MAX_PREDICTOR_DISTANCE
        {
            h = step / 2.0;
            continue;
        }
        let corrected = corrected.and_then(|(z, value, res, it)| {
            complete(problem, frame, z, value, res, &a.tangent)
                .map(|b| (b, it))
                .map_err(Some)
        });
        let (b, iterations) = match corrected {
            Ok(ok) => ok,
            Err(e) => {
                if e.is_some() {
                    last_error = e;
                }
                h = step / 2.0;
                if h < opts.min_step {
                    return (nodes, end_of(last_error));
                }
                continue;
            }
        };
        // Too sharp a turn, also onto the end of the range.
        let distance = (&b.z - &pred).norm();
        if shortcut && b.tangent.dot(&a.tangent) < 0.9 {
            h = step / 2.0;
            continue;
        }
        last_error = None;
        if b.r().iter().any(|v| v.abs() > opts.max_state) {
            return (nodes, EndReason::StateBound);
        }
        let mut found = detect_between(&locator, &a, &b, family_end, opts);
        nodes.append(&mut found);
        if at_bound {
            let kind = if family_end || near_one(&b) && problem.has_family_at(frame.p(bound)) {
                LabelKind::Family
            } else {
                LabelKind::EndPoint
            };
            nodes.push(Node {
                s: b,
                label: Some((kind, 0.0)),
            });
            let reason = if kind == LabelKind::Family {
                EndReason::Family
            } else {
                EndReason::ParameterBound
            };
            return (nodes, reason);
        }
        if near_one(&b) && b.tangent[n].abs() < FOLD_NOISE {
            // The branch stands vertical on a multiplier at 1: a family of cycles at one
            // parameter value (the passive wheel's sliding gaits of every speed where friction
            // balances the slope on average), not a fold; following it only adds speed.
            nodes.push(Node {
                s: b,
                label: Some((LabelKind::Family, 0.0)),
            });
            return (nodes, EndReason::Family);
        }
        nodes.push(Node { s: b, label: None });
        h = if iterations <= 3 {
            step * growth(distance)
        } else if iterations > 8 {
            step / 2.0
        } else {
            step
        }
        .clamp(opts.min_step, opts.max_step);
    }
    (nodes, EndReason::MaxPoints)
}

/// The factor by which a step that converged in at most three iterations grows: 1.5, or more
/// where the predictor landed well within [`PREDICTOR_TARGET`] of the branch. The predictor's
/// distance from the corrected point grows as the square of the step (the branch's curvature
/// times `step^2 / 2`), so `sqrt(PREDICTOR_TARGET / distance)` is the factor that would bring it
/// to the target; at most [`MAX_GROWTH`]. On the flat ends of Fig. 8's branches (where the foot
/// sticks and each map costs five to seven times more than at small `mu0`) the step reaches the
/// largest step after one point instead of four.
fn growth(distance: f64) -> f64 {
    (PREDICTOR_TARGET / distance.max(f64::MIN_POSITIVE))
        .sqrt()
        .clamp(1.5, MAX_GROWTH)
}

/// Whether a multiplier of `s` is within [`UNIT_MULTIPLIER_TOL`] of 1.
fn near_one(s: &Solved) -> bool {
    detect::multipliers(s)
        .iter()
        .any(|m| (m.re - 1.0).hypot(m.im) < UNIT_MULTIPLIER_TOL)
}

/// The end reason after the step size fell below the minimum.
fn end_of(last: Option<ProblemError>) -> EndReason {
    match last {
        Some(e) => EndReason::map_failed(&e),
        None => EndReason::NoConvergence,
    }
}

/// The special points between the consecutive points `a` and `b`, located, in arclength
/// order. At an end on a family of cycles the fold and branch-point tests are skipped: their
/// zero there is the family's structural multiplier.
fn detect_between<G: GaitProblem + ?Sized>(
    loc: &Locator<'_, G>,
    a: &Solved,
    b: &Solved,
    family_end: bool,
    opts: &ContinuationOptions,
) -> Vec<Node> {
    let span = loc.frame.span.abs();
    let mut found = Vec::new();
    for kind in SIGN_TESTS {
        if family_end && matches!(kind, LabelKind::Fold | LabelKind::BranchPoint) {
            continue;
        }
        let (Some(va), Some(vb)) = (detect::value(kind, a), detect::value(kind, b)) else {
            continue;
        };
        if va * vb >= 0.0 || kind == LabelKind::Fold && va.abs().min(vb.abs()) < FOLD_NOISE {
            continue;
        }
        if kind == LabelKind::NeimarkSacker
            && !(detect::complex_pair_on_circle(a) || detect::complex_pair_on_circle(b))
        {
            continue;
        }
        if let Some((pt, bracket)) = loc.sign_change(kind, a, b) {
            if kind == LabelKind::NeimarkSacker && !detect::complex_pair_on_circle(&pt) {
                continue;
            }
            found.push(Node {
                s: pt,
                label: Some((kind, bracket * span)),
            });
        }
    }
    if detect::structure(&a.value.tests) != detect::structure(&b.value.tests)
        && let Some((pt, bracket)) = loc.structure_change(a, b)
    {
        found.push(Node {
            s: pt,
            label: Some((LabelKind::SlipChange, bracket * span)),
        });
    }
    let (qa, qb) = (a.q(), b.q());
    for &p in &opts.user_points {
        let q = (p - loc.frame.from) / loc.frame.span;
        if q > qa.min(qb)
            && q <= qa.max(qb)
            && let Some(pt) = loc.at_parameter(a, b, q)
        {
            found.push(Node {
                s: pt,
                label: Some((LabelKind::UserPoint, 0.0)),
            });
        }
    }
    found.sort_by(|x, y| (&x.s.z - &a.z).norm().total_cmp(&(&y.s.z - &a.z).norm()));
    found
}

/// The branch of the nodes in order, with numbered labels and `EP` at unlabelled ends.
pub(super) fn assemble<G: GaitProblem + ?Sized>(
    problem: &G,
    frame: &Frame,
    mut nodes: Vec<Node>,
    ends: [EndReason; 2],
    period: usize,
) -> Branch {
    let last = nodes.len().saturating_sub(1);
    for i in [0, last] {
        if let Some(node) = nodes.get_mut(i)
            && node.label.is_none()
        {
            node.label = Some((LabelKind::EndPoint, 0.0));
        }
    }
    let mut number = 0;
    let points = nodes
        .into_iter()
        .map(|node| {
            let label = node.label.map(|(kind, bracket)| {
                number += 1;
                Label {
                    kind,
                    tag: kind.tag(),
                    number,
                    bracket,
                }
            });
            point_of(frame, &node.s, label)
        })
        .collect();
    Branch {
        parameter: problem.parameter_name().to_owned(),
        period,
        points,
        ends,
    }
}

/// The public view of a converged point.
pub(super) fn point_of(frame: &Frame, s: &Solved, label: Option<Label>) -> Point {
    let multipliers = detect::multipliers(s);
    let max = multipliers.iter().map(|m| m.modulus()).fold(0.0, f64::max);
    let stability = if max > 1.0 + UNIT_MULTIPLIER_TOL {
        Stability::Unstable
    } else if max >= 1.0 - UNIT_MULTIPLIER_TOL {
        Stability::Neutral
    } else {
        Stability::Stable
    };
    Point {
        parameter: frame.p(s.q()),
        state: s.r(),
        cycle: s.value.cycle,
        multipliers,
        stability,
        tests: s.value.tests,
        physical: s.value.tests.physical(),
        residual: s.residual,
        label,
    }
}
