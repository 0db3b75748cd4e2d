//! Ranges of `mu0` for the summary: consecutive points of a sweep with the same outcome merged
//! into one `outcome for mu0 in [a, b]`, so that a sweep reads at a glance.

use walker::sweep::SweepPoint;

/// The runs of consecutive points (neighbours in the sweep's grid) that `label` gives the same
/// label: `(label, first mu0, last mu0)`, in grid order. A point labelled `None` belongs to no
/// run and ends the run before it.
pub fn runs(
    pts: &[SweepPoint],
    label: impl Fn(&SweepPoint) -> Option<String>,
) -> Vec<(String, f64, f64)> {
    let mut out: Vec<(String, f64, f64)> = Vec::new();
    let mut open = false;
    for p in pts {
        match label(p) {
            Some(l) => match out.last_mut() {
                Some(last) if open && last.0 == l => last.2 = p.value,
                _ => {
                    out.push((l, p.value, p.value));
                    open = true;
                }
            },
            None => open = false,
        }
    }
    out
}

/// `mu0 in [a, b]` with two decimals, or `mu0 = a` for a single point.
#[must_use]
pub fn interval(a: f64, b: f64) -> String {
    if a == b {
        format!("mu0 = {a:.2}")
    } else {
        format!("mu0 in [{a:.2}, {b:.2}]")
    }
}

/// The runs of [`runs`] as `label for mu0 in [a, b]`, joined by `; `, or `none`.
#[must_use]
pub fn describe(pts: &[SweepPoint], label: impl Fn(&SweepPoint) -> Option<String>) -> String {
    let parts: Vec<String> = runs(pts, label)
        .iter()
        .map(|(l, a, b)| format!("{l} for {}", interval(*a, *b)))
        .collect();
    if parts.is_empty() {
        "none".to_owned()
    } else {
        parts.join("; ")
    }
}

/// The label of a point's failure (its name), `None` if it walked.
#[must_use]
pub fn failure(p: &SweepPoint) -> Option<String> {
    p.failure.as_ref().map(|f| f.name().to_owned())
}

#[cfg(test)]
mod tests {
    use super::{describe, failure, interval, runs};
    use walker::sim::{Failure, FailureKind};
    use walker::sweep::SweepPoint;

    fn point(mu0: f64, failed: bool) -> SweepPoint {
        SweepPoint {
            value: mu0,
            steps: 0,
            last: None,
            previous: None,
            failure: failed.then(|| FailureKind::NoImpact.at(0, 0.0, [0.0; 8].into())),
            periodic: false,
        }
    }

    #[test]
    fn consecutive_failures_merge_and_a_walking_point_splits_them() {
        let pts: Vec<SweepPoint> = [true, true, true, false, true]
            .iter()
            .enumerate()
            .map(|(k, &f)| point(0.01 * k as f64, f))
            .collect();
        let r = runs(&pts, failure);
        assert_eq!(r.len(), 2, "{r:?}");
        assert_eq!((r[0].1, r[0].2), (0.0, 0.02));
        assert_eq!((r[1].1, r[1].2), (0.04, 0.04));
        assert_eq!(
            describe(&pts, failure),
            "no-impact for mu0 in [0.00, 0.02]; no-impact for mu0 = 0.04"
        );
    }

    #[test]
    fn no_labelled_point_is_none_and_different_labels_are_different_runs() {
        let pts: Vec<SweepPoint> = (0..3).map(|k| point(0.1 * k as f64, false)).collect();
        assert_eq!(describe(&pts, failure), "none");
        let by_parity = |p: &SweepPoint| Some(format!("{}", (p.value * 10.0).round() as i32 % 2));
        assert_eq!(runs(&pts, by_parity).len(), 3);
        assert_eq!(interval(0.1, 0.45), "mu0 in [0.10, 0.45]");
    }

    /// `Failure` is the library's type: the label is its CLI name.
    #[test]
    fn the_failure_label_is_the_failure_name() {
        let f: Failure = FailureKind::NoImpact.at(0, 0.0, [0.0; 8].into());
        assert_eq!(failure(&point(0.0, true)).as_deref(), Some(f.name()));
    }
}
