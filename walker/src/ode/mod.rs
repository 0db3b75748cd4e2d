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
mod events;
mod linalg;
mod rodas4;

pub use events::{Direction, Event};
pub use linalg::{Lu, LuError};

use control::{Controller, UROUND};
use dop853::Dop853;
use dopri5::Dopri5;
use rodas4::Rodas4;

/// A system of ordinary differential equations `y' = f(t, y)` with `N`
/// components.
pub trait OdeSystem<const N: usize> {
    /// Evaluate the right-hand side: `dy = f(t, y)`.
    fn rhs(&mut self, t: f64, y: &[f64; N], dy: &mut [f64; N]);

    /// Evaluate the Jacobian `jac[i][j] = d f_i / d y_j` at `(t, y)`.
    ///
    /// Return `false` (the default) if no Jacobian is provided; the stiff
    /// method then uses forward finite differences, column by column, with
    /// the increment `sqrt(eps * max(1e-5, |y_j|))` of Hairer's codes.
    fn jacobian(&mut self, t: f64, y: &[f64; N], jac: &mut [[f64; N]; N]) -> bool {
        let _ = (t, y, jac);
        false
    }

    /// Evaluate the partial derivative `df/dt` at `(t, y)` (used by the
    /// Rosenbrock method for non-autonomous systems).
    ///
    /// Return `false` (the default) to have it computed by a forward finite
    /// difference in `t`; an autonomous system can fill zeros and return
    /// `true` to save one evaluation per step.
    fn time_derivative(&mut self, t: f64, y: &[f64; N], dfdt: &mut [f64; N]) -> bool {
        let _ = (t, y, dfdt);
        false
    }

    /// How many leading components the error test of the attempted step from
    /// `(t0, y0)` to `(t1, y1)` watches (default: all `N`).
    ///
    /// The components after them are carried along by the method (typically
    /// quadratures such as an integral of power, which nothing else depends
    /// on) but cannot cause a rejection of this attempt; the caller is then
    /// responsible for their accuracy on this step, for example where their
    /// integrand has a kink inside it (see [`Observer::wants_step`]). Values
    /// above `N` count as `N`; zero means no error control for this attempt.
    fn controlled_components(&mut self, t0: f64, y0: &[f64; N], t1: f64, y1: &[f64; N]) -> usize {
        let _ = (t0, y0, t1, y1);
        N
    }

    /// The first time strictly after `t` at which the right-hand side is not
    /// smooth (for example the end of a ramp), if any.
    ///
    /// The integrator never lets a step straddle such a point: the step that
    /// reaches it ends exactly on it and [`Integrator::integrate`] returns
    /// [`Outcome::Breakpoint`]. Values that are not strictly after `t` are
    /// ignored. The default has no breakpoints.
    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        let _ = t;
        None
    }
}

/// The integration method.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Dormand–Prince 5(4), 4th-order dense output (Hairer's DOPRI5).
    Dopri5,
    /// Dormand–Prince 8(5,3), 7th-order dense output (Hairer's DOP853).
    Dop853,
    /// Rosenbrock RODAS 4(3), stiffly accurate and L-stable, 3rd-order dense
    /// output (Hairer's RODAS, coefficient set 1).
    Rodas4,
}

impl Method {
    /// Classical order of the propagated solution.
    pub fn order(self) -> u32 {
        match self {
            Method::Dopri5 => 5,
            Method::Dop853 => 8,
            Method::Rodas4 => 4,
        }
    }

    /// Order of the dense output (continuous extension).
    pub fn dense_order(self) -> u32 {
        match self {
            Method::Dopri5 => 4,
            Method::Dop853 => 7,
            Method::Rodas4 => 3,
        }
    }
}

/// Scalar error tolerances: the local error of component `i` is kept below
/// roughly `atol + rtol * |y_i|`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerances {
    /// Relative tolerance (non-negative).
    pub rtol: f64,
    /// Absolute tolerance (non-negative; `rtol` and `atol` not both zero).
    pub atol: f64,
}

impl Tolerances {
    /// Tolerances with the given relative and absolute parts.
    pub fn new(rtol: f64, atol: f64) -> Self {
        Self { rtol, atol }
    }

    fn validate(&self) -> Result<(), &'static str> {
        let ok = self.rtol.is_finite()
            && self.atol.is_finite()
            && self.rtol >= 0.0
            && self.atol >= 0.0
            && (self.rtol > 0.0 || self.atol > 0.0);
        if ok {
            Ok(())
        } else {
            Err("tolerances must be finite, non-negative and not both zero")
        }
    }
}

/// Step-size control settings. [`Config::for_method`] gives Hairer's
/// defaults for each method.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Config {
    /// Maximum number of attempted steps per call to
    /// [`Integrator::integrate`] (Hairer's `NMAX`, default 100 000).
    pub max_steps: usize,
    /// Initial step size; `None` selects it as Hairer's `hinit` does.
    pub h0: Option<f64>,
    /// Maximum step size; `None` means `t_end - t0`.
    pub hmax: Option<f64>,
    /// Safety factor in the step-size prediction (default 0.9).
    pub safety: f64,
    /// Lower bound for the ratio `hnew / h` (0.2 for DOPRI5 and RODAS,
    /// 0.333 for DOP853).
    pub facmin: f64,
    /// Upper bound for the ratio `hnew / h` (10 for DOPRI5, 6 for DOP853 and
    /// RODAS).
    pub facmax: f64,
    /// Lund stabilisation exponent `beta` of the explicit methods (0.04 for
    /// DOPRI5, 0 for DOP853; ignored by RODAS).
    pub beta: f64,
    /// Fixed step size: when set, error control is switched off and every
    /// step has this size (except the last one before `t_end`, a breakpoint
    /// or an event). Meant for convergence studies.
    pub fixed_step: Option<f64>,
}

impl Config {
    /// Hairer's default settings for `method`.
    pub fn for_method(method: Method) -> Self {
        let (facmin, facmax, beta) = match method {
            Method::Dopri5 => (0.2, 10.0, 0.04),
            Method::Dop853 => (0.333, 6.0, 0.0),
            Method::Rodas4 => (0.2, 6.0, 0.0),
        };
        Self {
            max_steps: 100_000,
            h0: None,
            hmax: None,
            safety: 0.9,
            facmin,
            facmax,
            beta,
            fixed_step: None,
        }
    }

    fn validate(&self) -> Result<(), &'static str> {
        let pos = |x: Option<f64>| x.is_none_or(|v| v.is_finite() && v > 0.0);
        if !pos(self.h0) || !pos(self.hmax) || !pos(self.fixed_step) {
            return Err("h0, hmax and fixed_step must be finite and positive");
        }
        if !(self.safety > 1e-4 && self.safety < 1.0) {
            return Err("safety factor must lie in (1e-4, 1)");
        }
        if !(self.facmin > 0.0
            && self.facmin <= 1.0
            && self.facmax >= 1.0
            && self.facmax.is_finite())
        {
            return Err("need 0 < facmin <= 1 <= facmax < inf");
        }
        if !(0.0..=0.2).contains(&self.beta) {
            return Err("beta must lie in [0, 0.2]");
        }
        Ok(())
    }
}

/// Work counters, accumulated over all calls of one [`Integrator`] until
/// [`Integrator::reset_stats`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Evaluations of [`OdeSystem::rhs`] (including those for finite
    /// differences and for the initial step size).
    pub rhs_evals: u64,
    /// Calls of [`OdeSystem::jacobian`] that provided a Jacobian.
    pub jacobian_evals: u64,
    /// Jacobians approximated by finite differences.
    pub fd_jacobians: u64,
    /// LU factorisations of the Rosenbrock iteration matrix.
    pub lu_decompositions: u64,
    /// Accepted steps.
    pub accepted_steps: u64,
    /// Rejected steps (error test failures and attempts that produced
    /// non-finite values).
    pub rejected_steps: u64,
    /// Events reported (terminal and non-terminal).
    pub events: u64,
}

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
    /// The breakpoint `t` given by [`OdeSystem::next_breakpoint`] was reached
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
    /// [`Config::max_steps`] attempts were made without reaching `t_end`.
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

/// Continuous extension of one step, `theta = (t - t_start) / h`.
pub(crate) trait Dense<const N: usize> {
    /// Interpolated state at `theta`.
    fn eval(&self, theta: f64, out: &mut [f64; N]);
    /// Derivative of the interpolant with respect to `theta`.
    fn eval_dtheta(&self, theta: f64, out: &mut [f64; N]);
}

/// One accepted step as shown to an [`Observer`], with its dense output.
///
/// The step covers `[t_start, t_end]`. When a terminal event truncates the
/// step, `t_end` is the event time and `y_end` the state there as returned in
/// [`Outcome::Event`] (from a step ending on the event, so it can differ from
/// the interpolant at `t_end` by the interpolant's error).
pub struct Step<'a, const N: usize> {
    t_start: f64,
    t_end: f64,
    h: f64,
    y_start: &'a [f64; N],
    y_end: &'a [f64; N],
    dense: &'a dyn Dense<N>,
}

impl<const N: usize> Step<'_, N> {
    /// Start time of the step.
    pub fn t_start(&self) -> f64 {
        self.t_start
    }

    /// End time of the step (the event time if a terminal event truncated
    /// it).
    pub fn t_end(&self) -> f64 {
        self.t_end
    }

    /// State at [`Step::t_start`].
    pub fn y_start(&self) -> &[f64; N] {
        self.y_start
    }

    /// State at [`Step::t_end`].
    pub fn y_end(&self) -> &[f64; N] {
        self.y_end
    }

    /// Dense-output state at `t`, meant for `t` in `[t_start, t_end]`
    /// (outside, the interpolant is extrapolated). At the two ends the
    /// stored states are returned exactly.
    pub fn eval(&self, t: f64, out: &mut [f64; N]) {
        if t == self.t_start {
            *out = *self.y_start;
        } else if t == self.t_end {
            *out = *self.y_end;
        } else {
            self.dense.eval((t - self.t_start) / self.h, out);
        }
    }

    /// Time derivative of the dense-output polynomial at `t` (one order less
    /// accurate than [`Step::eval`]).
    pub fn eval_derivative(&self, t: f64, out: &mut [f64; N]) {
        self.dense.eval_dtheta((t - self.t_start) / self.h, out);
        for v in out.iter_mut() {
            *v /= self.h;
        }
    }
}

/// Receives every accepted step and every non-terminal event.
///
/// Any `FnMut(&Step<'_, N>)` closure is an observer (write the parameter type
/// out: `|s: &Step<'_, 3>| ...`). [`NoObserver`] disables the callbacks and
/// saves the dense-output work when no event needs it.
pub trait Observer<const N: usize> {
    /// Whether [`Observer::on_step`] is to be called. When false, the dense
    /// output is only built for steps in which an event must be located.
    const WANTS_STEPS: bool = true;

    /// Whether the accepted step from `(t0, y0)` to `(t1, y1)` is to be
    /// shown to [`Observer::on_step`] (default: every step). Called once per
    /// accepted step when [`Observer::WANTS_STEPS`] is true, before the dense
    /// output is built, so an observer that needs only some steps (those in
    /// which an integrand changes sign, say) saves the interpolation work of
    /// the others. A terminal event may still shorten the step shown.
    fn wants_step(&mut self, t0: f64, y0: &[f64; N], t1: f64, y1: &[f64; N]) -> bool {
        let _ = (t0, y0, t1, y1);
        true
    }

    /// Called after each accepted step that [`Observer::wants_step`] asked
    /// for, in order, before any event of that step is reported. Steps of
    /// zero length (an event at the very start of a step) are not shown.
    fn on_step(&mut self, step: &Step<'_, N>);

    /// Called for each non-terminal event, in time order, after the step
    /// that contains it. Terminal events are returned as
    /// [`Outcome::Event`] instead.
    fn on_event(&mut self, index: usize, t: f64, y: &[f64; N]) {
        let _ = (index, t, y);
    }
}

/// An observer that ignores everything.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoObserver;

impl<const N: usize> Observer<N> for NoObserver {
    const WANTS_STEPS: bool = false;
    fn on_step(&mut self, _step: &Step<'_, N>) {}
}

impl<const N: usize, F: FnMut(&Step<'_, N>)> Observer<N> for F {
    fn on_step(&mut self, step: &Step<'_, N>) {
        self(step);
    }
}

/// How a method wants its step size controlled.
#[derive(Clone, Copy, Debug)]
pub(crate) enum ControlKind {
    /// Hairer's explicit-RK controller with Lund stabilisation:
    /// `expo1 = base - beta * weight`.
    Lund { base: f64, weight: f64 },
    /// Hairer's RODAS controller with Gustafsson's predictive correction,
    /// error exponent `exponent`.
    Predictive { exponent: f64 },
}

/// One-step method with an embedded error estimate and dense output.
pub(crate) trait Stepper<const N: usize>: Dense<N> + Clone {
    /// `IORD` passed to `hinit` (order of the local error estimate).
    const HINIT_ORDER: i32;
    /// Step-size controller.
    const CONTROL: ControlKind;

    /// Begin an integration at `(t, y)`: evaluate `f(t, y)`.
    fn start<S: OdeSystem<N>>(&mut self, sys: &mut S, t: f64, y: &[f64; N], stats: &mut Stats);

    /// `f(t, y)` at the start of the next step.
    fn f0(&self) -> &[f64; N];

    /// Attempt a step of size `h` from `(t, y)`; store the new state and
    /// return the scaled error norm (NaN or infinite when the attempt
    /// failed).
    fn attempt<S: OdeSystem<N>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &[f64; N],
        h: f64,
        tol: &Tolerances,
        stats: &mut Stats,
    ) -> f64;

    /// The state computed by the last attempt.
    fn y_new(&self) -> &[f64; N];

    /// The last attempt was accepted: prepare the next step (`f0` at the new
    /// point) and, if `dense`, the interpolant on `[t, t + h]`.
    fn accept<S: OdeSystem<N>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &[f64; N],
        h: f64,
        dense: bool,
        stats: &mut Stats,
    );
}

/// Evaluate the right-hand side and count it.
#[inline]
pub(crate) fn rhs<S: OdeSystem<N>, const N: usize>(
    sys: &mut S,
    stats: &mut Stats,
    t: f64,
    y: &[f64; N],
    dy: &mut [f64; N],
) {
    stats.rhs_evals += 1;
    sys.rhs(t, y, dy);
}

/// Weighted RMS norm of the first `n` components of `e` with Hairer's scale
/// `atol + rtol * max(|y_i|, |y_new_i|)` (`n` from
/// [`OdeSystem::controlled_components`], clamped to `N`).
pub(crate) fn error_norm<const N: usize>(
    e: &[f64; N],
    y: &[f64; N],
    y_new: &[f64; N],
    tol: &Tolerances,
    n: usize,
) -> f64 {
    let n = n.min(N);
    if n == 0 {
        return 0.0;
    }
    let mut sum = 0.0;
    for i in 0..n {
        let sk = tol.atol + tol.rtol * y[i].abs().max(y_new[i].abs());
        let r = e[i] / sk;
        sum += r * r;
    }
    (sum / n as f64).sqrt()
}

/// The time and state of a terminal event located at `te` in the accepted step from `(t, y)`
/// to `t_new`: the state from steps of the method that end on the event ([`step_to`]), with
/// `te` refined by Newton's method on `g` along the flow (its derivative by a difference along
/// `f`). Each correction aims 16 ulps past the root (later, on the far side). The iteration
/// stops at a correction below 64 ulps of `t` (the time resolution: `g` is then at its rounding
/// level and its sign is noise), or after a correction below `1e-6 (t_new - t)`, which leaves
/// an error of its size times the larger of itself (relative to the step) and the relative
/// local error (the slope is the flow's, not the one-step map's). Where `g` has no simple
/// root (it only touches zero, as the walker's `ydot u` does where the ramp ends at `T_set`)
/// the iteration may not settle: then the iterate with the smallest `|g|` is taken. `None`
/// only if no step to the event passes the error test (the caller keeps the interpolated
/// state).
///
/// Why not the interpolant: it locates the sign change well, but its values are not under
/// error control, and where a fast, strongly damped mode sets the step size (the walker's foot
/// creeping under the `tanh` law) they are far less accurate than the steps' ends: the
/// walker's post-impact velocities were off by up to 4.3e-7 at `rtol = atol = 1e-8` with the
/// interpolated state, and are within 1.0e-8 with this (`walker/tests/sim_stiff.rs`).
/// The usual cost is two steps (26 evaluations with DOP853) per event.
#[allow(clippy::too_many_arguments)]
fn settle<const N: usize, St: Stepper<N>, S: OdeSystem<N>>(
    st: &mut St,
    sys: &mut S,
    ev: &mut Event<'_, N>,
    t: f64,
    y: &[f64; N],
    te: f64,
    t_new: f64,
    tol: &Tolerances,
    stats: &mut Stats,
) -> Option<(f64, [f64; N])> {
    let resolution = |tau: f64| 16.0 * f64::EPSILON * tau.abs();
    let mut tau = te;
    let mut best: Option<(f64, f64, [f64; N])> = None;
    for _ in 0..4 {
        let Some(y_tau) = step_to(st, sys, t, y, tau, tol, stats) else {
            break;
        };
        let g = ev.value(tau, &y_tau);
        if g == 0.0 {
            return Some((tau, y_tau));
        }
        if !g.is_finite() {
            break;
        }
        if best.is_none_or(|(b, ..)| g.abs() < b) {
            best = Some((g.abs(), tau, y_tau));
        }
        // Newton's correction along the flow.
        let mut f = [0.0; N];
        rhs(sys, stats, tau, &y_tau, &mut f);
        let eps = 1e-7 * (t_new - t);
        let mut y_eps = y_tau;
        for (v, d) in y_eps.iter_mut().zip(&f) {
            *v += eps * d;
        }
        let dt = -g * eps / (ev.value(tau + eps, &y_eps) - g);
        if !dt.is_finite() {
            break;
        }
        if dt.abs() <= 4.0 * resolution(tau) {
            return Some((tau, y_tau));
        }
        let next = tau + dt + resolution(tau);
        if !(next > t && next <= t_new) {
            break;
        }
        tau = next;
        if dt.abs() <= 1e-6 * (t_new - t) {
            // Small enough for a last correction: what it leaves is of order dt times the
            // larger of dt / (t_new - t) and the relative local error.
            return step_to(st, sys, t, y, tau, tol, stats)
                .map(|y_tau| (tau, y_tau))
                .or_else(|| best.map(|(_, tb, yb)| (tb, yb)));
        }
    }
    best.map(|(_, tau, y_tau)| (tau, y_tau))
}

/// The state at `t_end` in `(t, t + h]` by fresh steps of the method from `(t, y)`, where `h`
/// is an accepted step: one step of `t_end - t`, or, if its error test fails, 2, 4 or 8 equal
/// steps. `None` if none of these passes or `t_end <= t`. Overwrites the stepper's storage.
fn step_to<const N: usize, St: Stepper<N>, S: OdeSystem<N>>(
    st: &mut St,
    sys: &mut S,
    t: f64,
    y: &[f64; N],
    t_end: f64,
    tol: &Tolerances,
    stats: &mut Stats,
) -> Option<[f64; N]> {
    if t_end <= t {
        return None;
    }
    'split: for parts in [1u32, 2, 4, 8] {
        let h = (t_end - t) / f64::from(parts);
        let (mut tk, mut yk) = (t, *y);
        st.start(sys, tk, &yk, stats);
        for k in 1..=parts {
            let hk = if k == parts { t_end - tk } else { h };
            let err = st.attempt(sys, tk, &yk, hk, tol, stats);
            if !(err <= 1.0 && all_finite(st.y_new())) {
                continue 'split;
            }
            if k < parts {
                st.accept(sys, tk, &yk, hk, false, stats);
            }
            yk = *st.y_new();
            tk = if k == parts { t_end } else { tk + hk };
        }
        return Some(yk);
    }
    None
}

fn all_finite<const N: usize>(y: &[f64; N]) -> bool {
    y.iter().all(|v| v.is_finite())
}

#[allow(clippy::large_enum_variant)]
enum AnyStepper<const N: usize> {
    Dopri5(Dopri5<N>),
    Dop853(Dop853<N>),
    Rodas4(Rodas4<N>),
}

/// An adaptive integrator for systems with `N` components.
///
/// It owns the stage storage of its method (allocated once, in
/// [`Integrator::new`]), its tolerances, settings and work counters.
pub struct Integrator<const N: usize> {
    method: Method,
    tol: Tolerances,
    config: Config,
    stats: Stats,
    stepper: Box<AnyStepper<N>>,
}

impl<const N: usize> Integrator<N> {
    /// An integrator with Hairer's default settings for `method`.
    pub fn new(method: Method, tol: Tolerances) -> Self {
        Self::with_config(method, tol, Config::for_method(method))
    }

    /// An integrator with explicit settings.
    pub fn with_config(method: Method, tol: Tolerances, config: Config) -> Self {
        let stepper = Box::new(match method {
            Method::Dopri5 => AnyStepper::Dopri5(Dopri5::new()),
            Method::Dop853 => AnyStepper::Dop853(Dop853::new()),
            Method::Rodas4 => AnyStepper::Rodas4(Rodas4::new()),
        });
        Self {
            method,
            tol,
            config,
            stats: Stats::default(),
            stepper,
        }
    }

    /// The method in use.
    pub fn method(&self) -> Method {
        self.method
    }

    /// Current tolerances.
    pub fn tolerances(&self) -> Tolerances {
        self.tol
    }

    /// Change the tolerances for the following calls.
    pub fn set_tolerances(&mut self, tol: Tolerances) {
        self.tol = tol;
    }

    /// Current settings.
    pub fn config(&self) -> &Config {
        &self.config
    }

    /// Mutable access to the settings for the following calls.
    pub fn config_mut(&mut self) -> &mut Config {
        &mut self.config
    }

    /// Work counters accumulated so far.
    pub fn stats(&self) -> &Stats {
        &self.stats
    }

    /// Reset the work counters to zero.
    pub fn reset_stats(&mut self) {
        self.stats = Stats::default();
    }

    /// Integrate `sys` from `(t0, y0)` towards `t_end >= t0`.
    ///
    /// Stops at `t_end`, at the first terminal event, at the next breakpoint
    /// of the system, or on failure; see [`Outcome`]. Non-terminal events and
    /// accepted steps are reported to `observer` as they happen. Pass
    /// `&mut []` for no events and `&mut NoObserver` for no observer.
    pub fn integrate<S: OdeSystem<N>, O: Observer<N>>(
        &mut self,
        sys: &mut S,
        t0: f64,
        y0: &[f64; N],
        t_end: f64,
        events: &mut [Event<'_, N>],
        observer: &mut O,
    ) -> Outcome<N> {
        let run = Run {
            config: &self.config,
            tol: &self.tol,
            stats: &mut self.stats,
        };
        match self.stepper.as_mut() {
            AnyStepper::Dopri5(st) => run.go(st, sys, t0, y0, t_end, events, observer),
            AnyStepper::Dop853(st) => run.go(st, sys, t0, y0, t_end, events, observer),
            AnyStepper::Rodas4(st) => run.go(st, sys, t0, y0, t_end, events, observer),
        }
    }
}

/// Consecutive attempts producing non-finite values tolerated (each one
/// divides the step size by 4) before giving up with
/// [`Outcome::NonFinite`].
const MAX_NONFINITE_ATTEMPTS: u32 = 30;

/// Borrowed settings for one call of [`Integrator::integrate`].
struct Run<'a> {
    config: &'a Config,
    tol: &'a Tolerances,
    stats: &'a mut Stats,
}

impl Run<'_> {
    #[allow(clippy::too_many_arguments)]
    fn go<const N: usize, St: Stepper<N>, S: OdeSystem<N>, O: Observer<N>>(
        self,
        st: &mut St,
        sys: &mut S,
        t0: f64,
        y0: &[f64; N],
        t_end: f64,
        events: &mut [Event<'_, N>],
        obs: &mut O,
    ) -> Outcome<N> {
        let Run { config, tol, stats } = self;
        let invalid = |reason| Outcome::InvalidInput {
            t: t0,
            y: *y0,
            reason,
        };
        if !t0.is_finite() || !t_end.is_finite() {
            return invalid("t0 and t_end must be finite");
        }
        if t_end < t0 {
            return invalid("only forward integration (t_end >= t0) is supported");
        }
        if let Err(reason) = tol.validate().and_then(|()| config.validate()) {
            return invalid(reason);
        }
        if !all_finite(y0) {
            return Outcome::NonFinite { t: t0, y: *y0 };
        }

        let mut t = t0;
        let mut y = *y0;
        if events::start(events, t, &y).is_err() {
            return Outcome::NonFinite { t, y };
        }
        if t_end == t0 {
            return Outcome::Reached { t, y };
        }

        let target = match sys.next_breakpoint(t0) {
            Some(b) if b > t0 && b < t_end => b,
            _ => t_end,
        };

        st.start(sys, t, &y, stats);
        if !all_finite(st.f0()) {
            return Outcome::NonFinite { t, y };
        }

        let hmax = config.hmax.map_or(t_end - t0, |m| m.min(t_end - t0));
        let mut h = match (config.fixed_step, config.h0) {
            (Some(hf), _) => hf,
            (None, Some(h0)) => h0.min(hmax),
            (None, None) => control::hinit(sys, t, &y, st.f0(), St::HINIT_ORDER, hmax, tol, stats),
        };
        let mut controller = Controller::new(St::CONTROL, config);
        let mut reject = false;
        let mut attempts = 0usize;
        let mut nonfinite_streak = 0u32;

        loop {
            if attempts >= config.max_steps {
                return Outcome::MaxSteps { t, y };
            }
            if !(h.is_finite() && 0.1 * h.abs() > t.abs() * UROUND) {
                return if nonfinite_streak > 0 {
                    Outcome::NonFinite { t, y }
                } else {
                    Outcome::StepSizeTooSmall { t, y, h }
                };
            }
            let mut last = false;
            if t + 1.01 * h >= target {
                h = target - t;
                last = true;
            }
            attempts += 1;

            let err = st.attempt(sys, t, &y, h, tol, stats);
            if !(err.is_finite() && all_finite(st.y_new())) {
                stats.rejected_steps += 1;
                nonfinite_streak += 1;
                if config.fixed_step.is_some() || nonfinite_streak >= MAX_NONFINITE_ATTEMPTS {
                    return Outcome::NonFinite { t, y };
                }
                h *= 0.25;
                reject = true;
                continue;
            }
            nonfinite_streak = 0;

            let (accepted, mut h_new) = match config.fixed_step {
                Some(hf) => (true, hf),
                None => controller.propose(err, h),
            };
            if !accepted {
                stats.rejected_steps += 1;
                reject = true;
                h = h_new;
                continue;
            }

            // ---- The step is accepted. ----
            stats.accepted_steps += 1;
            let t_new = if last { target } else { t + h };
            let y_new = *st.y_new();
            let need_events = match events::check_end(events, t_new, &y_new) {
                Ok(need) => need,
                Err(()) => return Outcome::NonFinite { t: t_new, y: y_new },
            };
            let show = O::WANTS_STEPS && obs.wants_step(t, &y, t_new, &y_new);
            st.accept(sys, t, &y, h, need_events || show, stats);

            let span = events::Span {
                t0: t,
                t1: t_new,
                h,
                y0: &y,
                y1: &y_new,
                dense: &*st,
            };
            let hit = if need_events {
                match events::locate(events, &span) {
                    Ok(hit) => hit,
                    Err(bad_t) => {
                        let mut yb = [0.0; N];
                        span.state_at(bad_t, &mut yb);
                        return Outcome::NonFinite { t: bad_t, y: yb };
                    }
                }
            } else {
                None
            };

            // At a terminal event, the state comes from steps of the method that end on the
            // event (see `settle`), on a copy of the stepper: the observer still sees this
            // step's interpolant.
            let (t_stop, y_stop, g_far) = match hit {
                Some((index, te)) => {
                    let mut y_te = [0.0; N];
                    span.state_at(te, &mut y_te);
                    let mut copy = st.clone();
                    let ev = &mut events[index];
                    let g_far = ev.value(t_new, &y_new);
                    settle(&mut copy, sys, ev, t, &y, te, t_new, tol, stats)
                        .map_or((te, y_te, g_far), |(ts, ys)| (ts, ys, g_far))
                }
                None => (t_new, y_new, 0.0),
            };
            if show && t_stop > t {
                obs.on_step(&Step {
                    t_start: t,
                    t_end: t_stop,
                    h,
                    y_start: &y,
                    y_end: &y_stop,
                    dense: &*st,
                });
            }
            if need_events {
                stats.events += events::report_non_terminal(events, &span, t_stop, obs);
            }
            if let Some((index, _)) = hit {
                stats.events += 1;
                events[index].mark_fired(t_stop, &y_stop, g_far);
                return Outcome::Event {
                    index,
                    t: t_stop,
                    y: y_stop,
                };
            }
            events::commit(events, t_new);

            t = t_new;
            y = y_new;
            if !all_finite(st.f0()) {
                return Outcome::NonFinite { t, y };
            }
            if last {
                return if target == t_end {
                    Outcome::Reached { t, y }
                } else {
                    Outcome::Breakpoint { t, y }
                };
            }
            if config.fixed_step.is_none() {
                h_new = h_new.min(hmax);
                if reject {
                    h_new = h_new.min(h);
                }
            }
            reject = false;
            h = h_new;
        }
    }
}
