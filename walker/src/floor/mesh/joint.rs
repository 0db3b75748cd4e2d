//! The floor of the chain when it sets the slope too ([`JointFloor`]): the friction's samples
//! and the slope's, and the slope of the step before carried in the chain's floor state.
//!
//! A step's Poincare section depends on the slope the strike before it landed on (the rimless
//! wheel's `th = phi - alpha/2`; the compass gait's `th_sw = 2 phi - th_st`), and whether a
//! step can start at all depends on it too (a sliding foot meeting another slope is a
//! [`crate::sim::FailureKind::SlopeKink`]). So on a floor that sets `phi` the chain's floor
//! state carries the index of the slope sample the previous step walked on: the slope's
//! samples are a finite quadrature set, and the transition from `(r, j)` under the sample `k`
//! lands on `(r', k)`. An independent distribution of `phi` (uniform, truncated normal) thus
//! has `M` floor states, one per sample, each followed by every sample with weight `1/M`; a
//! Markov floor's two states are its two values already.
//!
//! The floor's states and values are the products of the friction's ([`FloorSamples`]: one
//! state for an independent `mu0`, two for a Markov one) and the slope's, the friction's index
//! first. A floor of friction only is the product with the trivial slope (one state, one value,
//! probability 1): multiplying by 1 is exact, so its chain is the friction's, bit for bit.

use super::samples::FloorSamples;

/// The per-step floor of the chain on a floor of friction, slope, or both.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct JointFloor {
    /// The friction's samples (`None`: the floor sets no `mu0`).
    mu0: Option<FloorSamples>,
    /// The slope's samples, one floor state per value (`None`: the floor sets no `phi`).
    phi: Option<FloorSamples>,
    /// The index of the slope's central sample (0 without a slope).
    phi_central: usize,
}

/// The trivial part of a floor that does not set a quantity: one state, one value (unused).
fn trivial() -> FloorSamples {
    FloorSamples {
        values: vec![f64::NAN],
        prob: vec![vec![1.0]],
        next: vec![0],
        start: vec![1.0],
        states: vec!["any".to_owned()],
    }
}

impl JointFloor {
    /// The floor of the friction's samples `mu0` and the slope's `phi` (as
    /// [`FloorSamples::of`] gives them; given one floor state per value here).
    #[must_use]
    pub fn new(mu0: Option<FloorSamples>, phi: Option<FloorSamples>) -> JointFloor {
        let phi_central = phi.as_ref().map_or(0, |p| {
            let c = p.central();
            p.values
                .iter()
                .position(|v| v.to_bits() == c.to_bits())
                .unwrap_or(0)
        });
        JointFloor {
            mu0,
            phi: phi.map(FloorSamples::by_value),
            phi_central,
        }
    }

    /// The friction's values (`None`: the floor sets no `mu0`).
    #[must_use]
    pub fn mu0_values(&self) -> Option<&[f64]> {
        self.mu0.as_ref().map(|p| p.values.as_slice())
    }

    /// The slope's values (`None`: the floor sets no `phi`).
    #[must_use]
    pub fn phi_values(&self) -> Option<&[f64]> {
        self.phi.as_ref().map(|p| p.values.as_slice())
    }

    /// The friction's part, or the trivial one.
    fn mu0_part(&self) -> std::borrow::Cow<'_, FloorSamples> {
        self.mu0.as_ref().map_or_else(
            || std::borrow::Cow::Owned(trivial()),
            std::borrow::Cow::Borrowed,
        )
    }

    /// The slope's part, or the trivial one.
    fn phi_part(&self) -> std::borrow::Cow<'_, FloorSamples> {
        self.phi.as_ref().map_or_else(
            || std::borrow::Cow::Owned(trivial()),
            std::borrow::Cow::Borrowed,
        )
    }

    /// The number of slope samples (1 on a floor of friction only).
    #[must_use]
    pub fn slopes(&self) -> usize {
        self.phi.as_ref().map_or(1, |p| p.values.len())
    }

    /// The number of joint values (friction samples times slope samples).
    #[must_use]
    pub fn values(&self) -> usize {
        self.mu0.as_ref().map_or(1, |p| p.values.len()) * self.slopes()
    }

    /// The number of floor states (the friction's times the slope's).
    #[must_use]
    pub fn floor_states(&self) -> usize {
        self.mu0_part().floor_states() * self.phi_part().floor_states()
    }

    /// Joint value `v`'s `(mu0, phi)`: each `None` where the floor does not set it.
    #[must_use]
    pub fn value(&self, v: usize) -> (Option<f64>, Option<f64>) {
        let s = self.slopes();
        (
            self.mu0.as_ref().map(|p| p.values[v / s]),
            self.phi.as_ref().map(|p| p.values[v % s]),
        )
    }

    /// The index of the slope sample of joint value `v` (0 without a slope).
    #[must_use]
    pub fn slope_of_value(&self, v: usize) -> usize {
        v % self.slopes()
    }

    /// The index of the slope sample the step before walked on, in floor state `f` (0
    /// without a slope).
    #[must_use]
    pub fn slope_of_state(&self, f: usize) -> usize {
        f % self.phi_part().floor_states()
    }

    /// The probability of joint value `v` after floor state `f`.
    #[must_use]
    pub fn prob(&self, f: usize, v: usize) -> f64 {
        let (m, p) = (self.mu0_part(), self.phi_part());
        let (fs, vs) = (p.floor_states(), self.slopes());
        m.prob[f / fs][v / vs] * p.prob[f % fs][v % vs]
    }

    /// The floor state a step on joint value `v` leaves.
    #[must_use]
    pub fn next(&self, v: usize) -> usize {
        let (m, p) = (self.mu0_part(), self.phi_part());
        let vs = self.slopes();
        m.next[v / vs] * p.floor_states() + p.next[v % vs]
    }

    /// The distribution of the floor state before the first step: the friction's stationary
    /// law, and the slope the start stands on, the central one ([`JointFloor::central`]).
    #[must_use]
    pub fn start(&self) -> Vec<f64> {
        let (m, p) = (self.mu0_part(), self.phi_part());
        let c = self.phi_central;
        let mut out = Vec::with_capacity(self.floor_states());
        for &a in &m.start {
            for b in 0..p.floor_states() {
                out.push(if b == c { a } else { 0.0 });
            }
        }
        out
    }

    /// The values the gait's fixed point is found at, `(mu0, phi)` ([`FloorSamples::central`]
    /// of each part the floor sets).
    #[must_use]
    pub fn central(&self) -> (Option<f64>, Option<f64>) {
        (
            self.mu0.as_ref().map(FloorSamples::central),
            self.phi.as_ref().map(|p| p.values[self.phi_central]),
        )
    }

    /// The names of the floor states: the friction's (`any`; `dry`, `icy`) alone on a floor of
    /// friction only, else the slope sample's index (`phi[3]`), after the friction's state where
    /// the floor sets `mu0` (`dry, phi[3]`).
    #[must_use]
    pub fn state_names(&self) -> Vec<String> {
        let Some(p) = &self.phi else {
            return self.mu0_part().states.clone();
        };
        let m = self.mu0_part();
        let mut out = Vec::with_capacity(self.floor_states());
        for a in &m.states {
            for b in 0..p.floor_states() {
                out.push(match &self.mu0 {
                    Some(_) => format!("{a}, phi[{b}]"),
                    None => format!("phi[{b}]"),
                });
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::JointFloor;
    use crate::floor::mesh::FloorSamples;
    use walker_scene::{Distribution, FloorSpec};

    fn samples(d: Distribution, m: usize) -> FloorSamples {
        FloorSamples::of(&FloorSpec::Random { seed: 1, mu0: d }, m).expect("random")
    }

    #[test]
    fn a_floor_of_friction_only_is_the_frictions_chain_bit_for_bit() {
        let ice = samples(
            Distribution::Markov {
                dry: 0.4,
                icy: 0.05,
                dry_length: 20.0,
                icy_length: 3.0,
            },
            8,
        );
        let j = JointFloor::new(Some(ice.clone()), None);
        assert_eq!(j.floor_states(), 2);
        assert_eq!(j.values(), 2);
        for f in 0..2 {
            for v in 0..2 {
                assert_eq!(j.prob(f, v).to_bits(), ice.prob[f][v].to_bits());
            }
        }
        assert_eq!(j.next(1), ice.next[1]);
        assert_eq!(j.start(), ice.start);
        assert_eq!(j.state_names(), vec!["dry", "icy"]);
        assert_eq!(j.value(1), (Some(0.05), None));
    }

    #[test]
    fn a_slope_floor_carries_the_slope_sample_of_the_step_before() {
        let phi = samples(Distribution::Uniform { lo: 0.1, hi: 0.2 }, 4);
        let mu0 = samples(
            Distribution::Markov {
                dry: 0.6,
                icy: 0.1,
                dry_length: 4.0,
                icy_length: 2.0,
            },
            4,
        );
        let j = JointFloor::new(Some(mu0), Some(phi));
        assert_eq!((j.floor_states(), j.values()), (8, 8));
        // Value 6 is icy (friction index 1) on slope sample 2; it leaves state (icy, phi[2]).
        assert_eq!(j.value(6), (Some(0.1), Some(0.1 + 0.1 * 2.5 / 4.0)));
        assert_eq!(j.next(6), 6);
        assert_eq!(j.slope_of_state(j.next(6)), 2);
        assert_eq!(j.state_names()[6], "icy, phi[2]");
        // Every row sums to one; the start stands on the central slope (sample 2 of 4).
        for f in 0..8 {
            let sum: f64 = (0..8).map(|v| j.prob(f, v)).sum();
            assert!((sum - 1.0).abs() < 1e-15, "{sum}");
        }
        let start = j.start();
        assert_eq!(start.iter().filter(|&&p| p > 0.0).count(), 2);
        assert!(start[2] > 0.0 && start[6] > 0.0);
        assert_eq!(j.central(), (Some(0.6), Some(0.1 + 0.1 * 2.5 / 4.0)));
    }
}
