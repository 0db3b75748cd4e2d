//! Adaptive ODE integrators with dense output, event location and breakpoints.
//!
//! The state is a fixed-size array `[f64; N]`; nothing is allocated on the
//! heap while stepping. Three methods are available (see [`Method`]):
//!
//! * [`Method::Dopri5`]: Dormand–Prince 5(4) with Shampine's 4th-order dense
//!   output, as in Hairer's `dopri5.f`;
//! * [`Method::Dop853`]: Dormand–Prince 8(5,3) with the 7th-order dense output
//!   (three extra stages per step when the interpolant is needed), as in
//!   Hairer's `dop853.f`;
//! * [`Method::Rodas4`]: the stiffly accurate, L-stable Rosenbrock method
//!   RODAS of order 4(3) with 3rd-order dense output, as in Hairer's
//!   `rodas.f`. It uses the system's Jacobian ([`OdeSystem::jacobian`]) or
//!   finite differences when none is provided.
//!
//! Step-size control follows Hairer's codes: error norm
//! `sqrt(mean((e_i / (atol + rtol * max(|y_i|, |ynew_i|)))^2))`, safety factor
//! 0.9, ratio bounds `facmin <= hnew/h <= facmax`, Lund stabilisation for the
//! explicit methods, Gustafsson's predictive controller for RODAS, initial
//! step from Hairer's `hinit`, steps limited by `hmax` and by the end time,
//! and no step-size increase directly after a rejection.
//!
//! # Driving an integration
//!
//! [`Integrator::integrate`] runs from `t0` to `t_end` and returns an
//! [`Outcome`]: either the end was reached, or a terminal event fired, or a
//! declared breakpoint ([`OdeSystem::next_breakpoint`]) was reached, or the
//! integration failed (step size too small, non-finite values, too many
//! steps). Failures are values, never panics, and no outcome ever carries a
//! NaN produced by the integrator without saying so ([`Outcome::NonFinite`]).
//! To continue after an event or a breakpoint, call `integrate` again from the
//! returned time and state (after applying any reset map).
//!
//! Every accepted step is shown to an [`Observer`] as a [`Step`], which gives
//! access to the dense output on that step (for plots, sampling, or
//! quadrature of derived quantities). Quantities whose integral must be as
//! accurate as the solution itself are best added as extra state components
//! (quadrature variables): they are then under error control.
//!
//! Events ([`Event`]) are located on the dense output; the rule that
//! decides what counts as a crossing, in particular when an integration
//! starts on a guard, is documented on [`Event`]. The state returned at a
//! terminal event is not interpolated: the step that contains the event is
//! taken again, ending on it, because the interpolant is not under error
//! control and can be much less accurate than the steps' ends where a
//! strongly damped mode limits the step size.

mod control;
mod dop853;
mod dopri5;
mod driver;
mod events;
mod linalg;
mod observer;
mod options;
mod outcome;
mod rodas4;
mod settle;
mod stats;
mod stepper;
mod system;

pub use driver::Integrator;
pub use events::{Direction, Event};
pub use linalg::{Lu, LuError};
pub use observer::{NoObserver, Observer, Step};
pub use options::{Config, Method, Tolerances};
pub use outcome::{GaveUp, Outcome};
pub use stats::Stats;
pub use system::OdeSystem;
