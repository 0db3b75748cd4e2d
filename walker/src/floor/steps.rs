//! The values of one quantity (friction or slope) at each step of one walk on a floor
//! ([`FloorSteps`]): a floor file's description ([`FloorSpec`]) turned into `x_0, x_1, ...`.

use walker_scene::{Distribution, FloorSpec};

use super::draw::StepDraws;

/// The most rejections a truncated-normal draw makes before it takes the interval's point
/// nearest the mean: a floor file's interval holds at least 1% of the normal's mass
/// ([`walker_scene::floor::MIN_TRUNCATED_MASS`]), so all of them are rejected with
/// probability below `0.99^10000 = 2e-44`.
const MAX_TRIES: usize = 10_000;

/// The friction coefficients of the steps of walk `walk` on a floor, in order: step `k`'s
/// value is a pure function of (the floor, `walk`, `k`). A `uniform` or `steps` floor gives
/// every walk the same values; a random floor draws step `k` of walk `walk` from the stream
/// of (seed, walk) at step `k` (`super::draw`), the Markov chain's state carried from step
/// to step.
#[derive(Clone, Debug)]
pub struct FloorSteps<'f> {
    spec: &'f FloorSpec,
    walk: u64,
    step: u64,
    /// The Markov chain's state at the last step (true: icy).
    icy: bool,
    /// The lane of each step's draws (0: `mu0`, 1: `phi`; `super::draw::StepDraws::in_lane`).
    lane: u8,
}

impl<'f> FloorSteps<'f> {
    /// The steps of walk `walk` on `spec`, from step 0.
    #[must_use]
    pub fn new(spec: &'f FloorSpec, walk: u64) -> FloorSteps<'f> {
        FloorSteps::in_lane(spec, walk, 0)
    }

    /// The steps of walk `walk` on `spec` drawing in lane `lane` of each step's random numbers
    /// (0 for a floor's `mu0`, 1 for its `phi`: the two are independent).
    #[must_use]
    pub fn in_lane(spec: &'f FloorSpec, walk: u64, lane: u8) -> FloorSteps<'f> {
        FloorSteps {
            spec,
            walk,
            step: 0,
            icy: false,
            lane,
        }
    }
}

impl Iterator for FloorSteps<'_> {
    type Item = f64;

    fn next(&mut self) -> Option<f64> {
        let k = self.step;
        self.step += 1;
        Some(match self.spec {
            // A floor of patches gives `mu0` by position, not by step (the walker asks its
            // patches, `super::patches`): per step, its value outside the patches.
            FloorSpec::Uniform { mu0 } | FloorSpec::Patches { mu0, .. } => *mu0,
            FloorSpec::Steps { mu0 } => {
                let i = usize::try_from(k).unwrap_or(usize::MAX).min(mu0.len() - 1);
                mu0[i]
            }
            FloorSpec::Random { seed, mu0 } => {
                let mut draws = StepDraws::in_lane(*seed, self.walk, k, self.lane);
                match *mu0 {
                    Distribution::Uniform { lo, hi } => {
                        // lo + (hi - lo) u rounds to hi for u near 1 in rare cases: keep [lo, hi).
                        let x = lo + (hi - lo) * draws.uniform();
                        if x < hi { x } else { lo }
                    }
                    Distribution::TruncatedNormal { mean, sd, lo, hi } => (0..MAX_TRIES)
                        .map(|_| mean + sd * draws.normal())
                        .find(|x| (lo..=hi).contains(x))
                        .unwrap_or(mean.clamp(lo, hi)),
                    Distribution::Markov {
                        dry,
                        icy,
                        dry_length,
                        icy_length,
                    } => {
                        let u = draws.uniform();
                        self.icy = if k == 0 {
                            // The stationary distribution: icy with probability
                            // icy_length / (dry_length + icy_length).
                            u < icy_length / (dry_length + icy_length)
                        } else {
                            // A patch of mean length L ends after each step with probability
                            // 1 / L (its length is geometric).
                            let leave = 1.0 / if self.icy { icy_length } else { dry_length };
                            self.icy != (u < leave)
                        };
                        if self.icy { icy } else { dry }
                    }
                }
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use walker_scene::{Distribution, FloorSpec};

    use super::FloorSteps;

    #[test]
    fn a_slope_draws_in_a_lane_of_its_own_that_shares_no_number_with_the_friction() {
        // A truncated normal uses a varying number of words per step: lane 1 starting in the
        // middle of each step's block keeps the two apart, and lane 0 is the friction's
        // stream as it was before slopes existed.
        let spec = FloorSpec::Random {
            seed: 3,
            mu0: Distribution::TruncatedNormal {
                mean: 0.3,
                sd: 0.2,
                lo: 0.1,
                hi: 0.5,
            },
        };
        let friction: Vec<f64> = FloorSteps::new(&spec, 2).take(200).collect();
        let lane0: Vec<f64> = FloorSteps::in_lane(&spec, 2, 0).take(200).collect();
        let lane1: Vec<f64> = FloorSteps::in_lane(&spec, 2, 1).take(200).collect();
        assert_eq!(friction, lane0);
        assert!(lane1.iter().all(|x| !friction.contains(x)));
        assert!(lane1.iter().all(|x| (0.1..=0.5).contains(x)));
    }
}
