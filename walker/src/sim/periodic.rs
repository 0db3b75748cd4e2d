//! The periodic stop of a walk ([`super::WalkLimits::periodic`]): whether the step-to-step
//! changes of the gait descriptors shrink geometrically to within a tolerance.

use super::gait::StepResult;

/// The ratio below which step-to-step changes count as converging ([`super::WalkLimits::periodic`]).
const PERIODIC_RATIO: f64 = 0.9;

/// The largest relative change of `T`, `dx` and `p` from step `a` to step `b`.
fn descriptor_change(a: &StepResult, b: &StepResult) -> f64 {
    let rel = |x: f64, y: f64| ((y - x) / y).abs();
    let p = match (a.p, b.p) {
        (Some(x), Some(y)) if y != 0.0 => rel(x, y),
        _ => 0.0,
    };
    rel(a.period, b.period).max(rel(a.dx, b.dx)).max(p)
}

/// Whether the last steps of `steps` are periodic within `tol` ([`super::WalkLimits::periodic`]):
/// three consecutive changes `d1, d2, d3` shrinking at ratios `r = max(d2/d1, d3/d2) < 0.9`,
/// with the rest of the series, `d3 r / (1 - r)`, at most `tol`.
pub(super) fn is_periodic(steps: &[StepResult], tol: f64) -> bool {
    let [.., s0, s1, s2, s3] = steps else {
        return false;
    };
    let (d1, d2, d3) = (
        descriptor_change(s0, s1),
        descriptor_change(s1, s2),
        descriptor_change(s2, s3),
    );
    if d3 == 0.0 {
        return d2 == 0.0;
    }
    let ratio = (d2 / d1).max(d3 / d2);
    ratio < PERIODIC_RATIO && d3 * ratio / (1.0 - ratio) <= tol
}

#[cfg(test)]
mod tests {
    use super::{StepResult, is_periodic};

    /// Steps whose `T`, `dx` and `p` approach 1 as `1 + d_k`.
    fn steps(d: &[f64]) -> Vec<StepResult> {
        d.iter()
            .map(|&d| StepResult {
                period: 1.0 + d,
                dx: 1.0 + d,
                speed: 1.0,
                p: Some(1.0 + d),
                sr: None,
                q_plus: crate::vector::Vector::zeros(4),
                qd_plus: crate::vector::Vector::zeros(4),
                foot_normal_velocity: 0.0,
                foot_impulse: [0.0; 2],
                rear_impulse: 0.0,
                impact: crate::model::ImpactRegime::Frictionless,
                lambda_min: 0.0,
                stuck_time: 0.0,
                floor: None,
            })
            .collect()
    }

    #[test]
    fn a_geometric_approach_is_periodic_once_its_tail_is_within_the_tolerance() {
        // Deviations 0.5^k: changes of about 0.5^(k+1), ratio 0.5, so the tail is about the
        // last change.
        let d: Vec<f64> = (0..40).map(|k| 0.5_f64.powi(k)).collect();
        let first = (4..=d.len())
            .find(|&n| is_periodic(&steps(&d[..n]), 1e-6))
            .expect("stops");
        // The change from step n-2 to n-1 is about 0.5^(n-1); its tail about the same.
        let last_change = 0.5_f64.powi(first as i32 - 2) - 0.5_f64.powi(first as i32 - 1);
        assert!(last_change <= 1.1e-6 && 2.0 * last_change > 1e-6, "{first}");
        // Exactly repeating steps are periodic.
        assert!(is_periodic(&steps(&[0.0; 4]), 1e-12));
    }

    #[test]
    fn slow_alternating_and_growing_changes_are_never_periodic() {
        // Ratio 0.95 (slow convergence), alternating deviations (period 2), growth.
        for d in [
            (0..60).map(|k| 1e-9 * 0.95_f64.powi(k)).collect::<Vec<_>>(),
            (0..60)
                .map(|k| if k % 2 == 0 { 1e-9 } else { -1e-9 })
                .collect(),
            (0..60).map(|k| 1e-12 * 1.1_f64.powi(k)).collect(),
        ] {
            assert!((4..=d.len()).all(|n| !is_periodic(&steps(&d[..n]), 1e-6)));
        }
    }
}
