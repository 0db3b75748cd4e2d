//! Survival statistics of walks that end by a failure or at a step limit (`docs/floors.md`):
//! the Kaplan-Meier survival curve, the mean first-passage time (the mean number of steps
//! before a failure, Byl and Tedrake 2009) as a lower bound and as the estimate of a constant
//! per-step failure rate with its confidence interval, and the failures by kind.

use std::collections::BTreeMap;

use serde::Serialize;

/// The normal quantile of a two-sided 95% interval.
const Z95: f64 = 1.959_963_984_540_054;

/// `-ln(0.05)`: with no failure in `E` step attempts, a per-step failure rate above
/// `-ln(0.05) / E` would have shown one with probability at least 95% (the "rule of three").
const NO_FAILURE_95: f64 = 2.995_732_273_553_991;

/// How one walk of a batch ended.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SurviveOutcome {
    /// The walk's index (its stream of a random floor).
    pub walk: u64,
    /// The steps it completed.
    pub steps: usize,
    /// Its failure's name (the walker's failure kinds, `lift-off`, ...) or `None`: it reached
    /// the step limit (censored).
    pub failure: Option<String>,
}

/// The survival curve at one step count.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SurvivalPoint {
    /// Steps completed.
    pub step: usize,
    /// The Kaplan-Meier estimate of the fraction of walks that complete at least `step` steps.
    pub alive: f64,
    /// Walks that attempted step number `step` (1-based): not failed or censored before.
    pub at_risk: usize,
    /// Walks that failed in that step.
    pub failed: usize,
}

/// An estimate with a 95% confidence interval; `None` for an unbounded end.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Estimate {
    /// The estimate (`None`: infinite).
    pub estimate: Option<f64>,
    /// The interval's lower end.
    pub lo: f64,
    /// The interval's upper end (`None`: unbounded).
    pub hi: Option<f64>,
}

/// The mean first-passage time: the mean number of steps completed before a failure.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Mfpt {
    /// The area under the Kaplan-Meier curve up to the longest walk, the mean of
    /// `min(T, limit)`: a lower bound of the mean first-passage time, equal to it when no walk
    /// is censored.
    pub restricted_mean: f64,
    /// The sample mean of the steps to failure with the normal 95% interval
    /// (`mean +- 1.96 s / sqrt(n)`), when every walk failed (and at least two walked).
    pub sample_mean: Option<Estimate>,
    /// The estimate under a constant per-step failure rate `h` (the geometric law of a
    /// metastable walker, Byl and Tedrake 2009): `h = failures / step attempts` (its maximum
    /// likelihood with censoring), the mean `1/h - 1`, and the 95% interval from the
    /// log-normal interval of `h`, `h exp(+-1.96 / sqrt(failures))`. With no failure, only the
    /// one-sided 95% lower bound `attempts / 3.0 - 1` (`lo`).
    pub exponential: Estimate,
    /// Step attempts of all walks (a failed walk's completed steps plus the one it failed
    /// in, a censored walk's completed steps).
    pub attempts: u64,
}

/// The statistics of a batch of walks.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Survival {
    /// Walks.
    pub walks: usize,
    /// Walks that failed.
    pub failures: usize,
    /// Walks that reached the step limit (censored).
    pub censored: usize,
    /// The Kaplan-Meier curve at step 0 and at every step where a walk failed, and at the
    /// longest walk.
    pub curve: Vec<SurvivalPoint>,
    /// The mean first-passage time.
    pub mfpt: Mfpt,
    /// Failures by kind (name: count), in name order.
    pub failures_by_kind: BTreeMap<String, usize>,
}

/// [`Survival`] without its curve: what `walker mfpt --walks` reports of its Monte Carlo check.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SurvivalSummary<'a> {
    /// Walks.
    pub walks: usize,
    /// Walks that failed.
    pub failures: usize,
    /// Walks that reached the step limit (censored).
    pub censored: usize,
    /// The mean first-passage time.
    pub mfpt: &'a Mfpt,
    /// Failures by kind (name: count), in name order.
    pub failures_by_kind: &'a BTreeMap<String, usize>,
}

impl Survival {
    /// The statistics without the survival curve.
    #[must_use]
    pub fn summary(&self) -> SurvivalSummary<'_> {
        SurvivalSummary {
            walks: self.walks,
            failures: self.failures,
            censored: self.censored,
            mfpt: &self.mfpt,
            failures_by_kind: &self.failures_by_kind,
        }
    }

    /// The failures by kind as text, in name order: each `kind`, `pair`, count, joined by
    /// `between` (`"fall:3 slip:2"` with `(":", " ")`); empty where no walk failed.
    #[must_use]
    pub fn failures_text(&self, pair: &str, between: &str) -> String {
        let kinds: Vec<String> = self
            .failures_by_kind
            .iter()
            .map(|(k, n)| format!("{k}{pair}{n}"))
            .collect();
        kinds.join(between)
    }
}

/// The statistics of `outcomes` (at least one).
#[must_use]
pub fn survival(outcomes: &[SurviveOutcome]) -> Survival {
    let n = outcomes.len();
    let longest = outcomes.iter().map(|o| o.steps).max().unwrap_or(0);
    // Walks failing in step k (1-based: completed k - 1), and censored after k completed.
    let mut died = vec![0usize; longest + 2];
    let mut left = vec![0usize; longest + 2];
    let mut by_kind = BTreeMap::new();
    for o in outcomes {
        match &o.failure {
            Some(kind) => {
                died[o.steps + 1] += 1;
                *by_kind.entry(kind.clone()).or_insert(0) += 1;
            }
            None => left[o.steps] += 1,
        }
    }
    let failures: usize = died.iter().sum();
    let mut curve = vec![SurvivalPoint {
        step: 0,
        alive: 1.0,
        at_risk: n,
        failed: 0,
    }];
    let (mut alive, mut at_risk, mut area) = (1.0, n, 0.0);
    for k in 1..=longest + 1 {
        // Censored after k - 1 completed steps: not at risk in step k.
        at_risk -= left[k - 1];
        if died[k] > 0 {
            alive *= 1.0 - died[k] as f64 / at_risk as f64;
        }
        if k <= longest {
            area += alive;
        }
        if died[k] > 0 || k == longest {
            curve.push(SurvivalPoint {
                step: k,
                alive,
                at_risk,
                failed: died[k],
            });
        }
        at_risk -= died[k];
    }
    let attempts: u64 = outcomes
        .iter()
        .map(|o| o.steps as u64 + u64::from(o.failure.is_some()))
        .sum();
    let sample_mean = (failures == n && n >= 2).then(|| {
        let mean = outcomes.iter().map(|o| o.steps as f64).sum::<f64>() / n as f64;
        let var = outcomes
            .iter()
            .map(|o| (o.steps as f64 - mean).powi(2))
            .sum::<f64>()
            / (n - 1) as f64;
        let half = Z95 * (var / n as f64).sqrt();
        Estimate {
            estimate: Some(mean),
            lo: (mean - half).max(0.0),
            hi: Some(mean + half),
        }
    });
    let exponential = if failures == 0 {
        Estimate {
            estimate: None,
            lo: (attempts as f64 / NO_FAILURE_95 - 1.0).max(0.0),
            hi: None,
        }
    } else {
        let h = failures as f64 / attempts as f64;
        let spread = (Z95 / (failures as f64).sqrt()).exp();
        let mean = |h: f64| (1.0 / h - 1.0).max(0.0);
        Estimate {
            estimate: Some(mean(h)),
            lo: mean((h * spread).min(1.0)),
            hi: Some(mean(h / spread)),
        }
    };
    Survival {
        walks: n,
        failures,
        censored: n - failures,
        curve,
        mfpt: Mfpt {
            restricted_mean: area,
            sample_mean,
            exponential,
            attempts,
        },
        failures_by_kind: by_kind,
    }
}

#[cfg(test)]
mod tests;
