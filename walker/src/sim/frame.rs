//! The walk's motion at one time ([`Frame`]) and the collector of the frames at `0, dt, 2 dt,
//! ..` since the start of a walk ([`Frames`]): each frame is evaluated from the integrator's
//! dense output inside the accepted step that contains its time (not at the last accepted
//! step's end), with the ground reaction and the contact of that moment.

use serde::Serialize;

use crate::model::{Contact, Model, Reaction};
use crate::ode::Step;
use crate::vector::Vector;

use super::failure::Failure;
use super::foot::{Foot, control_input, ground_reaction, initial_contact};
use super::state::{finite, integrated, mech, with_state_size};

/// The walk's motion at one time.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Frame {
    /// Time since the start of the walk, `k dt` (s).
    pub time: f64,
    /// Time since the last impact (the step's own clock, on which `T_set` is counted) (s).
    pub t: f64,
    /// Step number (0 for the step that starts at the initial condition).
    pub step: usize,
    /// State `[q, qd]` in the stance leg's coordinates: `(x, z)` is the stance foot.
    pub state: Vector,
    /// The ground's force on the stance foot (`lambda`, its normal and friction parts).
    pub reaction: Reaction,
    /// Control inputs `u` (none for a passive walker).
    pub u: Vector,
    /// How the stance foot touches the floor.
    pub contact: Contact,
}

/// Collects the frames of a walk: the stance observer's share of each accepted step.
pub(super) struct Frames {
    dt: f64,
    max_frames: usize,
    next: usize,
    frames: Vec<Frame>,
    truncated: bool,
}

impl Frames {
    /// No frames yet; frames every `dt` (finite and > 0, else none), at most `max_frames`.
    pub(super) fn new(dt: f64, max_frames: usize) -> Self {
        let usable = dt.is_finite() && dt > 0.0;
        Frames {
            dt,
            max_frames: if usable { max_frames } else { 0 },
            next: 0,
            frames: Vec::new(),
            truncated: false,
        }
    }

    /// The number of frames so far.
    pub(super) fn len(&self) -> usize {
        self.frames.len()
    }

    /// Moves the stance foot's position in the frames from `from` on by `o` (the step's
    /// model saw the walker from the point `o`, `super::StepModels::origin`).
    pub(super) fn move_from(&mut self, from: usize, o: [f64; 2]) {
        for f in self.frames.iter_mut().skip(from) {
            f.state[0] += o[0];
            f.state[1] += o[1];
        }
    }

    /// The frames, and whether the walk went on past the last one (`max_frames` reached).
    pub(super) fn finish(self) -> (Vec<Frame>, bool) {
        (self.frames, self.truncated)
    }

    /// Called for every accepted step `st` of the stance phase `step` (its clock starts at
    /// `t_offset` since the start of the walk) with the stance foot `foot`: evaluates the dense
    /// output at every `k dt` inside the step.
    pub(super) fn on_step<const S: usize>(
        &mut self,
        foot: &Foot<'_>,
        t_offset: f64,
        step: usize,
        st: &Step<'_, S>,
    ) {
        let end = t_offset + st.t_end();
        let mut y = [0.0; S];
        loop {
            let time = self.next as f64 * self.dt;
            if time > end {
                return;
            }
            if self.frames.len() >= self.max_frames {
                self.truncated = true;
                return;
            }
            // Steps follow each other without gaps, so `time` is not before this step's start
            // but by rounding; clamping keeps the interpolant inside its step.
            let t = (time - t_offset).clamp(st.t_start(), st.t_end());
            st.eval(t, &mut y);
            let contact = foot.contact();
            let reaction = foot.reaction(t, &y);
            let u = control_input(foot.model, t, &y, contact);
            self.next += 1;
            if finite(&y) && reaction.lambda.is_finite() {
                self.frames.push(Frame {
                    time,
                    t,
                    step,
                    state: mech(&y),
                    reaction,
                    u,
                    contact,
                });
            }
        }
    }
}

/// The frame at the moment of `failure`, `time` since the start of the walk: the failure's
/// state, with the contact of `last` (the last frame before it) if that is of the same step,
/// else the contact the step began with (stuck where none is consistent, as for
/// [`super::FailureKind::ContactInconsistent`]). The ground reaction may be huge or not finite
/// there (a vanishing denominator of `lambda` is a failure).
pub(super) fn at_failure(
    model: &Model,
    failure: &Failure,
    time: f64,
    last: Option<&Frame>,
) -> Frame {
    let contact = match last {
        Some(f) if f.step == failure.step => f.contact,
        _ => with_state_size!(model.n(), S => {
            let y: [f64; S] = integrated(&failure.state);
            initial_contact(model, &y, failure.step).unwrap_or(Contact::Stuck)
        }, _ => Contact::Stuck),
    };
    let y = &failure.state;
    Frame {
        time,
        t: failure.t,
        step: failure.step,
        state: failure.state,
        reaction: ground_reaction(model, failure.t, y, contact),
        u: control_input(model, failure.t, y, contact),
        contact,
    }
}
