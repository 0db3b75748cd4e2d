//! What the study walks: the paper's active walker on level ground (Table 1, Section 4's
//! start) for a grid of ramp durations `T_set`, under two contact laws, on two random floors,
//! on uniform floors spanning each random floor's range, and across ice patches of growing
//! length on a dry floor.

use walker::floor::{Distribution, FloorSpec};
use walker_scene::{Friction, ImpactLaw};

/// The ramp durations `T_set` (s): Fig. 8's 0.2, 0.3 and 0.4, and the values between and
/// beyond, up to 0.6 (from about 0.68 s on, the strike comes before the ramp ends).
pub const T_SETS: [f64; 9] = [0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5, 0.55, 0.6];

/// A contact law of the stance foot and of the strike.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Law {
    /// Its name in the files.
    pub name: &'static str,
    /// The stance foot's friction law.
    pub friction: Friction,
    /// The strike's impact law.
    pub impact: ImpactLaw,
}

/// The paper's laws (tanh friction in stance, a frictionless impact) and exact Coulomb
/// friction in stance and at the strike (`docs/impacts.md`).
pub const LAWS: [Law; 2] = [
    Law {
        name: "tanh",
        friction: Friction::Tanh,
        impact: ImpactLaw::Frictionless,
    },
    Law {
        name: "coulomb",
        friction: Friction::Coulomb,
        impact: ImpactLaw::Coulomb,
    },
];

/// A random floor of the study.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RandomFloor {
    /// Its name in the files.
    pub name: &'static str,
    /// What it is, in words.
    pub about: &'static str,
    /// The seed of its draws.
    pub seed: u64,
    /// How `mu0` is drawn per step.
    pub mu0: Distribution,
}

impl RandomFloor {
    /// The floor.
    #[must_use]
    pub fn spec(&self) -> FloorSpec {
        FloorSpec::Random {
            seed: self.seed,
            mu0: self.mu0,
        }
    }

    /// The mean `mu0` of a step (the stationary mean of the Markov chain).
    #[must_use]
    pub fn mean(&self) -> f64 {
        match self.mu0 {
            Distribution::Uniform { lo, hi } => 0.5 * (lo + hi),
            Distribution::TruncatedNormal { mean, .. } => mean,
            Distribution::Markov {
                dry,
                icy,
                dry_length,
                icy_length,
            } => (dry * dry_length + icy * icy_length) / (dry_length + icy_length),
        }
    }
}

/// The random floors: a rough road whose `mu0` is drawn anew at every step, and patches of
/// ice on a dry road.
pub const FLOORS: [RandomFloor; 2] = [
    RandomFloor {
        name: "rough",
        about: "mu0 uniform on [0.02, 0.6), drawn anew at every step",
        seed: 1,
        mu0: Distribution::Uniform { lo: 0.02, hi: 0.6 },
    },
    RandomFloor {
        name: "ice",
        about: "a dry road (mu0 = 0.6) with patches of ice (mu0 = 0.05), \
                dry stretches of 10 steps and patches of 3 on average",
        seed: 2,
        mu0: Distribution::Markov {
            dry: 0.6,
            icy: 0.05,
            dry_length: 10.0,
            icy_length: 3.0,
        },
    },
];

/// How many uniform floors span a random floor's range (its bounds included).
pub const UNIFORM_POINTS: usize = 12;

/// The ice patch: `LEAD` dry steps, `k` icy ones, then `TAIL` dry ones.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Patch {
    /// `mu0` of the dry floor.
    pub dry: f64,
    /// `mu0` of the ice.
    pub icy: f64,
    /// Dry steps before the patch (the walker settles from its start).
    pub lead: usize,
    /// Dry steps after the patch that the walker must complete to have crossed it.
    pub tail: usize,
    /// The longest patch tried (steps).
    pub longest: usize,
}

/// The ice patch of the study: the ice floor's dry and icy values.
pub const PATCH: Patch = Patch {
    dry: 0.6,
    icy: 0.05,
    lead: 10,
    tail: 20,
    longest: 20,
};

impl Patch {
    /// The floor with a patch of `k` icy steps.
    #[must_use]
    pub fn floor(&self, k: usize) -> FloorSpec {
        let mut mu0 = vec![self.dry; self.lead];
        mu0.extend(std::iter::repeat_n(self.icy, k));
        mu0.push(self.dry);
        FloorSpec::Steps { mu0 }
    }

    /// The steps a walk across a patch of `k` steps must complete.
    #[must_use]
    pub fn steps(&self, k: usize) -> usize {
        self.lead + k + self.tail
    }
}
