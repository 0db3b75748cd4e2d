//! Test functions along a branch and the location of their zeros.
//!
//! Bifurcations, from the multipliers `lambda_i` (eigenvalues of `D_r P`) and the tangent `t`:
//! a fold (`FP`) where the parameter component of the tangent `t_q` changes sign; a branch
//! point (`BP`) where `det [D_r P - I | dP/dq; t^T]` changes sign (it keeps its sign through a
//! fold, which is why the tangent is oriented by continuity); period doubling (`PD`) where
//! `prod (1 + lambda_i)` does; Neimark-Sacker (`NS`) where `prod_{i<j} (lambda_i lambda_j - 1)`
//! does and the pair on the unit circle is complex (a real pair with product 1, a neutral
//! saddle, is not labelled). Boundaries, from the problem's [`Tests`]: lift-off (`LO`), the
//! double-support test (`DS`), the heel strike at `T_set` (`IT`), each where its value changes
//! sign, and a change of the stick-slip structure (`SC`).
//!
//! A zero between two consecutive points `a`, `b` is located on the chord from `a` to `b`: at
//! the distance `s` along it the corrector finds the branch point in the hyperplane normal to
//! the chord, and `s` is found by the Illinois variant of regula falsi on the test value (by
//! bisection on the structure) until the bracket is below the tolerance in arclength.

use nalgebra::DVector;

use crate::poincare::{Multiplier, eigenvalues};

use super::branch::LabelKind;
use super::corrector::{CorrectError, Frame, Solved, bordered, complete, correct};
use super::problem::{GaitProblem, SlipStructure, Tests};

/// The multipliers of a converged point, by decreasing modulus.
pub(super) fn multipliers(s: &Solved) -> Vec<Multiplier> {
    let rows: Vec<Vec<f64>> = (0..s.jac.nrows())
        .map(|i| s.jac.row(i).iter().copied().collect())
        .collect();
    eigenvalues(&rows)
}

/// The real part of `prod f(lambda_i)` over the multipliers, in complex arithmetic.
fn product(ms: &[Multiplier], f: impl Fn(f64, f64) -> (f64, f64)) -> f64 {
    let (mut re, mut im) = (1.0, 0.0);
    for m in ms {
        let (a, b) = f(m.re, m.im);
        (re, im) = (re * a - im * b, re * b + im * a);
    }
    re
}

/// The value of the test function of `kind` at `s` (`None`: the problem has no such test, or
/// the kind is not a sign-change test).
pub(super) fn value(kind: LabelKind, s: &Solved) -> Option<f64> {
    let tests = &s.value.tests;
    match kind {
        LabelKind::Fold => Some(s.tangent[s.z.len() - 1]),
        LabelKind::BranchPoint => Some(bordered(&s.jac, &s.fq, &s.tangent).determinant()),
        LabelKind::PeriodDoubling => Some(product(&multipliers(s), |re, im| (1.0 + re, im))),
        LabelKind::NeimarkSacker => {
            let ms = multipliers(s);
            if ms.len() < 2 {
                return None;
            }
            let mut pairs = Vec::new();
            for i in 0..ms.len() {
                for j in i + 1..ms.len() {
                    let (a, b) = (ms[i], ms[j]);
                    pairs.push(Multiplier {
                        re: a.re * b.re - a.im * b.im,
                        im: a.re * b.im + a.im * b.re,
                    });
                }
            }
            Some(product(&pairs, |re, im| (re - 1.0, im)))
        }
        LabelKind::LiftOff => tests.min_normal_force,
        LabelKind::DoubleSupport => tests.rear_release.map(|v| -v),
        LabelKind::ImpactBeforeTSet => tests.strike_after_t_set,
        _ => None,
    }
}

/// The kinds located by a sign change of [`value`], cheap ones (the map alone) first.
pub(super) const SIGN_TESTS: [LabelKind; 7] = [
    LabelKind::LiftOff,
    LabelKind::DoubleSupport,
    LabelKind::ImpactBeforeTSet,
    LabelKind::Fold,
    LabelKind::BranchPoint,
    LabelKind::PeriodDoubling,
    LabelKind::NeimarkSacker,
];

/// Whether the test of `kind` needs the Jacobian (a full point) at every iterate.
fn needs_jacobian(kind: LabelKind) -> bool {
    matches!(
        kind,
        LabelKind::Fold
            | LabelKind::BranchPoint
            | LabelKind::PeriodDoubling
            | LabelKind::NeimarkSacker
    )
}

/// The structure signature of a point.
pub(super) fn structure(t: &Tests) -> Option<SlipStructure> {
    t.structure
}

/// Whether the pair of multipliers nearest the unit circle at `s` is complex (a genuine
/// Neimark-Sacker point rather than a neutral saddle).
pub(super) fn complex_pair_on_circle(s: &Solved) -> bool {
    multipliers(s)
        .iter()
        .min_by(|a, b| {
            (a.modulus() - 1.0)
                .abs()
                .total_cmp(&(b.modulus() - 1.0).abs())
        })
        .is_some_and(|m| m.im.abs() > 1e-9)
}

/// What the location of a zero between `a` and `b` needs.
pub(super) struct Locator<'a, G: GaitProblem + ?Sized> {
    /// The problem.
    pub(super) problem: &'a G,
    /// The parameter's scaling.
    pub(super) frame: Frame,
    /// The corrector's tolerance on `|F|`.
    pub(super) tol: f64,
    /// The bracket (in scaled arclength) at which the location stops.
    pub(super) locate_tol: f64,
}

impl<G: GaitProblem + ?Sized> Locator<'_, G> {
    /// The point of the branch at distance `s` along the chord `d` (unit) from `a`, with its
    /// Jacobian if `full` (otherwise `a`'s are kept).
    fn at(&self, a: &Solved, d: &DVector<f64>, s: f64, full: bool) -> Option<Solved> {
        let anchor = &a.z + d * s;
        let (z, value, res, _) = correct(
            self.problem,
            &self.frame,
            anchor.clone(),
            d,
            &anchor,
            &a.jac,
            &a.fq,
            self.tol,
        )
        .map_err(|e: CorrectError| e)
        .ok()?;
        if full {
            complete(self.problem, &self.frame, z, value, res, &a.tangent).ok()
        } else {
            Some(Solved {
                z,
                value,
                jac: a.jac.clone(),
                fq: a.fq.clone(),
                tangent: a.tangent.clone(),
                residual: res,
            })
        }
    }

    /// The chord from `a` to `b`: unit direction and length.
    fn chord(a: &Solved, b: &Solved) -> (DVector<f64>, f64) {
        let d = &b.z - &a.z;
        let len = d.norm();
        (d / len.max(f64::MIN_POSITIVE), len)
    }

    /// The zero of the test of `kind` between `a` and `b` (whose values have opposite signs),
    /// as a full point, with the final bracket's width in `q`.
    pub(super) fn sign_change(
        &self,
        kind: LabelKind,
        a: &Solved,
        b: &Solved,
    ) -> Option<(Solved, f64)> {
        let full = needs_jacobian(kind);
        let (d, len) = Self::chord(a, b);
        let (mut s0, mut f0) = (0.0, value(kind, a)?);
        let (mut s1, mut f1) = (len, value(kind, b)?);
        let mut best: Option<Solved> = None;
        for _ in 0..60 {
            if (s1 - s0).abs() <= self.locate_tol {
                break;
            }
            let mut s = (s0 * f1 - s1 * f0) / (f1 - f0);
            let (lo, hi) = (s0.min(s1), s0.max(s1));
            if !(s.is_finite() && s > lo && s < hi) {
                s = 0.5 * (s0 + s1);
            }
            let pt = self.at(a, &d, s, full)?;
            let f = value(kind, &pt)?;
            best = Some(pt);
            if f == 0.0 {
                s0 = s;
                s1 = s;
                break;
            }
            if f * f1 < 0.0 {
                (s0, f0) = (s1, f1);
            } else {
                f0 *= 0.5;
            }
            (s1, f1) = (s, f);
        }
        let bracket = (s1 - s0).abs() * d[d.len() - 1].abs();
        let pt = best?;
        let pt = if full {
            pt
        } else {
            complete(
                self.problem,
                &self.frame,
                pt.z,
                pt.value,
                pt.residual,
                &a.tangent,
            )
            .ok()?
        };
        Some((pt, bracket))
    }

    /// The change of the stick-slip structure between `a` and `b`, by bisection, as a full
    /// point on the far side with the final bracket's width in `q`.
    pub(super) fn structure_change(&self, a: &Solved, b: &Solved) -> Option<(Solved, f64)> {
        let (d, len) = Self::chord(a, b);
        let sa = structure(&a.value.tests);
        let (mut s0, mut s1) = (0.0, len);
        let mut far: Option<Solved> = None;
        // Bisection to a bracket of `locate_tol`, at most 40 halvings of the chord.
        for _ in 0..40 {
            if s1 - s0 <= self.locate_tol {
                break;
            }
            let s = 0.5 * (s0 + s1);
            let pt = self.at(a, &d, s, false)?;
            if structure(&pt.value.tests) == sa {
                s0 = s;
            } else {
                s1 = s;
                far = Some(pt);
            }
        }
        let pt = match far {
            Some(pt) => pt,
            None => self.at(a, &d, s1, false)?,
        };
        let pt = complete(
            self.problem,
            &self.frame,
            pt.z,
            pt.value,
            pt.residual,
            &a.tangent,
        )
        .ok()?;
        Some((pt, (s1 - s0) * d[d.len() - 1].abs()))
    }

    /// The point at the scaled parameter `q` between `a` and `b` (a user point), corrected at
    /// fixed `q` from the chord's interpolation.
    pub(super) fn at_parameter(&self, a: &Solved, b: &Solved, q: f64) -> Option<Solved> {
        let (qa, qb) = (a.q(), b.q());
        let w = (q - qa) / (qb - qa);
        let z0 = &a.z + (&b.z - &a.z) * w;
        let n = z0.len();
        let mut normal = DVector::zeros(n);
        normal[n - 1] = 1.0;
        let (z, value, res, _) = correct(
            self.problem,
            &self.frame,
            z0.clone(),
            &normal,
            &z0,
            &a.jac,
            &a.fq,
            self.tol,
        )
        .ok()?;
        complete(self.problem, &self.frame, z, value, res, &a.tangent).ok()
    }
}
