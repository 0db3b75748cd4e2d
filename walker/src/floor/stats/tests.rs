//! The survival statistics against hand-computed cases.

use super::{SurviveOutcome, survival};

fn failed(walk: u64, steps: usize) -> SurviveOutcome {
    SurviveOutcome {
        walk,
        steps,
        failure: Some("lift-off".to_owned()),
    }
}

fn censored(walk: u64, steps: usize) -> SurviveOutcome {
    SurviveOutcome {
        walk,
        steps,
        failure: None,
    }
}

#[test]
fn without_censoring_the_curve_is_the_empirical_survival_and_the_mean_exact() {
    // Steps to failure 0, 2, 2, 4: alive after 1 step 3/4, after 3 steps 1/4, after 5 none.
    let s = survival(&[failed(0, 0), failed(1, 2), failed(2, 2), failed(3, 4)]);
    let curve: Vec<(usize, f64)> = s.curve.iter().map(|p| (p.step, p.alive)).collect();
    assert_eq!(
        curve,
        vec![(0, 1.0), (1, 0.75), (3, 0.25), (4, 0.25), (5, 0.0)]
    );
    // The mean of min(T, 4) = (0 + 2 + 2 + 4) / 4 = 2, the sample mean too.
    assert_eq!(s.mfpt.restricted_mean, 2.0);
    let mean = s.mfpt.sample_mean.expect("all failed");
    assert_eq!(mean.estimate, Some(2.0));
    // s^2 = (4 + 0 + 0 + 4) / 3, half width 1.96 sqrt(s^2 / 4).
    let half = 1.959_963_984_540_054 * (8.0_f64 / 3.0 / 4.0).sqrt();
    assert!((mean.hi.expect("bounded") - (2.0 + half)).abs() < 1e-12);
    assert_eq!(s.failures_by_kind.get("lift-off"), Some(&4));
    // Attempts: 1 + 3 + 3 + 5 = 12, h = 4 / 12, mean 1/h - 1 = 2.
    assert_eq!(s.mfpt.attempts, 12);
    assert!((s.mfpt.exponential.estimate.expect("finite") - 2.0).abs() < 1e-12);
}

#[test]
fn censored_walks_leave_the_risk_set_without_a_drop_of_the_curve() {
    // Two walks reach the limit of 3 steps, one fails in its second step: the Kaplan-Meier
    // curve drops to 2/3 after step 2 and stays there; the restricted mean 1 + 2/3 + 2/3.
    let s = survival(&[censored(0, 3), failed(1, 1), censored(2, 3)]);
    let curve: Vec<(usize, f64, usize)> = s
        .curve
        .iter()
        .map(|p| (p.step, p.alive, p.at_risk))
        .collect();
    // The product-limit factor 1 - 1/3, as the estimator computes it.
    let two_thirds = 1.0 - 1.0 / 3.0;
    assert_eq!(
        curve,
        vec![(0, 1.0, 3), (2, two_thirds, 3), (3, two_thirds, 2)]
    );
    assert!((s.mfpt.restricted_mean - (1.0 + 4.0 / 3.0)).abs() < 1e-15);
    assert_eq!(s.mfpt.sample_mean, None);
    assert_eq!((s.failures, s.censored, s.mfpt.attempts), (1, 2, 8));
    // One failure in 8 attempts: mean 7, interval h exp(+-1.96) around 1/8.
    let e = s.mfpt.exponential;
    assert_eq!(e.estimate, Some(7.0));
    assert!(e.lo < 7.0 && e.hi.expect("bounded") > 7.0);
}

#[test]
fn with_no_failure_only_a_lower_bound_is_known() {
    let s = survival(&[censored(0, 100), censored(1, 100)]);
    assert_eq!(s.failures, 0);
    assert_eq!(s.curve.last().map(|p| p.alive), Some(1.0));
    assert_eq!(s.mfpt.restricted_mean, 100.0);
    let e = s.mfpt.exponential;
    assert_eq!((e.estimate, e.hi), (None, None));
    // 200 attempts without a failure: h < 3.0 / 200 at 95%, so the mean > 200 / 3.0 - 1.
    assert!((e.lo - (200.0 / 2.995_732_273_553_991 - 1.0)).abs() < 1e-12);
}
