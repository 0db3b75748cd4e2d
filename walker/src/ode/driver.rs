//! The driver: [`Integrator`] and its loop over attempted steps, with events, breakpoints,
//! observers and failures.

use super::control::{self, Controller, UROUND};
use super::dop853::Dop853;
use super::dopri5::Dopri5;
use super::events::{self, Event};
use super::observer::{Observer, Step};
use super::options::{Config, Method, Tolerances};
use super::outcome::Outcome;
use super::rodas4::Rodas4;
use super::settle::settle;
use super::stats::Stats;
use super::stepper::{Stepper, all_finite};
use super::system::OdeSystem;

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
            let need_events = match events::check_end(events, sys, t_new, &y_new) {
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
