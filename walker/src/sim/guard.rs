//! The stance events, named: every zero crossing that ends an integration segment of a stance
//! phase is a [`Guard`], and the event list handed to the integrator is built from
//! [`Guard::list`], so that an event's index and its meaning cannot drift apart.

use std::cell::Cell;

use crate::model::{Contact, FrictionLaw, Model, Reaction};
use crate::ode::{Direction, Event};

use super::foot::{Foot, ground_reaction};

/// The most falls a model's stance watches (its `[[fall]]` entries): the loader's limit, so
/// that a model with more is refused at load rather than cut here.
pub const MAX_FALLS: usize = walker_scene::limits::MAX_FALLS;

/// A stance event (a terminal event of the stance integration).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Guard {
    /// The strike: the model's strike guard (`events`' first output) falls through zero
    /// (`alpha/2 - th1` on the paper's level floor). Ends the stance phase where the striking
    /// point is ahead of the stance foot (or the model does not ask); elsewhere (the compass
    /// gait's swing foot passing the stance foot) the integration goes on.
    Strike,
    /// The normal ground reaction falls through zero (Eq. 23): lift-off.
    LiftOff,
    /// The model's fall `i` (`[[fall]]`, in file order): its value falls through zero (the
    /// paper's wheel rolling back onto its rear spoke, a hip touching the floor).
    Fall(usize),
    /// `|lambda|` rises through [`super::SimConfig::lambda_blowup`] `m_t g`: the denominator of
    /// Eq. 23 vanishes, or its numerator is huge (`sim/blowup.rs` tells which).
    LambdaBlowUp,
    /// The power kink of input `i`: its power `u_i w_i` changes sign while the power counts
    /// (where `|u_i w_i|`, the power quadrature's integrand, has a kink; see the stance
    /// system's error test, `Stance::controlled_components`). Off from the end of the power's
    /// count on (a switch by time would be a jump at the breakpoint). The integration goes on
    /// from it. A walker with one input (or none) has one, `PowerKink(0)`, whose value is the
    /// product `prod u_i w_i`; a walker with several has one per input: the product's sign
    /// changes with each factor's, but two factors changing sign within one integrator step
    /// leave it unchanged, and those kinks went unlocated (RABBIT's step-to-step `SR` varied by
    /// 2e-5 relative at any tolerance; `docs/design.md`, "RABBIT").
    PowerKink(usize),
    /// Coulomb friction: a sliding foot comes to rest (`sigma xd` falls through zero; zero while
    /// stuck).
    FootStops,
    /// Coulomb friction: a stuck foot starts to slip (the force that holds it leaves the cone,
    /// `|lambda_t| - mu0 lambda_n` rises through zero).
    FootSlips,
    /// A floor of patches by position (`sim/patches.rs`): the stance foot reaches an end of
    /// the patch it stands on (`min(s - from, to - s)` falls through zero, `s` the foot's
    /// position along the floor). Watched only on such a floor, after the others.
    Boundary,
}

impl Guard {
    /// The guards watched for a model with `falls` falls and `inputs` inputs under the friction
    /// law `law`, in the order of the event list: the strike, lift-off, the falls, the blow-up,
    /// the power kinks (one, or one per input where there are several), and under Coulomb
    /// friction the stick-slip pair.
    pub fn list(falls: usize, inputs: usize, law: FrictionLaw) -> Vec<Guard> {
        let mut out = vec![Guard::Strike, Guard::LiftOff];
        out.extend((0..falls.min(MAX_FALLS)).map(Guard::Fall));
        out.push(Guard::LambdaBlowUp);
        out.extend((0..inputs.max(1)).map(Guard::PowerKink));
        if law == FrictionLaw::Coulomb {
            out.extend([Guard::FootStops, Guard::FootSlips]);
        }
        out
    }

    /// The direction of the zero crossing that fires the guard.
    pub fn direction(self) -> Direction {
        match self {
            Guard::LambdaBlowUp | Guard::FootSlips => Direction::Rising,
            Guard::Strike
            | Guard::LiftOff
            | Guard::Fall(_)
            | Guard::FootStops
            | Guard::Boundary => Direction::Falling,
            Guard::PowerKink(_) => Direction::Either,
        }
    }
}

/// The guard functions of one stance phase: what they share (the foot with its remembered
/// reaction and power) and the thresholds they compare with.
pub(super) struct Guards<'a> {
    foot: &'a Foot<'a>,
    /// The guards, in the order of the event list.
    list: Vec<Guard>,
    /// The blow-up threshold of `|lambda|`.
    lambda_max: f64,
    /// Whether the power kink is watched (before the end of the power's count).
    kinks: Cell<bool>,
    /// The patch the foot stands on, `[from, to)` along the floor (m), and `cos phi` (the
    /// foot's position along the floor is `x / cos phi`): only on a floor of patches.
    patch: Option<([f64; 2], f64)>,
}

impl<'a> Guards<'a> {
    /// The guards of a stance phase of `foot`, with the blow-up threshold `lambda_max`.
    pub(super) fn new(foot: &'a Foot<'a>, lambda_max: f64) -> Self {
        let model: &Model = foot.model;
        Self {
            foot,
            list: Guard::list(
                model.event_count() - 1,
                model.inputs(),
                model.friction_law(),
            ),
            lambda_max,
            kinks: Cell::new(model.is_active()),
            patch: None,
        }
    }

    /// The guards of [`Guards::new`] and [`Guard::Boundary`] for a foot on the patch
    /// `[from, to)` (`patch`, metres along the floor; an end may be infinite), on a floor of
    /// slope `cos_phi`.
    pub(super) fn on_patch(
        foot: &'a Foot<'a>,
        lambda_max: f64,
        patch: [f64; 2],
        cos_phi: f64,
    ) -> Self {
        let mut g = Self::new(foot, lambda_max);
        g.list.push(Guard::Boundary);
        g.patch = Some((patch, cos_phi));
        g
    }

    /// Whether the power kink is still watched.
    pub(super) fn power_kinks(&self) -> bool {
        self.kinks.get()
    }

    /// The guard of an event index of the integrator's [`crate::ode::Outcome::Event`].
    pub(super) fn of_event(&self, index: usize) -> Option<Guard> {
        self.list.get(index).copied()
    }

    /// Stop watching the power kink (from the end of the power's count on).
    pub(super) fn end_power_kinks(&self) {
        self.kinks.set(false);
    }

    /// The stance foot the guards watch.
    pub(super) fn foot(&self) -> &'a Foot<'a> {
        self.foot
    }

    /// The value of the guard function of `guard` at `(t, y)`.
    fn value<const S: usize>(&self, guard: Guard, t: f64, y: &[f64; S]) -> f64 {
        let foot = self.foot;
        match guard {
            Guard::Strike | Guard::Fall(_) => {
                let mut e = [0.0; 1 + MAX_FALLS];
                self.model_events(y, &mut e);
                Self::event_value(guard, &e)
            }
            Guard::LiftOff | Guard::LambdaBlowUp | Guard::FootSlips => {
                self.reaction_value(guard, || foot.reaction(t, y))
            }
            Guard::PowerKink(_) | Guard::FootStops | Guard::Boundary => self.own_value(guard, t, y),
        }
    }

    /// The values of every guard at `(t, y)`, in the order of the event list, into `out`:
    /// each what [`Guards::value`] gives, with the model's `events` kernel and the ground
    /// reaction evaluated once for all the guards that read them (the integrator asks at every
    /// accepted step's end). Returns `false`, writing nothing, where `out` is not one value
    /// per guard.
    pub(super) fn values<const S: usize>(&self, t: f64, y: &[f64; S], out: &mut [f64]) -> bool {
        if out.len() != self.list.len() {
            return false;
        }
        let mut e = [0.0; 1 + MAX_FALLS];
        self.model_events(y, &mut e);
        let mut reaction = None;
        for (v, &guard) in out.iter_mut().zip(&self.list) {
            *v = match guard {
                Guard::Strike | Guard::Fall(_) => Self::event_value(guard, &e),
                Guard::LiftOff | Guard::LambdaBlowUp | Guard::FootSlips => {
                    self.reaction_value(guard, || {
                        *reaction.get_or_insert_with(|| {
                            ground_reaction(self.foot.model, t, y, self.foot.contact())
                        })
                    })
                }
                Guard::PowerKink(_) | Guard::FootStops | Guard::Boundary => {
                    self.own_value(guard, t, y)
                }
            };
        }
        true
    }

    /// The model's `events` kernel (the strike guard and the falls) at the coordinates of `y`,
    /// into the first of `e` (the rest stays zero).
    fn model_events<const S: usize>(&self, y: &[f64; S], e: &mut [f64; 1 + MAX_FALLS]) {
        let model = self.foot.model;
        let k = model.event_count().min(e.len());
        model.events(&y[..model.n()], &mut e[..k]);
    }

    /// The value of the strike or fall guard `guard` from the `events` kernel's values `e`.
    fn event_value(guard: Guard, e: &[f64; 1 + MAX_FALLS]) -> f64 {
        match guard {
            Guard::Fall(i) => e[1 + i],
            _ => e[0],
        }
    }

    /// The value of the lift-off, blow-up or slip guard `guard` from the ground reaction
    /// (`reaction` gives it; the slip guard of a foot that is not stuck does not ask).
    fn reaction_value(&self, guard: Guard, reaction: impl FnOnce() -> Reaction) -> f64 {
        match guard {
            Guard::LiftOff => reaction().normal,
            Guard::LambdaBlowUp => reaction().lambda.abs() - self.lambda_max,
            _ => {
                if self.foot.contact() == Contact::Stuck {
                    let r = reaction();
                    r.tangential.abs() - self.foot.model.mu0() * r.normal
                } else {
                    -1.0
                }
            }
        }
    }

    /// The value of the power-kink, foot-stops or boundary guard `guard` at `(t, y)`.
    fn own_value<const S: usize>(&self, guard: Guard, t: f64, y: &[f64; S]) -> f64 {
        let foot = self.foot;
        match guard {
            Guard::PowerKink(i) => {
                if !self.kinks.get() {
                    1.0
                } else if foot.several {
                    foot.input_power(t, y, i)
                } else {
                    foot.power(t, y)
                }
            }
            Guard::Boundary => match self.patch {
                Some(([from, to], cos_phi)) => {
                    let s = y[0] / cos_phi;
                    (s - from).min(to - s)
                }
                None => 1.0,
            },
            _ => foot.contact().sigma() * y[foot.model.n()],
        }
    }

    /// The event list: one terminal event per guard, in the order of [`Guard::list`].
    pub(super) fn events<const S: usize>(&self) -> Vec<Event<'_, S>> {
        self.list
            .iter()
            .map(|&g| Event::terminal(g.direction(), move |t, y: &[f64; S]| self.value(g, t, y)))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::{Guard, Guards};
    use crate::model::{Contact, Friction, FrictionLaw, Slide};
    use crate::setup::Setup;
    use crate::sim::foot::Foot;

    /// What the integrator is given at a step's end, all the guards' values in one call
    /// ([`Guards::values`]), is each guard's own value ([`Guards::value`], what root location
    /// asks for) bit for bit: for the tanh law, and for Coulomb friction with the foot stuck
    /// and sliding either way, at the start and at states and times away from it (the ramp's
    /// middle and its end). A buffer that is not one value per guard is refused.
    #[test]
    fn the_guards_values_together_are_each_guards_own_value_bit_for_bit() {
        for coulomb in [false, true] {
            let mut setup = Setup::active_level().expect("the built-in scene");
            if coulomb {
                setup.friction = Friction::Coulomb;
            }
            let model = setup.model().expect("compiled kernels");
            assert_eq!(
                model.n(),
                4,
                "the paper's walker: a state of 8 and the power"
            );
            let contacts = if coulomb {
                vec![
                    Contact::Stuck,
                    Contact::Sliding(Slide::of(1.0)),
                    Contact::Sliding(Slide::of(-1.0)),
                ]
            } else {
                vec![Contact::Smooth]
            };
            let mut y0 = [0.0; 9];
            y0[..8].copy_from_slice(&model.start_state());
            for contact in contacts {
                let foot = Foot::new(&model, contact);
                let guards = Guards::new(&foot, 1e3);
                for (t, scale) in [(0.0, 1.0), (0.15, 0.9), (0.3, 1.1)] {
                    let y = y0.map(|v| v * scale);
                    let mut together = vec![f64::NAN; guards.list.len()];
                    assert!(guards.values(t, &y, &mut together));
                    let each: Vec<u64> = guards
                        .list
                        .iter()
                        .map(|&g| guards.value(g, t, &y).to_bits())
                        .collect();
                    let together: Vec<u64> = together.iter().map(|v| v.to_bits()).collect();
                    assert_eq!(together, each, "{contact:?} at t = {t}");
                }
                let mut short = vec![0.0; guards.list.len() - 1];
                assert!(!guards.values(0.0, &y0, &mut short));
            }
        }
    }

    #[test]
    fn the_list_has_the_falls_after_lift_off_a_kink_per_input_and_coulomb_adds_the_stick_slip_pair()
    {
        let tanh = Guard::list(1, 1, FrictionLaw::Tanh);
        assert_eq!(
            tanh,
            [
                Guard::Strike,
                Guard::LiftOff,
                Guard::Fall(0),
                Guard::LambdaBlowUp,
                Guard::PowerKink(0)
            ]
        );
        assert_eq!(Guard::list(1, 0, FrictionLaw::Tanh), tanh);
        let coulomb = Guard::list(2, 3, FrictionLaw::Coulomb);
        assert_eq!(coulomb.len(), 10);
        assert_eq!(&coulomb[2..4], [Guard::Fall(0), Guard::Fall(1)]);
        assert_eq!(
            &coulomb[5..8],
            [
                Guard::PowerKink(0),
                Guard::PowerKink(1),
                Guard::PowerKink(2)
            ]
        );
        assert_eq!(&coulomb[8..], [Guard::FootStops, Guard::FootSlips]);
    }
}
