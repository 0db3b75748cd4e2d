//! The floor's per-step `mu0` as the chain sees it ([`FloorSamples`]): a finite set of values
//! with their probabilities, and, for a Markov floor, the chain's state (dry or icy) that joins
//! the mesh state.
//!
//! An independent floor (uniform, truncated normal) is replaced by `M` values at the midpoints
//! of `M` intervals of equal probability (the quantiles `(j + 1/2) / M`), each of weight `1/M`:
//! the midpoint rule in probability, whose error in an expectation of a smooth function of
//! `mu0` falls as `1/M^2`. A Markov floor has its two values exactly: the chain's state after
//! a step is the floor state of that step, and the next step's value is drawn from the row of
//! the previous state (a patch of mean length `L` ends with probability `1/L`).

use walker_scene::{Distribution, FloorSpec};

/// The per-step floor of the chain: `values[j]` with probability `prob[s][j]` after a step
/// whose floor left the chain's floor state `s`; a step on value `j` leaves the floor state
/// `next[j]`.
#[derive(Clone, Debug, PartialEq)]
pub struct FloorSamples {
    /// The values of `mu0`.
    pub values: Vec<f64>,
    /// `prob[s][j]`: the probability of value `j` after floor state `s` (each row sums to 1).
    pub prob: Vec<Vec<f64>>,
    /// The floor state a step on value `j` leaves.
    pub next: Vec<usize>,
    /// The distribution of the floor state before the first step (the stationary one).
    pub start: Vec<f64>,
    /// Names of the floor states (`["any"]` for an independent floor, `["dry", "icy"]`).
    pub states: Vec<String>,
}

impl FloorSamples {
    /// The samples of `spec` with `m` values for an independent distribution (a Markov floor
    /// has its two; a uniform floor its one), or `None` for a `steps` floor, whose values are
    /// no per-step distribution.
    #[must_use]
    pub fn of(spec: &FloorSpec, m: usize) -> Option<FloorSamples> {
        let m = m.max(1);
        let independent = |values: Vec<f64>| {
            let w = 1.0 / values.len() as f64;
            FloorSamples {
                prob: vec![vec![w; values.len()]],
                next: vec![0; values.len()],
                values,
                start: vec![1.0],
                states: vec!["any".to_owned()],
            }
        };
        match spec {
            FloorSpec::Steps { .. } | FloorSpec::Patches { .. } => None,
            FloorSpec::Uniform { mu0 } => Some(independent(vec![*mu0])),
            FloorSpec::Random { mu0, .. } => Some(match *mu0 {
                Distribution::Uniform { lo, hi } => independent(
                    (0..m)
                        .map(|j| lo + (hi - lo) * (j as f64 + 0.5) / m as f64)
                        .collect(),
                ),
                Distribution::TruncatedNormal { mean, sd, lo, hi } => {
                    let cdf =
                        |x: f64| 0.5 * libm::erfc(-(x - mean) / (sd * std::f64::consts::SQRT_2));
                    let (a, b) = (cdf(lo), cdf(hi));
                    independent(
                        (0..m)
                            .map(|j| {
                                let p = a + (b - a) * (j as f64 + 0.5) / m as f64;
                                bisect(&cdf, p, lo, hi)
                            })
                            .collect(),
                    )
                }
                Distribution::Markov {
                    dry,
                    icy,
                    dry_length,
                    icy_length,
                } => {
                    let (leave_dry, leave_icy) = (1.0 / dry_length, 1.0 / icy_length);
                    let icy_share = icy_length / (dry_length + icy_length);
                    FloorSamples {
                        values: vec![dry, icy],
                        prob: vec![
                            vec![1.0 - leave_dry, leave_dry],
                            vec![leave_icy, 1.0 - leave_icy],
                        ],
                        next: vec![0, 1],
                        start: vec![1.0 - icy_share, icy_share],
                        states: vec!["dry".to_owned(), "icy".to_owned()],
                    }
                }
            }),
        }
    }

    /// The same samples with one floor state per value (`next[j] = j`, every state followed
    /// by the values' own law), as the chain carries a slope: the step after a step on
    /// sample `j` needs to know `j`. A Markov floor's states are its values already, and a
    /// single value is one state: both are returned as they are. The states are named by
    /// the value's index (`[0]`, `[1]`, ...) for an independent floor.
    #[must_use]
    pub fn by_value(self) -> FloorSamples {
        if self.floor_states() != 1 || self.values.len() == 1 {
            return self;
        }
        let n = self.values.len();
        let law = self.prob[0].clone();
        FloorSamples {
            prob: vec![law.clone(); n],
            next: (0..n).collect(),
            start: law,
            states: (0..n).map(|j| format!("[{j}]")).collect(),
            values: self.values,
        }
    }

    /// The number of floor states the mesh state carries.
    #[must_use]
    pub fn floor_states(&self) -> usize {
        self.start.len()
    }

    /// The value the gait's fixed point is found at: the middle sample of an independent
    /// floor, the more frequent state's of a Markov floor.
    #[must_use]
    pub fn central(&self) -> f64 {
        if self.floor_states() == 1 {
            self.values[self.values.len() / 2]
        } else {
            let s = usize::from(self.start[1] > self.start[0]);
            self.values[s]
        }
    }
}

/// The `x` in `[lo, hi]` with `cdf(x) = p` for an increasing `cdf`, by bisection to the last
/// bit (at most 200 halvings).
fn bisect(cdf: &dyn Fn(f64) -> f64, p: f64, lo: f64, hi: f64) -> f64 {
    let (mut a, mut b) = (lo, hi);
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        if cdf(m) < p {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

#[cfg(test)]
mod tests {
    use super::FloorSamples;
    use walker_scene::{Distribution, FloorSpec};

    fn random(mu0: Distribution) -> FloorSpec {
        FloorSpec::Random { seed: 1, mu0 }
    }

    #[test]
    fn a_uniform_floor_is_sampled_at_the_midpoints_of_equal_intervals() {
        let s = FloorSamples::of(&random(Distribution::Uniform { lo: 0.1, hi: 0.5 }), 4)
            .expect("random");
        let want = [0.15, 0.25, 0.35, 0.45];
        for (v, w) in s.values.iter().zip(want) {
            assert!((v - w).abs() < 1e-15, "{v} vs {w}");
        }
        assert_eq!(s.prob, vec![vec![0.25; 4]]);
    }

    #[test]
    fn a_truncated_normal_is_sampled_at_its_quantiles() {
        // The symmetric truncation of a normal: its samples are symmetric about the mean, and
        // the middle of an odd number of them is the mean (to the bisection's last bits).
        let d = Distribution::TruncatedNormal {
            mean: 0.3,
            sd: 0.1,
            lo: 0.1,
            hi: 0.5,
        };
        let s = FloorSamples::of(&random(d), 5).expect("random");
        assert!((s.values[2] - 0.3).abs() < 1e-12, "{:?}", s.values);
        assert!(
            (s.values[0] + s.values[4] - 0.6).abs() < 1e-12,
            "{:?}",
            s.values
        );
        // The first sample is the 10% quantile of the truncated law: inside (lo, mean).
        assert!(s.values[0] > 0.1 && s.values[0] < s.values[1]);
    }

    #[test]
    fn a_markov_floor_keeps_its_two_states_and_their_chain() {
        let d = Distribution::Markov {
            dry: 0.4,
            icy: 0.05,
            dry_length: 20.0,
            icy_length: 2.0,
        };
        let s = FloorSamples::of(&random(d), 16).expect("random");
        assert_eq!(s.values, vec![0.4, 0.05]);
        assert_eq!(s.prob, vec![vec![0.95, 0.05], vec![0.5, 0.5]]);
        // Stationary: pi P = pi.
        let pi = &s.start;
        for j in 0..2 {
            let x: f64 = (0..2).map(|i| pi[i] * s.prob[i][j]).sum();
            assert!((x - pi[j]).abs() < 1e-15);
        }
        assert_eq!(s.central(), 0.4);
        assert!(FloorSamples::of(&FloorSpec::Steps { mu0: vec![0.4] }, 4).is_none());
    }
}
