//! The walker's structure: the floor it stands on, the stance foot's friction law, whether
//! the torso is driven, and the law of the impact at heel strike. Independent choices; the
//! derivation, the generator and the simulator all read them from here.

use std::fmt;

use serde::{Deserialize, Serialize};

/// The floor the walker stands on.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Floor {
    /// The level floor (Sections 2-4).
    Level,
    /// A slope of angle `phi` descending towards `+x` (Section 5).
    Slope,
}

/// The friction model that defines `mu` from the state.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Friction {
    /// Frictionless: `mu = 0`.
    None,
    /// `mu = -mu0 tanh(c xd)` (Eq. 26), on the slope `-mu0 tanh(c xd / cos phi)` (Eq. 37).
    Tanh,
    /// Exact Coulomb friction with stick-slip, static coefficient = sliding coefficient `mu0`
    /// (Eq. 25 with the sign that opposes sliding). While the foot slides, `mu = -mu0 sigma`
    /// and the sliding kernels take the sliding direction `sigma` (`+1` towards `+x`, `-1`
    /// backwards) instead of `xd`: the simulator holds it as a discrete mode, where
    /// `sign(xd)` would be `0` at the start of every slide. While it sticks, the stick kernels
    /// (not in the paper) give the accelerations and the ground force.
    Coulomb,
}

/// Whether the torso is driven.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Torso {
    /// Output-following control of `y = th1 - th2` (Eqs. 30-32).
    Actuated,
    /// No torque: `u = 0`.
    Passive,
}

/// The law of the impact at heel strike (`docs/impacts.md`).
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Default, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ImpactLaw {
    /// The paper's impact (Eqs. 6-16, 39-46): only the striking foot's normal velocity is
    /// constrained, so the new stance foot may keep sliding whatever `mu0` is.
    #[default]
    Frictionless,
    /// A plastic impact with Coulomb friction `mu0` at the striking foot (Stronge's
    /// incremental model with a zero restitution coefficient): the foot sticks where the
    /// required impulse lies in the friction cone `|Lambda_t| <= mu0 Lambda_n`, and slides
    /// with `Lambda_t = -mu0 Lambda_n` times the sign of its slip otherwise.
    Coulomb,
}

impl fmt::Display for Floor {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Floor::Level => "level",
            Floor::Slope => "slope",
        })
    }
}

impl fmt::Display for Friction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Friction::None => "none",
            Friction::Tanh => "tanh",
            Friction::Coulomb => "coulomb",
        })
    }
}

impl fmt::Display for Torso {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Torso::Actuated => "actuated",
            Torso::Passive => "passive",
        })
    }
}

impl fmt::Display for ImpactLaw {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            ImpactLaw::Frictionless => "frictionless",
            ImpactLaw::Coulomb => "coulomb",
        })
    }
}
