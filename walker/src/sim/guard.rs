//! The stance events, named: every zero crossing that ends an integration segment of a stance
//! phase is a [`Guard`], and the event list handed to the integrator is built from
//! [`Guard::ALL`], so that an event's index and its meaning cannot drift apart.

use std::cell::Cell;

use crate::model::{Contact, FrictionLaw};
use crate::ode::{Direction, Event};

use super::foot::Foot;
use super::state::N;

/// A stance event (a terminal event of the stance integration).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Guard {
    /// Heel strike: the stance-leg angle `th1` rises through the heel-strike angle (`alpha/2`,
    /// `alpha/2 + phi` on the slope). Ends the stance phase.
    Strike,
    /// The normal ground reaction falls through zero (Eq. 23): lift-off.
    LiftOff,
    /// `th1` falls through the rear-contact angle: the wheel rolled back onto its rear spoke.
    FellBackward,
    /// `|lambda|` rises through [`super::SimConfig::lambda_blowup`] `m_t g`: the denominator of
    /// Eq. 23 vanishes, or its numerator is huge (`sim/blowup.rs` tells which).
    LambdaBlowUp,
    /// The power kink: `ydot u` changes sign before `T_set` (where `|ydot u|`, the power
    /// quadrature's integrand, has a kink; see the stance system's error test,
    /// `Stance::controlled_components`). Off from the breakpoint at `T_set` on (a switch by
    /// time would be a jump at the breakpoint). The integration goes on from it.
    PowerKink,
    /// Coulomb friction: a sliding foot comes to rest (`sigma xd` falls through zero; zero while
    /// stuck).
    FootStops,
    /// Coulomb friction: a stuck foot starts to slip (the force that holds it leaves the cone,
    /// `|lambda_t| - mu0 lambda_n` rises through zero).
    FootSlips,
}

impl Guard {
    /// Every guard, in the order of the event list.
    pub const ALL: [Guard; 7] = [
        Guard::Strike,
        Guard::LiftOff,
        Guard::FellBackward,
        Guard::LambdaBlowUp,
        Guard::PowerKink,
        Guard::FootStops,
        Guard::FootSlips,
    ];

    /// The guards watched under the friction law `law` (a prefix of [`Guard::ALL`]): the
    /// stick-slip guards only under Coulomb friction.
    pub fn active(law: FrictionLaw) -> &'static [Guard] {
        match law {
            FrictionLaw::Tanh => &Self::ALL[..5],
            FrictionLaw::Coulomb => &Self::ALL,
        }
    }

    /// The guard of an event index of the integrator's [`crate::ode::Outcome::Event`].
    pub fn of_event(index: usize) -> Option<Guard> {
        Self::ALL.get(index).copied()
    }

    /// The direction of the zero crossing that fires the guard.
    pub fn direction(self) -> Direction {
        match self {
            Guard::Strike | Guard::LambdaBlowUp | Guard::FootSlips => Direction::Rising,
            Guard::LiftOff | Guard::FellBackward | Guard::FootStops => Direction::Falling,
            Guard::PowerKink => Direction::Either,
        }
    }
}

/// The guard functions of one stance phase: what they share (the foot with its remembered
/// reaction and power) and the thresholds they compare with.
pub(super) struct Guards<'a> {
    foot: &'a Foot<'a>,
    /// The heel-strike angle.
    heel: f64,
    /// The rear-contact angle.
    rear: f64,
    /// The blow-up threshold of `|lambda|`.
    lambda_max: f64,
    /// The friction coefficient.
    mu0: f64,
    /// Whether the power kink is watched (active walker, before `T_set`).
    kinks: Cell<bool>,
}

impl<'a> Guards<'a> {
    /// The guards of a stance phase of `foot`, with the blow-up threshold `lambda_max`.
    pub(super) fn new(foot: &'a Foot<'a>, lambda_max: f64) -> Self {
        let model = foot.model;
        Self {
            foot,
            heel: model.heel_strike_angle(),
            rear: model.rear_contact_angle(),
            lambda_max,
            mu0: model.runtime.mu0,
            kinks: Cell::new(model.is_active()),
        }
    }

    /// Stop watching the power kink (from the breakpoint `T_set` on).
    pub(super) fn end_power_kinks(&self) {
        self.kinks.set(false);
    }

    /// The value of the guard function of `guard` at `(t, y)`.
    fn value(&self, guard: Guard, t: f64, y: &[f64; N]) -> f64 {
        let foot = self.foot;
        match guard {
            Guard::Strike => y[2] - self.heel,
            Guard::LiftOff => foot.reaction(t, y).normal,
            Guard::FellBackward => y[2] - self.rear,
            Guard::LambdaBlowUp => foot.reaction(t, y).lambda.abs() - self.lambda_max,
            Guard::PowerKink => {
                if self.kinks.get() {
                    foot.power(t, y)
                } else {
                    1.0
                }
            }
            Guard::FootStops => foot.contact().sigma() * y[4],
            Guard::FootSlips => {
                if foot.contact() == Contact::Stuck {
                    let r = foot.reaction(t, y);
                    r.tangential.abs() - self.mu0 * r.normal
                } else {
                    -1.0
                }
            }
        }
    }

    /// The event list: one terminal event per guard of [`Guard::ALL`], in that order (pass
    /// the prefix [`Guard::active`] to the integrator).
    pub(super) fn events(&self) -> [Event<'_, N>; 7] {
        Guard::ALL
            .map(|g| Event::terminal(g.direction(), move |t, y: &[f64; N]| self.value(g, t, y)))
    }
}

#[cfg(test)]
mod tests {
    use super::Guard;
    use crate::model::FrictionLaw;

    #[test]
    fn an_event_index_names_the_guard_at_that_place_of_the_list() {
        for (i, g) in Guard::ALL.iter().enumerate() {
            assert_eq!(Guard::of_event(i), Some(*g));
        }
        assert_eq!(Guard::of_event(Guard::ALL.len()), None);
    }

    #[test]
    fn the_smooth_law_watches_five_guards_and_coulomb_adds_the_stick_slip_pair() {
        let tanh = Guard::active(FrictionLaw::Tanh);
        let coulomb = Guard::active(FrictionLaw::Coulomb);
        assert_eq!(tanh.len(), 5);
        assert!(!tanh.contains(&Guard::FootStops) && !tanh.contains(&Guard::FootSlips));
        assert_eq!(coulomb, &Guard::ALL);
        assert_eq!(&coulomb[..5], tanh);
    }
}
