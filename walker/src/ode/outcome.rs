//! How an integration ended: reached, event, breakpoint, or a failure; and why it gave up,
//! for the layers above to report ([`GaveUp`]).

use std::fmt;

use serde::{Serialize, Serializer};

/// How an integration ended. Every variant carries the time and state at
/// which the integrator stopped; the state is the last accepted (finite) one
/// unless stated otherwise.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Outcome<const N: usize> {
    /// `t_end` was reached; `t == t_end` exactly.
    Reached {
        /// Final time.
        t: f64,
        /// Final state.
        y: [f64; N],
    },
    /// The terminal event `index` (position in the events slice) fired at
    /// `t`; `y` is the state there, from a step of the method that ends at
    /// `t` (not from the interpolant that located `t`).
    Event {
        /// Index of the event in the slice passed to `integrate`.
        index: usize,
        /// Located event time.
        t: f64,
        /// State at `t`.
        y: [f64; N],
    },
    /// The breakpoint `t` given by [`OdeSystem::next_breakpoint`](super::OdeSystem::next_breakpoint) was reached
    /// exactly; continue by calling `integrate` from `(t, y)`.
    Breakpoint {
        /// The breakpoint.
        t: f64,
        /// State at the breakpoint.
        y: [f64; N],
    },
    /// The step size fell below what the time resolution allows
    /// (`0.1 |h| <= eps |t|`), as in Hairer's codes.
    StepSizeTooSmall {
        /// Time reached.
        t: f64,
        /// State at `t`.
        y: [f64; N],
        /// The step size that was too small.
        h: f64,
    },
    /// The right-hand side or an event function returned a non-finite value
    /// (or the initial state was not finite). `t`, `y` is the last finite
    /// point, except when the initial state itself is not finite.
    NonFinite {
        /// Time of the last finite point.
        t: f64,
        /// State at `t`.
        y: [f64; N],
    },
    /// [`Config::max_steps`](super::Config::max_steps) attempts were made without reaching `t_end`.
    MaxSteps {
        /// Time reached.
        t: f64,
        /// State at `t`.
        y: [f64; N],
    },
    /// The arguments were inconsistent (for example `t_end < t0`, bad
    /// tolerances or settings); nothing was integrated.
    InvalidInput {
        /// The initial time.
        t: f64,
        /// The initial state.
        y: [f64; N],
        /// What was wrong.
        reason: &'static str,
    },
}

impl<const N: usize> Outcome<N> {
    /// Time at which the integration stopped.
    pub fn t(&self) -> f64 {
        match *self {
            Outcome::Reached { t, .. }
            | Outcome::Event { t, .. }
            | Outcome::Breakpoint { t, .. }
            | Outcome::StepSizeTooSmall { t, .. }
            | Outcome::NonFinite { t, .. }
            | Outcome::MaxSteps { t, .. }
            | Outcome::InvalidInput { t, .. } => t,
        }
    }

    /// State at which the integration stopped.
    pub fn y(&self) -> &[f64; N] {
        match self {
            Outcome::Reached { y, .. }
            | Outcome::Event { y, .. }
            | Outcome::Breakpoint { y, .. }
            | Outcome::StepSizeTooSmall { y, .. }
            | Outcome::NonFinite { y, .. }
            | Outcome::MaxSteps { y, .. }
            | Outcome::InvalidInput { y, .. } => y,
        }
    }

    /// True for [`Outcome::Reached`], [`Outcome::Event`] and
    /// [`Outcome::Breakpoint`]: the integration stopped where it was asked
    /// to, not because of a failure.
    pub fn is_success(&self) -> bool {
        matches!(
            self,
            Outcome::Reached { .. } | Outcome::Event { .. } | Outcome::Breakpoint { .. }
        )
    }
}

/// Why an integration stopped short of where it was asked to go without a non-finite value:
/// the integrator gave up. The simulation's failures and the Poincare map's errors carry it.
///
/// Serialised as its text without numbers (`"too many steps"`, `"step size too small"`, or
/// the description of the invalid input), as the JSON of a failed walk has it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GaveUp {
    /// [`Outcome::StepSizeTooSmall`]: the step size fell below the time resolution.
    StepSizeTooSmall {
        /// The step size that was too small.
        h: f64,
    },
    /// [`Outcome::MaxSteps`]: the step budget ran out.
    TooManySteps,
    /// [`Outcome::InvalidInput`]: the integrator's arguments were inconsistent.
    InvalidInput(&'static str),
}

impl GaveUp {
    /// The reason in words, without numbers (`"too many steps"`, ...).
    #[must_use]
    pub fn as_str(&self) -> &'static str {
        match self {
            GaveUp::StepSizeTooSmall { .. } => "step size too small",
            GaveUp::TooManySteps => "too many steps",
            GaveUp::InvalidInput(reason) => reason,
        }
    }
}

impl fmt::Display for GaveUp {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GaveUp::StepSizeTooSmall { h } => write!(f, "step size too small (h = {h:e})"),
            other => f.write_str(other.as_str()),
        }
    }
}

impl std::error::Error for GaveUp {}

impl Serialize for GaveUp {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.as_str())
    }
}
