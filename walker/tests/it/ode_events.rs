//! Event location, the start-on-guard rule, breakpoints and failure
//! outcomes.

#![allow(clippy::panic)] // tests report failures by panicking

use std::f64::consts::PI;

use walker::ode::{
    Config, Direction, Event, Integrator, Method, NoObserver, Observer, OdeSystem, Outcome, Step,
    Tolerances,
};

const METHODS: [Method; 3] = [Method::Dopri5, Method::Dop853, Method::Rodas4];

/// x'' = -x.
struct Oscillator;

impl OdeSystem<2> for Oscillator {
    fn rhs(&mut self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        dy[0] = y[1];
        dy[1] = -y[0];
    }
}

/// Free fall: height and velocity.
struct Ball {
    g: f64,
}

impl OdeSystem<2> for Ball {
    fn rhs(&mut self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        dy[0] = y[1];
        dy[1] = -self.g;
    }
}

/// Records non-terminal events and step ends.
#[derive(Default)]
struct Recorder {
    events: Vec<(usize, f64)>,
    step_ends: Vec<f64>,
}

impl<const N: usize> Observer<N> for Recorder {
    fn on_step(&mut self, step: &Step<'_, N>) {
        self.step_ends.push(step.t_end());
    }
    fn on_event(&mut self, index: usize, t: f64, _y: &[f64; N]) {
        self.events.push((index, t));
    }
}

fn ulps_apart(a: f64, b: f64) -> f64 {
    (a - b).abs() / (f64::EPSILON * a.abs().max(b.abs()))
}

#[test]
fn harmonic_oscillator_zero_crossings_and_directions() {
    // x = cos t crosses zero at (k + 1/2) pi: falling at pi/2 + 2k pi,
    // rising at 3pi/2 + 2k pi. Three non-terminal events on the same
    // function, one per direction filter.
    let t_end = 20.0;
    let mut ig = Integrator::new(Method::Dop853, Tolerances::new(1e-13, 1e-13));
    let mut events = [
        Event::non_terminal(Direction::Either, |_, y: &[f64; 2]| y[0]),
        Event::non_terminal(Direction::Rising, |_, y: &[f64; 2]| y[0]),
        Event::non_terminal(Direction::Falling, |_, y: &[f64; 2]| y[0]),
    ];
    let mut rec = Recorder::default();
    let out = ig.integrate(
        &mut Oscillator,
        0.0,
        &[1.0, 0.0],
        t_end,
        &mut events,
        &mut rec,
    );
    assert!(matches!(out, Outcome::Reached { .. }), "{out:?}");

    let zeros: Vec<f64> = (0..7)
        .map(|k| (f64::from(k) + 0.5) * PI)
        .filter(|&t| t < t_end)
        .collect();
    let either: Vec<f64> = rec
        .events
        .iter()
        .filter(|e| e.0 == 0)
        .map(|e| e.1)
        .collect();
    let rising: Vec<f64> = rec
        .events
        .iter()
        .filter(|e| e.0 == 1)
        .map(|e| e.1)
        .collect();
    let falling: Vec<f64> = rec
        .events
        .iter()
        .filter(|e| e.0 == 2)
        .map(|e| e.1)
        .collect();
    assert_eq!(either.len(), zeros.len());
    assert_eq!(rising.len(), zeros.len() / 2);
    assert_eq!(falling.len(), zeros.len() - zeros.len() / 2);
    let mut worst: f64 = 0.0;
    for (k, &z) in zeros.iter().enumerate() {
        worst = worst.max((either[k] - z).abs() / z);
        let (list, j) = if k % 2 == 0 {
            (&falling, k / 2)
        } else {
            (&rising, k / 2)
        };
        assert_eq!(list[j], either[k], "same function, same root");
    }
    // The root itself is located to a few ulps on the interpolant; what is
    // left is the integration error at rtol = atol = 1e-13.
    eprintln!("oscillator zero crossings: worst relative error {worst:.2e}");
    assert!(
        worst < 5e-14,
        "worst relative error of event times {worst:e}"
    );
    // Reported in time order.
    assert!(rec.events.windows(2).all(|w| w[0].1 <= w[1].1));
    assert_eq!(ig.stats().events as usize, rec.events.len());
}

#[test]
fn falling_ball_hits_the_ground_at_the_exact_time() {
    // h(t) = h0 - g t^2 / 2 is a quadratic: every method and every dense
    // output here is exact on it up to rounding, so the located time must
    // agree with sqrt(2 h0 / g) to a few ulps.
    let (h0, g): (f64, f64) = (10.0, 9.81);
    let exact = (2.0 * h0 / g).sqrt();
    for m in METHODS {
        let mut ig = Integrator::new(m, Tolerances::new(1e-8, 1e-8));
        let mut events = [Event::terminal(Direction::Falling, |_, y: &[f64; 2]| y[0])];
        let out = ig.integrate(
            &mut Ball { g },
            0.0,
            &[h0, 0.0],
            10.0,
            &mut events,
            &mut NoObserver,
        );
        let Outcome::Event { index, t, y } = out else {
            panic!("{m:?}: expected an event, got {out:?}");
        };
        assert_eq!(index, 0);
        let ulps = ulps_apart(t, exact);
        eprintln!("{m:?}: ball lands {ulps:.1} ulps from sqrt(2 h0 / g)");
        assert!(ulps <= 16.0, "{m:?}: t = {t}, exact {exact}, {ulps} ulps");
        // The state is on the guard to rounding: the height's rounding level at
        // h0 = 10 is ~2e-15, and within the time resolution (64 ulps of t ~ 2e-14 s at
        // ~14 m/s) it moves by ~3e-13.
        assert!(y[0].abs() < 1e-12, "{m:?}: height {:e}", y[0]);
        assert!((y[1] + g * exact).abs() < 1e-12);
    }
}

#[test]
fn bouncing_ball_restarts_on_the_guard_without_false_events() {
    // Each bounce resets v -> -e v and restarts from the event point, where
    // the height is zero up to rounding (either sign). The event is Falling,
    // the ball leaves the ground upwards: no event at the restart. Bounce k
    // happens at t1 + sum_{j=1}^{k-1} 2 e^j v1 / g.
    let (h0, g, e): (f64, f64, f64) = (10.0, 9.81, 0.7);
    let t1 = (2.0 * h0 / g).sqrt();
    let v1 = g * t1;
    for m in METHODS {
        let mut ig = Integrator::new(m, Tolerances::new(1e-10, 1e-10));
        let mut events = [Event::terminal(Direction::Falling, |_, y: &[f64; 2]| y[0])];
        let mut t = 0.0;
        let mut y = [h0, 0.0];
        let mut exact = t1;
        for k in 1..=6 {
            let out = ig.integrate(&mut Ball { g }, t, &y, 100.0, &mut events, &mut NoObserver);
            let Outcome::Event { t: te, y: ye, .. } = out else {
                panic!("{m:?} bounce {k}: expected an event, got {out:?}");
            };
            assert!(te > t, "{m:?} bounce {k}: event at the restart point");
            assert!(
                (te - exact).abs() < 1e-12 * exact,
                "{m:?} bounce {k}: {te} vs {exact}"
            );
            t = te;
            y = [ye[0], -e * ye[1]];
            exact += 2.0 * e.powi(k) * v1 / g;
        }
        assert_eq!(ig.stats().events, 6);
    }
}

#[test]
fn no_false_event_at_t0_on_the_guard() {
    let tol = Tolerances::new(1e-12, 1e-12);
    for m in METHODS {
        // x = sin t starts on the guard moving up: a Falling event must not
        // fire at t0; it fires at the genuine falling crossing t = pi.
        let mut ig = Integrator::new(m, tol);
        let mut ev = [Event::terminal(Direction::Falling, |_, y: &[f64; 2]| y[0])];
        let out = ig.integrate(
            &mut Oscillator,
            0.0,
            &[0.0, 1.0],
            10.0,
            &mut ev,
            &mut NoObserver,
        );
        let Outcome::Event { t, .. } = out else {
            panic!("{m:?}: {out:?}")
        };
        assert!((t - PI).abs() < 1e-9, "{m:?}: falling event at {t}");

        // Either: a zero start is never reported.
        let mut ev = [Event::terminal(Direction::Either, |_, y: &[f64; 2]| y[0])];
        let out = ig.integrate(
            &mut Oscillator,
            0.0,
            &[0.0, 1.0],
            10.0,
            &mut ev,
            &mut NoObserver,
        );
        let Outcome::Event { t, .. } = out else {
            panic!("{m:?}: {out:?}")
        };
        assert!((t - PI).abs() < 1e-9, "{m:?}: either event at {t}");

        // x = -sin t starts on the guard moving down, i.e. in the direction
        // of a Falling event: that is a genuine crossing at t0 itself.
        let y0 = [0.0, -1.0];
        let mut ev = [Event::terminal(Direction::Falling, |_, y: &[f64; 2]| y[0])];
        let out = ig.integrate(&mut Oscillator, 0.0, &y0, 10.0, &mut ev, &mut NoObserver);
        assert_eq!(
            out,
            Outcome::Event {
                index: 0,
                t: 0.0,
                y: y0
            },
            "{m:?}"
        );

        // ... while a Rising event ignores that departure and fires at pi.
        let mut ev = [Event::terminal(Direction::Rising, |_, y: &[f64; 2]| y[0])];
        let out = ig.integrate(&mut Oscillator, 0.0, &y0, 10.0, &mut ev, &mut NoObserver);
        let Outcome::Event { t, .. } = out else {
            panic!("{m:?}: {out:?}")
        };
        assert!((t - PI).abs() < 1e-9, "{m:?}: rising event at {t}");
    }
}

/// y' = 1 (so y = t): trivially integrated with long steps.
struct Clock;

impl OdeSystem<1> for Clock {
    fn rhs(&mut self, _t: f64, _y: &[f64; 1], dy: &mut [f64; 1]) {
        dy[0] = 1.0;
    }
}

#[test]
fn early_dip_in_the_event_direction_is_seen_within_a_long_first_step() {
    // g = y (y - 0.05) starts at zero, is negative on (0, 0.05) and positive
    // after: it leaves the guard in the Falling direction. The first step is
    // far longer than 0.05; the guard is sampled near the start of the step,
    // so the departure is still seen and reported at t0.
    for m in METHODS {
        let mut ig = Integrator::new(m, Tolerances::new(1e-6, 1e-6));
        let mut rec = Recorder::default();
        let mut ev = [Event::terminal(Direction::Falling, |_, y: &[f64; 1]| {
            y[0] * (y[0] - 0.05)
        })];
        let out = ig.integrate(&mut Clock, 0.0, &[0.0], 10.0, &mut ev, &mut rec);
        assert_eq!(
            out,
            Outcome::Event {
                index: 0,
                t: 0.0,
                y: [0.0]
            },
            "{m:?}"
        );
        // A Rising event on the same function fires at the crossing 0.05.
        let mut ev = [Event::terminal(Direction::Rising, |_, y: &[f64; 1]| {
            y[0] * (y[0] - 0.05)
        })];
        let out = ig.integrate(&mut Clock, 0.0, &[0.0], 10.0, &mut ev, &mut rec);
        let Outcome::Event { t, .. } = out else {
            panic!("{m:?}: {out:?}")
        };
        assert!(ulps_apart(t, 0.05) <= 4.0, "{m:?}: {t}");
    }
}

#[test]
fn resuming_from_a_terminal_event_exactly_on_the_guard() {
    // Fixed steps of 1/4 land exactly on t = 1, where the time event
    // g = t - 1 is exactly zero; the crossing is confirmed by the next step
    // and reported at t = 1 with g = 0.
    let mut cfg = Config::for_method(Method::Dopri5);
    cfg.fixed_step = Some(0.25);
    let mut ig = Integrator::with_config(Method::Dopri5, Tolerances::new(1e-8, 1e-8), cfg);
    let mut ev = [Event::terminal(Direction::Rising, |t, _: &[f64; 1]| {
        t - 1.0
    })];
    let out = ig.integrate(&mut Clock, 0.0, &[0.0], 3.0, &mut ev, &mut NoObserver);
    let Outcome::Event { t, y, .. } = out else {
        panic!("{out:?}")
    };
    assert_eq!(t, 1.0);
    assert_eq!(ev[0].value(t, &y), 0.0);

    // Continuing from exactly that point: the crossing was already
    // reported, so it does not fire again.
    let out = ig.integrate(&mut Clock, t, &y, 3.0, &mut ev, &mut NoObserver);
    assert!(matches!(out, Outcome::Reached { t: 3.0, .. }), "{out:?}");

    // After a reset (a different state) or once the event forgot where it
    // fired, a start on the guard that moves in the event direction is a
    // genuine event at t0.
    let out = ig.integrate(&mut Clock, t, &[5.0], 3.0, &mut ev, &mut NoObserver);
    assert_eq!(
        out,
        Outcome::Event {
            index: 0,
            t: 1.0,
            y: [5.0]
        }
    );
    ev[0].forget_last_firing();
    let out = ig.integrate(&mut Clock, t, &[5.0], 3.0, &mut ev, &mut NoObserver);
    assert_eq!(
        out,
        Outcome::Event {
            index: 0,
            t: 1.0,
            y: [5.0]
        }
    );
    let out = ig.integrate(&mut Clock, t, &y, 3.0, &mut ev, &mut NoObserver);
    assert!(matches!(out, Outcome::Event { t: 1.0, .. }), "{out:?}");
}

#[test]
fn terminal_and_non_terminal_events_in_one_step() {
    // cos t = 0.5 at pi/3 (non-terminal), cos t = 0 at pi/2 (terminal),
    // cos t = -0.5 at 2 pi/3 (non-terminal, after the stop: not reported).
    // A loose tolerance makes the steps long enough to hold several events.
    for m in METHODS {
        let mut ig = Integrator::new(m, Tolerances::new(1e-3, 1e-3));
        let mut events = [
            Event::non_terminal(Direction::Either, |_, y: &[f64; 2]| y[0] + 0.5),
            Event::terminal(Direction::Falling, |_, y: &[f64; 2]| y[0]),
            Event::non_terminal(Direction::Falling, |_, y: &[f64; 2]| y[0] - 0.5),
        ];
        let mut rec = Recorder::default();
        let out = ig.integrate(
            &mut Oscillator,
            0.0,
            &[1.0, 0.0],
            10.0,
            &mut events,
            &mut rec,
        );
        let Outcome::Event { index, t, y } = out else {
            panic!("{m:?}: {out:?}")
        };
        assert_eq!(index, 1);
        assert!((t - PI / 2.0).abs() < 1e-2, "{m:?}: {t}");
        // On the guard: the time is refined by Newton on steps that end on the event, the
        // last correction (at most 1e-6 of the step, ~5e-7 here) leaving an error of its
        // size times the local error's relative size (~tol = 1e-3): below 1e-9.
        assert!(y[0].abs() < 1e-9, "{m:?}: x = {:e} at the event", y[0]);
        assert_eq!(rec.events.len(), 1, "{m:?}: {:?}", rec.events);
        assert_eq!(rec.events[0].0, 2);
        assert!((rec.events[0].1 - PI / 3.0).abs() < 1e-2);
        // The last step shown to the observer ends at the event.
        assert_eq!(rec.step_ends.last().copied(), Some(t));
        assert_eq!(ig.stats().events, 2);
    }
}

#[test]
fn earliest_terminal_event_wins() {
    let mut ig = Integrator::new(Method::Dop853, Tolerances::new(1e-12, 1e-12));
    let mut events = [
        Event::terminal(Direction::Falling, |_, y: &[f64; 2]| y[0]),
        Event::terminal(Direction::Falling, |_, y: &[f64; 2]| y[0] - 0.5),
    ];
    let out = ig.integrate(
        &mut Oscillator,
        0.0,
        &[1.0, 0.0],
        10.0,
        &mut events,
        &mut NoObserver,
    );
    let Outcome::Event { index, t, .. } = out else {
        panic!("{out:?}")
    };
    assert_eq!(index, 1);
    assert!((t - PI / 3.0).abs() < 1e-11, "{t}");
}

/// y' = ramp(t): t / T before T, 1 after; breakpoint at T (optional).
struct Ramp {
    t_set: f64,
    declare: bool,
}

impl OdeSystem<1> for Ramp {
    fn rhs(&mut self, t: f64, _y: &[f64; 1], dy: &mut [f64; 1]) {
        dy[0] = (t / self.t_set).min(1.0);
    }
    fn time_derivative(&mut self, t: f64, _y: &[f64; 1], dfdt: &mut [f64; 1]) -> bool {
        // The slope of the branch the step starts on.
        dfdt[0] = if t < self.t_set {
            1.0 / self.t_set
        } else {
            0.0
        };
        true
    }
    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        (self.declare && t < self.t_set).then_some(self.t_set)
    }
}

#[test]
fn breakpoint_ends_a_step_exactly_and_the_caller_continues() {
    let t_set = 0.7;
    let exact = |t: f64| {
        if t <= t_set {
            t * t / (2.0 * t_set)
        } else {
            t_set / 2.0 + (t - t_set)
        }
    };
    for m in METHODS {
        let mut ig = Integrator::new(m, Tolerances::new(1e-10, 1e-10));
        let mut sys = Ramp {
            t_set,
            declare: true,
        };
        let mut rec = Recorder::default();
        let out = ig.integrate(&mut sys, 0.0, &[0.0], 3.0, &mut [], &mut rec);
        let Outcome::Breakpoint { t, y } = out else {
            panic!("{m:?}: {out:?}")
        };
        assert_eq!(
            t, t_set,
            "{m:?}: the step must end exactly on the breakpoint"
        );
        assert!(
            rec.step_ends.iter().all(|&te| te <= t_set),
            "{m:?}: a step straddled T"
        );
        assert_eq!(rec.step_ends.last().copied(), Some(t_set));
        assert!(
            (y[0] - exact(t_set)).abs() < 1e-14,
            "{m:?}: {:e}",
            y[0] - exact(t_set)
        );
        // Continue from the breakpoint; no further breakpoint after it.
        let out = ig.integrate(&mut sys, t, &y, 3.0, &mut [], &mut rec);
        let Outcome::Reached { t, y } = out else {
            panic!("{m:?}: {out:?}")
        };
        assert_eq!(t, 3.0);
        assert!(
            (y[0] - exact(3.0)).abs() < 1e-13,
            "{m:?}: {:e}",
            y[0] - exact(3.0)
        );
        // Both pieces are polynomials of low degree: no step is rejected.
        assert_eq!(ig.stats().rejected_steps, 0, "{m:?}: {:?}", ig.stats());

        // Without the declaration the error estimate straddles the kink:
        // rejected steps, and a less accurate result.
        let mut ig2 = Integrator::new(m, Tolerances::new(1e-10, 1e-10));
        let mut undeclared = Ramp {
            t_set,
            declare: false,
        };
        let out = ig2.integrate(&mut undeclared, 0.0, &[0.0], 3.0, &mut [], &mut NoObserver);
        assert!(matches!(out, Outcome::Reached { .. }));
        assert!(ig2.stats().rejected_steps > 0, "{m:?}: {:?}", ig2.stats());
    }
}

#[test]
fn breakpoints_at_or_outside_the_interval_are_ignored() {
    let mut ig = Integrator::new(Method::Dopri5, Tolerances::new(1e-8, 1e-8));
    // At t_end: a plain Reached.
    let mut sys = Ramp {
        t_set: 1.0,
        declare: true,
    };
    let out = ig.integrate(&mut sys, 0.0, &[0.0], 1.0, &mut [], &mut NoObserver);
    assert!(matches!(out, Outcome::Reached { t: 1.0, .. }), "{out:?}");
    // Beyond t_end.
    let out = ig.integrate(&mut sys, 0.0, &[0.0], 0.5, &mut [], &mut NoObserver);
    assert!(matches!(out, Outcome::Reached { t: 0.5, .. }), "{out:?}");
    // Starting on it: it is not strictly after t0.
    let out = ig.integrate(&mut sys, 1.0, &[0.5], 2.0, &mut [], &mut NoObserver);
    assert!(matches!(out, Outcome::Reached { t: 2.0, .. }), "{out:?}");
}

/// y' = 1 until t = 1, then NaN.
struct Poisoned;

impl OdeSystem<1> for Poisoned {
    fn rhs(&mut self, t: f64, _y: &[f64; 1], dy: &mut [f64; 1]) {
        dy[0] = if t > 1.0 { f64::NAN } else { 1.0 };
    }
}

/// y' = y^2, y(0) = 1: blows up at t = 1.
struct BlowUp;

impl OdeSystem<1> for BlowUp {
    fn rhs(&mut self, _t: f64, y: &[f64; 1], dy: &mut [f64; 1]) {
        dy[0] = y[0] * y[0];
    }
}

#[test]
fn non_finite_values_are_reported_not_returned() {
    for m in METHODS {
        let mut ig = Integrator::new(m, Tolerances::new(1e-8, 1e-8));
        let out = ig.integrate(&mut Poisoned, 0.0, &[0.0], 5.0, &mut [], &mut NoObserver);
        let Outcome::NonFinite { t, y } = out else {
            panic!("{m:?}: {out:?}")
        };
        assert!(t <= 1.0 && y[0].is_finite(), "{m:?}: {t} {y:?}");
        assert!((y[0] - t).abs() < 1e-9);

        // Blow-up: the integration stops before t = 1 with a finite state,
        // as a failure (step size too small or non-finite values).
        let out = ig.integrate(&mut BlowUp, 0.0, &[1.0], 2.0, &mut [], &mut NoObserver);
        assert!(!out.is_success(), "{m:?}: {out:?}");
        // (The numerical blow-up may lag the exact one at t = 1 slightly.)
        assert!(out.t() < 1.0 + 1e-6, "{m:?}: {out:?}");
        assert!(out.y()[0].is_finite() && out.y()[0] > 1e3, "{m:?}: {out:?}");

        // Non-finite initial state.
        let out = ig.integrate(&mut Clock, 0.0, &[f64::NAN], 1.0, &mut [], &mut NoObserver);
        assert!(
            matches!(out, Outcome::NonFinite { t: 0.0, .. }),
            "{m:?}: {out:?}"
        );

        // Event function that turns non-finite.
        let mut ev = [Event::terminal(Direction::Either, |t, _: &[f64; 1]| {
            if t > 0.5 { f64::NAN } else { 1.0 }
        })];
        let out = ig.integrate(&mut Clock, 0.0, &[0.0], 1.0, &mut ev, &mut NoObserver);
        assert!(matches!(out, Outcome::NonFinite { .. }), "{m:?}: {out:?}");
        assert!(out.y()[0].is_finite());
    }
}

#[test]
fn invalid_input_and_step_limit() {
    let mut ig = Integrator::new(Method::Dopri5, Tolerances::new(1e-8, 1e-8));
    let out = ig.integrate(&mut Clock, 1.0, &[0.0], 0.0, &mut [], &mut NoObserver);
    assert!(
        matches!(out, Outcome::InvalidInput { t: 1.0, .. }),
        "{out:?}"
    );
    ig.set_tolerances(Tolerances::new(-1.0, 1e-8));
    let out = ig.integrate(&mut Clock, 0.0, &[0.0], 1.0, &mut [], &mut NoObserver);
    assert!(matches!(out, Outcome::InvalidInput { .. }), "{out:?}");
    ig.set_tolerances(Tolerances::new(1e-8, 1e-8));
    ig.config_mut().facmin = 2.0;
    let out = ig.integrate(&mut Clock, 0.0, &[0.0], 1.0, &mut [], &mut NoObserver);
    assert!(matches!(out, Outcome::InvalidInput { .. }), "{out:?}");

    let mut cfg = Config::for_method(Method::Dopri5);
    cfg.max_steps = 5;
    let mut ig = Integrator::with_config(Method::Dopri5, Tolerances::new(1e-10, 1e-10), cfg);
    let out = ig.integrate(
        &mut Oscillator,
        0.0,
        &[1.0, 0.0],
        100.0,
        &mut [],
        &mut NoObserver,
    );
    let Outcome::MaxSteps { t, y } = out else {
        panic!("{out:?}")
    };
    assert!(t > 0.0 && t < 100.0);
    assert!((y[0] - t.cos()).abs() < 1e-8);
    // t0 == t_end is a trivial success.
    let out = ig.integrate(
        &mut Oscillator,
        2.0,
        &[1.0, 0.0],
        2.0,
        &mut [],
        &mut NoObserver,
    );
    assert_eq!(
        out,
        Outcome::Reached {
            t: 2.0,
            y: [1.0, 0.0]
        }
    );
}

/// `y' = -k (y - cos t) - sin t` with `y(0) = 1`: the solution is `cos t`, and for large `k`
/// the explicit methods' step size is set by stability, not accuracy. The interpolant is not
/// under error control, and on such steps its values are poor (DOP853: 4e-5 at `tol = 1e-6`,
/// RODAS4 up to 5e-4, against a step-end error below 1e-6). The state at a terminal event
/// comes from a step of the method ending there, so it is as accurate as any step's end: the
/// global error of this damped problem is its last few local errors, each within
/// `tol (1 + |y|) <= 2 tol`.
#[test]
fn the_state_at_a_terminal_event_is_as_accurate_as_a_step_end_on_a_stiff_problem() {
    struct Stiff {
        k: f64,
    }
    impl OdeSystem<2> for Stiff {
        fn rhs(&mut self, t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
            dy[0] = -self.k * (y[0] - t.cos()) - t.sin();
            dy[1] = 1.0;
        }
    }
    let tol = 1e-6;
    let t_event = 0.7771;
    for method in METHODS {
        for k in [1e2, 1e4, 1e5] {
            let mut integ = Integrator::<2>::new(method, Tolerances::new(tol, tol));
            let mut events = [Event::terminal(
                Direction::Rising,
                move |_, y: &[f64; 2]| y[1] - t_event,
            )];
            let out = integ.integrate(
                &mut Stiff { k },
                0.0,
                &[1.0, 0.0],
                2.0,
                &mut events,
                &mut NoObserver,
            );
            let Outcome::Event { index: 0, t, y } = out else {
                panic!("{method:?}, k = {k}: {out:?}");
            };
            assert!((t - t_event).abs() < 1e-12, "{method:?}, k = {k}: t = {t}");
            let err = (y[0] - t.cos()).abs();
            assert!(
                err < 2.0 * tol,
                "{method:?}, k = {k}: error {err:e} at the event"
            );
        }
    }
}
