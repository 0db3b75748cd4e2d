//! The stance phase as an ODE system ([`Stance`]: the mechanical equations of motion and the
//! input-power quadrature, with their Jacobian where the model's kernels give it) and the
//! observer that samples the motion ([`Recorder`]).

use crate::jacobian::StanceJacobian;
use crate::model::{Model, StanceRhs};
use crate::ode::{Observer, OdeSystem, Step};
use crate::vector::Vector;

use super::foot::{Foot, control_input, ground_reaction};
use super::frame::Frames;
use super::gait::Sample;
use super::guard::Guards;
use super::state::mech;

/// The stance phase of `model` with the foot `foot`, as an ODE system for [`crate::ode`].
pub(super) struct Stance<'a> {
    /// The model.
    model: &'a Model,
    /// The state Jacobian from the model's Jacobian kernels; `None` falls back to finite
    /// differences.
    jac: Option<StanceJacobian<'a>>,
    /// The stance foot.
    foot: &'a Foot<'a>,
    /// The right-hand side in the foot's contact ([`Stance::in_contact`] after the contact
    /// changes).
    rhs: StanceRhs<'a>,
    /// The stance's guards, whose values the integrator asks for together at every step's end
    /// (the events handed to it are theirs, [`Guards::events`]).
    guards: &'a Guards<'a>,
}

impl<'a> Stance<'a> {
    /// The stance phase of the foot `guards` watch, in the foot's current contact, to be
    /// integrated with the guards' events ([`Guards::events`]).
    pub(super) fn new(guards: &'a Guards<'a>) -> Self {
        let foot = guards.foot();
        let model = foot.model;
        Self {
            model,
            jac: StanceJacobian::new(model).ok(),
            foot,
            rhs: model.stance_rhs_in(foot.contact()),
            guards,
        }
    }

    /// Follows the foot's contact (it changes between integration segments, at stick-slip
    /// transitions).
    pub(super) fn in_contact(&mut self) {
        self.rhs = self.model.stance_rhs_in(self.foot.contact());
    }
}

impl<const S: usize> OdeSystem<S> for Stance<'_> {
    fn rhs(&mut self, t: f64, y: &[f64; S], dy: &mut [f64; S]) {
        let n = S / 2;
        let (dq, power) = dy.split_at_mut(2 * n);
        power[0] = self.rhs.eval(t, &y[..2 * n], dq);
    }

    /// The error test watches the power quadrature (the last component) too, except on a step
    /// in which an input's power `u_i w_i` changes sign: its absolute value has a kink there,
    /// which would only cause rejections. Such a step is not kept: the kink is a terminal event
    /// of the stance integration ([`super::Guard::PowerKink`], one per input where there are several), so the step is taken again
    /// ending on the kink, and the integration goes on from there, with a smooth integrand on
    /// each side.
    fn controlled_components(&mut self, t0: f64, y0: &[f64; S], t1: f64, y1: &[f64; S]) -> usize {
        if self.foot.crossed(t0, y0, t1, y1) {
            S - 1
        } else {
            S
        }
    }

    /// The state Jacobian for the stiff integrator: `d qd / d y` is the identity block, and
    /// `d qdd / d y` and the power's row come from the model's Jacobian kernels
    /// ([`StanceJacobian`]).
    fn jacobian(&mut self, t: f64, y: &[f64; S], jac: &mut [[f64; S]; S]) -> bool {
        let Some(j) = &self.jac else {
            return false;
        };
        j.fill(t, y, self.foot.contact(), jac)
    }

    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        self.model.next_breakpoint(t)
    }

    /// The guards' values at a step's end, the kernels they share evaluated once
    /// ([`Guards::values`]).
    fn event_values(&mut self, t: f64, y: &[f64; S], out: &mut [f64]) -> bool {
        self.guards.values(t, y, out)
    }
}

/// Records samples of the motion, if `out` is set: every accepted step's end and `interior`
/// points inside it; and frames at given times, if `frames` is set.
pub(super) struct Recorder<'a> {
    /// The stance foot.
    pub(super) foot: &'a Foot<'a>,
    /// Where the samples go.
    pub(super) out: Option<&'a mut Vec<Sample>>,
    /// The time of the step's start since the start of the walk.
    pub(super) t_offset: f64,
    /// The step number.
    pub(super) step: usize,
    /// Samples inside each accepted step.
    pub(super) interior: usize,
    /// Where the frames at given times go ([`super::trajectory()`]).
    pub(super) frames: Option<&'a mut Frames>,
}

impl<const S: usize> Observer<S> for Recorder<'_> {
    fn wants_step(&mut self, _: f64, _: &[f64; S], _: f64, _: &[f64; S]) -> bool {
        self.out.is_some() || self.frames.is_some()
    }

    fn on_step(&mut self, st: &Step<'_, S>) {
        if let Some(frames) = self.frames.as_deref_mut() {
            frames.on_step(self.foot, self.t_offset, self.step, st);
        }
        let Some(out) = self.out.as_deref_mut() else {
            return;
        };
        let (model, contact) = (self.foot.model, self.foot.contact());
        let mut y = [0.0; S];
        for k in 1..=self.interior + 1 {
            let t =
                st.t_start() + (st.t_end() - st.t_start()) * k as f64 / (self.interior + 1) as f64;
            st.eval(t, &mut y);
            let u: Vector = control_input(model, t, &y, contact);
            let lambda = ground_reaction(model, t, &y, contact).lambda;
            if y.iter().all(|v| v.is_finite()) && lambda.is_finite() {
                out.push(Sample {
                    time: self.t_offset + t,
                    step: self.step,
                    state: mech(&y),
                    lambda,
                    u,
                });
            }
        }
    }
}
