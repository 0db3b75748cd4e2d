//! Detection and location of folds, period doubling and Neimark-Sacker points on constructed
//! maps whose bifurcations are known in closed form, exposed through the same
//! [`GaitProblem`] trait as the walkers.
//!
//! The quadratic map `r -> r + p - r^2` has the fixed points `r = +-sqrt(p)` with multiplier
//! `1 - 2 r`: a fold at `(p, r) = (0, 0)` and a period doubling at `(1, 1)`. With
//! `x = r - 1/2` it is the quadratic family `x -> c - x^2`, `c = p - 1/4`, whose period-two
//! cycle `x^2 - x + 1 - c = 0` gives `r = 1 +- sqrt(p - 1)` for `p > 1`, born at the period
//! doubling, and whose period-four cycle appears at `c = 5/4` (`p = 3/2`; Strogatz, *Nonlinear
//! dynamics and chaos*, Section 10.3). The planar map `z -> (1 + p) e^{i w} z - |z|^2 z` has
//! the fixed point 0 with multipliers `(1 + p) e^{+-i w}`: a Neimark-Sacker point at `p = 0`.
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use nalgebra::DMatrix;
use walker::continuation::{
    ContinuationOptions, Cycle, EndReason, GaitProblem, LabelKind, MapValue, ProblemError, Tests,
    continuation, period_two,
};

/// `r -> r + p - r^2`.
struct Quadratic;

fn value(image: Vec<f64>) -> MapValue {
    MapValue {
        cycle: Cycle {
            period: 1.0,
            dx: image[0],
            speed: image[0],
        },
        image,
        tests: Tests::default(),
    }
}

impl GaitProblem for Quadratic {
    fn dim(&self) -> usize {
        1
    }
    fn parameter_name(&self) -> &str {
        "p"
    }
    fn map(&self, r: &[f64], p: f64) -> Result<MapValue, ProblemError> {
        Ok(value(vec![r[0] + p - r[0] * r[0]]))
    }
    fn jacobian(&self, r: &[f64], _p: f64) -> Result<DMatrix<f64>, ProblemError> {
        Ok(DMatrix::from_element(1, 1, 1.0 - 2.0 * r[0]))
    }
    fn guess(&self, p: f64) -> Option<Vec<f64>> {
        (p > 0.0).then(|| vec![p.sqrt() * 1.01])
    }
}

/// `z -> (1 + p) e^{i w} z - |z|^2 z` in real coordinates, `w = 1`.
struct Rotation;

impl GaitProblem for Rotation {
    fn dim(&self) -> usize {
        2
    }
    fn parameter_name(&self) -> &str {
        "p"
    }
    fn map(&self, r: &[f64], p: f64) -> Result<MapValue, ProblemError> {
        let (s, c) = 1f64.sin_cos();
        let k = 1.0 + p;
        let n2 = r[0] * r[0] + r[1] * r[1];
        Ok(value(vec![
            k * (c * r[0] - s * r[1]) - n2 * r[0],
            k * (s * r[0] + c * r[1]) - n2 * r[1],
        ]))
    }
    fn jacobian(&self, r: &[f64], p: f64) -> Result<DMatrix<f64>, ProblemError> {
        let (s, c) = 1f64.sin_cos();
        let k = 1.0 + p;
        let n2 = r[0] * r[0] + r[1] * r[1];
        Ok(DMatrix::from_row_slice(
            2,
            2,
            &[
                k * c - n2 - 2.0 * r[0] * r[0],
                -k * s - 2.0 * r[0] * r[1],
                k * s - 2.0 * r[0] * r[1],
                k * c - n2 - 2.0 * r[1] * r[1],
            ],
        ))
    }
    fn guess(&self, _p: f64) -> Option<Vec<f64>> {
        Some(vec![1e-3, -1e-3])
    }
}

/// Location tolerance: special points are located to a bracket of `1e-9` in the scaled
/// arclength ([`ContinuationOptions::default`]); on these branches the parameter and the state
/// move at most as fast as the arclength, so both are placed to `1e-9`, and `1e-8` leaves a
/// factor 10 for the corrector's residual (`1e-11`) amplified by `1 / |1 - multiplier|`.
const LOCATED: f64 = 1e-8;

#[test]
fn the_quadratic_map_folds_at_zero_and_doubles_its_period_at_one() {
    let b = continuation(&Quadratic, -0.5, 2.0, &ContinuationOptions::default()).unwrap();
    let folds: Vec<_> = b.labelled(LabelKind::Fold).collect();
    assert_eq!(folds.len(), 1, "{:?}", b.special().collect::<Vec<_>>());
    assert!(folds[0].parameter.abs() < LOCATED, "{}", folds[0].parameter);
    assert!(folds[0].state[0].abs() < LOCATED, "{:?}", folds[0].state);
    let pds: Vec<_> = b.labelled(LabelKind::PeriodDoubling).collect();
    assert_eq!(pds.len(), 1);
    assert!((pds[0].parameter - 1.0).abs() < LOCATED);
    assert!((pds[0].state[0] - 1.0).abs() < LOCATED);
    assert!((pds[0].multipliers[0].re + 1.0).abs() < 2.0 * LOCATED);
    // Both halves of the branch reach the end of the range at p = 2: r = sqrt(2) and -sqrt(2).
    assert_eq!(
        b.ends,
        [EndReason::ParameterBound, EndReason::ParameterBound]
    );
    let (first, last) = (&b.points[0], &b.points[b.points.len() - 1]);
    assert!((first.parameter - 2.0).abs() < 1e-12 && (last.parameter - 2.0).abs() < 1e-12);
    let mut ends = [first.state[0], last.state[0]];
    ends.sort_by(f64::total_cmp);
    assert!((ends[0] + 2f64.sqrt()).abs() < 1e-10 && (ends[1] - 2f64.sqrt()).abs() < 1e-10);
    // Every point is a fixed point: r^2 = p.
    for pt in &b.points {
        assert!(
            (pt.state[0] * pt.state[0] - pt.parameter).abs() < 1e-10,
            "{pt:?}"
        );
    }
}

#[test]
fn the_period_two_branch_born_at_the_period_doubling_is_one_plus_minus_sqrt_p_minus_one() {
    let b = continuation(&Quadratic, 0.5, 1.4, &ContinuationOptions::default()).unwrap();
    let pd = b
        .labelled(LabelKind::PeriodDoubling)
        .next()
        .unwrap()
        .clone();
    let two = period_two(&Quadratic, &pd, 0.5, 1.4, &ContinuationOptions::default()).unwrap();
    assert_eq!(two.period, 2);
    assert_eq!(two.points[0].label.unwrap().kind, LabelKind::PeriodDoubling);
    assert_eq!(two.ends[1], EndReason::ParameterBound);
    assert!((two.points[two.points.len() - 1].parameter - 1.4).abs() < 1e-12);
    for pt in &two.points[1..] {
        // On the branch p = 1 + (r - 1)^2. Compared in p, which the fixed-point equation
        // `F = P(P(r)) - r` determines well: dF/dp = 2 - 2 P(r) = 2 (r - 1) + O((r - 1)^2),
        // so the corrector's residual (at most 1e-11) leaves p off by 1e-11 / (2 |r - 1|);
        // twice that is allowed. (In r at fixed p the error would be amplified by
        // 1 / (1 - multiplier), unbounded at the period doubling.)
        let e = pt.state[0] - 1.0;
        let err = pt.parameter - 1.0 - e * e;
        assert!(err.abs() < 1e-11 / e.abs(), "{pt:?}: {err}");
        assert!(pt.residual <= 1e-11);
        // Not a fixed point of the map itself: r != sqrt(p).
        assert!((pt.state[0] - pt.parameter.sqrt()).abs() > 1e-4);
    }
    // The period-two cycle is stable from its birth to the next doubling at p = 3/2.
    assert!(
        two.points[1..]
            .iter()
            .all(|p| p.multipliers[0].modulus() < 1.0)
    );
}

#[test]
fn a_rotating_fixed_point_loses_stability_in_a_neimark_sacker_point_at_zero() {
    let b = continuation(&Rotation, -0.5, 0.5, &ContinuationOptions::default()).unwrap();
    let ns: Vec<_> = b.labelled(LabelKind::NeimarkSacker).collect();
    assert_eq!(ns.len(), 1, "{:?}", b.special().collect::<Vec<_>>());
    assert!(ns[0].parameter.abs() < LOCATED, "{}", ns[0].parameter);
    assert!((ns[0].multipliers[0].modulus() - 1.0).abs() < LOCATED);
    // The multipliers there are e^{+-i}: the pair is complex, not a neutral saddle.
    assert!((ns[0].multipliers[0].im.abs() - 1f64.sin()).abs() < 1e-7);
    // Nothing else is special on the straight branch z = 0 besides its ends.
    assert_eq!(b.special().count(), 3);
}
