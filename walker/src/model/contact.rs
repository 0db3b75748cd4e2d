//! How the stance foot meets the floor: the friction law ([`FrictionLaw`]), the direction of a
//! slide ([`Slide`]), the contact mode ([`Contact`]) and the ground's force ([`Reaction`]).

use serde::Serialize;

/// The stance foot's friction law.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum FrictionLaw {
    /// `mu = -mu0 tanh(c xd)` (Eq. 26; `-mu0 tanh(c xd / cos phi)` on the slope, Eq. 37), or no
    /// friction with `mu0 = 0`: the foot always slides, and [`Contact::Smooth`] is its only
    /// contact.
    Tanh,
    /// Exact Coulomb friction (Eq. 25 with the sign that opposes sliding, the paper's static
    /// coefficient equal to the sliding one, `mu0`): the foot slides with friction `mu0` times
    /// the normal force against its motion, or sticks while the tangential force it needs is at
    /// most that ([`Contact::Sliding`], [`Contact::Stuck`]).
    Coulomb,
}

/// The direction in which the stance foot slides.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Slide {
    /// Towards `+x` (forwards; down the slope).
    Forward,
    /// Towards `-x`.
    Backward,
}

impl Slide {
    /// `sigma = sign(xd)` of Eq. 25: `1` forwards, `-1` backwards.
    pub fn sigma(self) -> f64 {
        match self {
            Slide::Forward => 1.0,
            Slide::Backward => -1.0,
        }
    }

    /// The direction of a nonzero number's sign.
    pub fn of(x: f64) -> Slide {
        if x > 0.0 {
            Slide::Forward
        } else {
            Slide::Backward
        }
    }
}

/// How the stance foot touches the floor.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "mode", content = "direction")]
pub enum Contact {
    /// The smooth friction law ([`FrictionLaw::Tanh`]): `mu` a function of `xd`.
    Smooth,
    /// Coulomb friction, sliding: `mu = -mu0 sigma` (Eq. 25).
    Sliding(Slide),
    /// Coulomb friction, stuck: `xd = 0` (the stance foot cannot move along the floor).
    Stuck,
}

impl Contact {
    /// `sigma` of a sliding contact (0 otherwise).
    pub fn sigma(self) -> f64 {
        match self {
            Contact::Sliding(s) => s.sigma(),
            Contact::Smooth | Contact::Stuck => 0.0,
        }
    }
}

/// The ground's force on the stance foot.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Reaction {
    /// The paper's `lambda`: the vertical component of the reaction without friction
    /// (Eqs. 22-23; on the slope the normal force times `cos phi`, Section 5.1). For a stuck
    /// foot the vertical component of the whole force.
    pub lambda: f64,
    /// The force along the floor's normal (negative: the foot would lift off).
    pub normal: f64,
    /// The force along the floor, positive towards `+x` (down the slope): `mu` times the normal
    /// force while sliding, what holds the foot while stuck.
    pub tangential: f64,
}
