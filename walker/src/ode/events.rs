//! Event functions, crossing detection and root location on the dense output.
//!
//! The detection rule is documented on [`Event`].

use super::observer::Observer;
use super::stepper::Dense;

/// Which crossings of zero an event reacts to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// `g` goes from negative to positive.
    Rising,
    /// `g` goes from positive to negative.
    Falling,
    /// Either direction.
    Either,
}

impl Direction {
    /// Whether a move to the sign `to` (+1 or -1) is in this direction.
    fn accepts(self, to: i8) -> bool {
        match self {
            Direction::Rising => to > 0,
            Direction::Falling => to < 0,
            Direction::Either => true,
        }
    }
}

/// Per-event bookkeeping between checked points.
struct Track<const N: usize> {
    /// Sign of the last nonzero value (+1/-1), or 0 while on the guard since
    /// the start.
    sign: i8,
    /// `g` at the start of the current step.
    g_left: f64,
    /// `g` at the end of the current step.
    g_right: f64,
    /// Last time `g` was seen to be exactly zero while `sign == 0`.
    t_zero: f64,
    /// Located root in the current step, not yet reported.
    root: Option<f64>,
    /// The `(t, y)` at which this event was last returned as terminal, and the sign of `g`
    /// past that crossing.
    last_fired: Option<(f64, [f64; N], i8)>,
}

/// A boxed event function `g(t, y)`.
type EventFn<'a, const N: usize> = Box<dyn FnMut(f64, &[f64; N]) -> f64 + 'a>;

/// An event function `g(t, y)` whose zeros the integrator locates.
///
/// Terminal events stop the integration
/// ([`Outcome::Event`](super::Outcome::Event)); non-terminal ones are passed
/// to [`Observer::on_event`] and the integration goes on. The event keeps a
/// little state between calls (to recognise a resumption from the point it
/// last fired at): use one `Event` per guard and reuse it across calls.
///
/// # Detection rule
///
/// Each event keeps a *reference sign*: the sign of the last nonzero value
/// of `g` seen at a checked point. A crossing is a **genuine sign change from
/// a nonzero value**: `g` had the reference sign at one checked point and has
/// the opposite (nonzero) sign at a later one. Checked points are the ends of
/// the accepted steps (and, while an event is still "on the guard", a few
/// interior points of the step, see below). Touching zero and coming back
/// (`+, 0, +`) is not a crossing.
///
/// * A crossing from negative to positive is *rising*, from positive to
///   negative *falling*. Crossings that do not match the event's
///   [`Direction`] only update the reference sign.
/// * A matching crossing is located by the Anderson–Björck variant of
///   regula falsi (Illinois-type, with bisection safeguard) on `g(t, u(t))`,
///   `u` being the dense output of the step, to a bracket of about two ulps
///   of `t`, the end of the final bracket on the *far side* (`g` zero or
///   already of the new sign on the interpolant). For a terminal event the
///   state there is then computed by steps of the method that end on it
///   (the interpolant's values are not error-controlled), and the time is
///   refined by Newton's method on `g` along the flow until that state is on
///   the far side too, or on the guard to within the time resolution (`g` at
///   its rounding level, where its sign is noise).
/// * If `g` was exactly zero at the previous step end and the crossing is
///   detected now, the root is that step end.
///
/// **Starting on the guard.** If `g(t0, y0) == 0` exactly (for example just
/// after a reset map put the state on the guard), there is no reference sign
/// yet and the zero at `t0` is *not* an event by itself. The direction in
/// which `g` leaves zero decides:
///
/// * it is sampled on the dense output of the following step(s) at
///   `theta = 2^-10, 2^-8, 2^-6, 2^-4, 1/4, 1/2, 3/4, 1`, so that an early
///   dip is seen even when the first step is long;
/// * if the first nonzero sample moves **in the event direction**
///   ([`Direction::Rising`] and positive, or [`Direction::Falling`] and
///   negative), the event fires at the last point where `g` was still zero
///   (normally `t0` itself, with the state `y0`): the trajectory leaves the
///   guard through the wrong side, which is a genuine event (a foot that
///   starts on the ground and moves into it);
/// * otherwise that sample only sets the reference sign; subsequent crossings
///   are detected as usual (also between the later samples of the same
///   step);
/// * for [`Direction::Either`] a zero start is never reported: leaving the
///   guard is indistinguishable from having been put on it.
///
/// **Resuming after a terminal event.** When an integration starts from
/// exactly the `(t, y)` that this event last returned as
/// [`Outcome::Event`](super::Outcome::Event) (bitwise equal: the caller
/// continues without changing the state), the crossing has already been
/// reported: the reference sign is set to the post-crossing sign, whatever
/// the sign of `g` there (zero, or rounding noise on the near side), and the
/// event does not fire again for that crossing. After a reset map the state
/// differs and the rules above apply.
///
/// **Rounding after a reset.** A reset map often puts the state only
/// *nearly* on the guard (`g = ±1e-17`). That value counts as nonzero: it
/// sets the reference sign, and moving away from the guard afterwards is a
/// sign change only if the value had the "wrong" sign. For a directional
/// event that change is in the opposite direction and is ignored, so
/// [`Direction::Rising`]/[`Direction::Falling`] guards are robust to this;
/// an [`Direction::Either`] event may fire right after such a restart. Use
/// directional events for guards that reset maps land on, or make the reset
/// land exactly on `g = 0`.
///
/// Limitation: an even number of sign changes between two checked points
/// (a short excursion across the guard within one step) is not seen. Limit
/// the step size ([`Config::hmax`](super::Config::hmax)) if such grazing
/// matters.
pub struct Event<'a, const N: usize> {
    g: EventFn<'a, N>,
    direction: Direction,
    terminal: bool,
    track: Track<N>,
}

impl<'a, const N: usize> Event<'a, N> {
    /// An event that stops the integration when it fires.
    pub fn terminal(direction: Direction, g: impl FnMut(f64, &[f64; N]) -> f64 + 'a) -> Self {
        Self::new(direction, true, g)
    }

    /// An event that is reported to the observer while the integration
    /// continues.
    pub fn non_terminal(direction: Direction, g: impl FnMut(f64, &[f64; N]) -> f64 + 'a) -> Self {
        Self::new(direction, false, g)
    }

    /// An event with an explicit terminal flag.
    pub fn new(
        direction: Direction,
        terminal: bool,
        g: impl FnMut(f64, &[f64; N]) -> f64 + 'a,
    ) -> Self {
        Self {
            g: Box::new(g),
            direction,
            terminal,
            track: Track {
                sign: 0,
                g_left: 0.0,
                g_right: 0.0,
                t_zero: 0.0,
                root: None,
                last_fired: None,
            },
        }
    }

    /// The crossing direction this event reacts to.
    pub fn direction(&self) -> Direction {
        self.direction
    }

    /// Whether the event stops the integration.
    pub fn is_terminal(&self) -> bool {
        self.terminal
    }

    /// Evaluate the event function.
    pub fn value(&mut self, t: f64, y: &[f64; N]) -> f64 {
        (self.g)(t, y)
    }

    /// Forget where this event last fired, so that a start from that point
    /// on the guard is treated like any other start on the guard.
    pub fn forget_last_firing(&mut self) {
        self.track.last_fired = None;
    }

    /// Record that the event fired at `(t, y)`, crossing to the sign of `g_far` (its value at
    /// the end of the step that contained the crossing).
    pub(crate) fn mark_fired(&mut self, t: f64, y: &[f64; N], g_far: f64) {
        self.track.last_fired = Some((t, *y, sign_of(g_far)));
        self.track.root = None;
    }
}

fn sign_of(v: f64) -> i8 {
    if v > 0.0 {
        1
    } else if v < 0.0 {
        -1
    } else {
        0
    }
}

/// An accepted step with its interpolant.
pub(crate) struct Span<'a, const N: usize> {
    pub(crate) t0: f64,
    pub(crate) t1: f64,
    pub(crate) h: f64,
    pub(crate) y0: &'a [f64; N],
    pub(crate) y1: &'a [f64; N],
    pub(crate) dense: &'a dyn Dense<N>,
}

impl<const N: usize> Span<'_, N> {
    /// State at `t` in the step (exact stored states at the two ends).
    pub(crate) fn state_at(&self, t: f64, out: &mut [f64; N]) {
        if t == self.t0 {
            *out = *self.y0;
        } else if t == self.t1 {
            *out = *self.y1;
        } else {
            self.dense.eval((t - self.t0) / self.h, out);
        }
    }
}

/// Initialise all events at the start `(t0, y0)`. `Err` if some `g` is not
/// finite there.
pub(crate) fn start<const N: usize>(
    events: &mut [Event<'_, N>],
    t0: f64,
    y0: &[f64; N],
) -> Result<(), ()> {
    for ev in events.iter_mut() {
        let g0 = (ev.g)(t0, y0);
        if !g0.is_finite() {
            return Err(());
        }
        let tr = &mut ev.track;
        tr.sign = sign_of(g0);
        tr.g_left = g0;
        tr.g_right = g0;
        tr.t_zero = t0;
        tr.root = None;
        match &tr.last_fired {
            Some((tf, yf, far)) if *tf == t0 && yf == y0 && *far != 0 => tr.sign = *far,
            _ => {}
        }
    }
    Ok(())
}

/// Evaluate every `g` at the end of an accepted step. Returns whether some
/// event needs the dense output of the step (a matching crossing to locate,
/// or an event still on the guard). `Err` if some `g` is not finite.
pub(crate) fn check_end<const N: usize>(
    events: &mut [Event<'_, N>],
    t1: f64,
    y1: &[f64; N],
) -> Result<bool, ()> {
    let mut need = false;
    for ev in events.iter_mut() {
        let g1 = (ev.g)(t1, y1);
        if !g1.is_finite() {
            return Err(());
        }
        let tr = &mut ev.track;
        tr.g_right = g1;
        tr.root = None;
        let s1 = sign_of(g1);
        if tr.sign == 0 || (s1 == -tr.sign && ev.direction.accepts(s1)) {
            need = true;
        }
    }
    Ok(need)
}

/// Sample points used while an event is still on the guard.
const GUARD_SAMPLES: [f64; 7] = [
    1.0 / 1024.0,
    1.0 / 256.0,
    1.0 / 64.0,
    1.0 / 16.0,
    0.25,
    0.5,
    0.75,
];

/// Locate the crossings in the step `span` (after [`check_end`]). Stores the
/// root of every event that fires and returns the earliest terminal one
/// (lowest index on ties) as `(index, t)`. `Err(t)` if some `g` is not finite
/// at an interpolated point `t`.
pub(crate) fn locate<const N: usize>(
    events: &mut [Event<'_, N>],
    span: &Span<'_, N>,
) -> Result<Option<(usize, f64)>, f64> {
    let mut y = [0.0; N];
    for ev in events.iter_mut() {
        let Event {
            g,
            direction,
            track: tr,
            ..
        } = ev;
        let dir = *direction;
        let mut gt = |t: f64| -> Result<f64, f64> {
            span.state_at(t, &mut y);
            let v = g(t, &y);
            if v.is_finite() { Ok(v) } else { Err(t) }
        };
        if tr.sign == 0 {
            // On the guard since the start: find where g leaves zero.
            let mut sign = 0i8;
            let mut prev = (span.t0, 0.0);
            let samples = GUARD_SAMPLES
                .iter()
                .map(|th| span.t0 + th * span.h)
                .filter(|&t| t < span.t1)
                .map(Some)
                .chain(core::iter::once(None));
            for sample in samples {
                let (t, gv) = match sample {
                    Some(t) => (t, gt(t)?),
                    None => (span.t1, tr.g_right),
                };
                let s = sign_of(gv);
                if sign == 0 {
                    if s == 0 {
                        tr.t_zero = t;
                    } else if dir != Direction::Either && dir.accepts(s) {
                        tr.root = Some(tr.t_zero);
                        break;
                    } else {
                        sign = s;
                    }
                } else if s == -sign {
                    if dir.accepts(s) {
                        tr.root = Some(if prev.1 == 0.0 {
                            prev.0
                        } else {
                            find_root(prev.0, prev.1, t, gv, &mut gt)?
                        });
                        break;
                    }
                    sign = s;
                }
                prev = (t, gv);
            }
        } else {
            let s1 = sign_of(tr.g_right);
            if s1 == -tr.sign && dir.accepts(s1) {
                tr.root = Some(if tr.g_left == 0.0 {
                    span.t0
                } else {
                    find_root(span.t0, tr.g_left, span.t1, tr.g_right, &mut gt)?
                });
            }
        }
    }
    let mut first: Option<(usize, f64)> = None;
    for (i, ev) in events.iter().enumerate() {
        if let (true, Some(t)) = (ev.terminal, ev.track.root)
            && first.is_none_or(|(_, tf)| t < tf)
        {
            first = Some((i, t));
        }
    }
    Ok(first)
}

/// Report the located non-terminal roots at or before `t_stop` to the
/// observer, in time order (lowest index on ties). Returns how many.
pub(crate) fn report_non_terminal<const N: usize, O: Observer<N>>(
    events: &mut [Event<'_, N>],
    span: &Span<'_, N>,
    t_stop: f64,
    obs: &mut O,
) -> u64 {
    let mut count = 0;
    loop {
        let mut next: Option<(usize, f64)> = None;
        for (i, ev) in events.iter().enumerate() {
            if let (false, Some(t)) = (ev.terminal, ev.track.root)
                && t <= t_stop
                && next.is_none_or(|(_, tn)| t < tn)
            {
                next = Some((i, t));
            }
        }
        let Some((i, t)) = next else {
            return count;
        };
        events[i].track.root = None;
        let mut y = [0.0; N];
        span.state_at(t, &mut y);
        obs.on_event(i, t, &y);
        count += 1;
    }
}

/// Move every event to the end `t1` of the step just processed.
pub(crate) fn commit<const N: usize>(events: &mut [Event<'_, N>], t1: f64) {
    for ev in events.iter_mut() {
        let tr = &mut ev.track;
        let s1 = sign_of(tr.g_right);
        if s1 != 0 {
            tr.sign = s1;
        } else if tr.sign == 0 {
            // Still (or again) on the guard since the start.
            tr.t_zero = t1;
        }
        tr.g_left = tr.g_right;
        tr.root = None;
    }
}

/// Maximum iterations of the root finder (it normally needs far fewer; the
/// bisection safeguard guarantees progress).
const MAX_ROOT_ITERATIONS: usize = 200;

/// Find a zero of `g` in `[a, b]`, given `ga = g(a)` and `gb = g(b)` of
/// strictly opposite signs, by the Anderson–Björck method with a bisection
/// safeguard. Returns the end of the final bracket on `b`'s side (where `g`
/// is zero or has the sign of `gb`), once the bracket is at most about two
/// ulps wide.
pub(crate) fn find_root<E>(
    mut a: f64,
    mut ga: f64,
    mut b: f64,
    mut gb: f64,
    g: &mut impl FnMut(f64) -> Result<f64, E>,
) -> Result<f64, E> {
    // side: +1 if b was replaced last, -1 if a was, 0 at the start.
    let mut side = 0i8;
    let mut width_ref = b - a;
    let mut stalled = 0u32;
    for _ in 0..MAX_ROOT_ITERATIONS {
        let width = b - a;
        let scale = a.abs().max(b.abs()).max(f64::MIN_POSITIVE);
        let tol = 2.0 * f64::EPSILON * scale;
        if width <= tol {
            break;
        }
        let mid = a + 0.5 * width;
        let mut c = if stalled >= 3 {
            stalled = 0;
            mid
        } else {
            b - gb * (width / (gb - ga))
        };
        if !c.is_finite() {
            c = mid;
        }
        // Never probe closer than tol/2 to an end (the secant point can
        // round onto an end): once one end has converged, this closes the
        // bracket from the other side at once.
        c = c.clamp(a + 0.5 * tol, b - 0.5 * tol);
        if !(c > a && c < b) {
            // a and b are adjacent floating-point numbers.
            break;
        }
        let gc = g(c)?;
        if gc == 0.0 {
            return Ok(c);
        }
        if (gc > 0.0) == (gb > 0.0) {
            // c replaces b; if a is kept twice in a row, scale g(a).
            if side == 1 {
                let m = 1.0 - gc / gb;
                ga *= if m > 0.0 { m } else { 0.5 };
            }
            b = c;
            gb = gc;
            side = 1;
        } else {
            if side == -1 {
                let m = 1.0 - gc / ga;
                gb *= if m > 0.0 { m } else { 0.5 };
            }
            a = c;
            ga = gc;
            side = -1;
        }
        if b - a <= 0.5 * width_ref {
            width_ref = b - a;
            stalled = 0;
        } else {
            stalled += 1;
        }
    }
    Ok(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn root(a: f64, b: f64, f: impl Fn(f64) -> f64) -> (f64, usize) {
        let mut calls = 0;
        let mut g = |t: f64| -> Result<f64, ()> {
            calls += 1;
            Ok(f(t))
        };
        let r = find_root(a, f(a), b, f(b), &mut g);
        (r.unwrap_or(f64::NAN), calls)
    }

    #[test]
    fn root_finder_reaches_a_few_ulps() {
        let exact = core::f64::consts::FRAC_PI_2;
        let (r, calls) = root(1.0, 2.0, f64::cos);
        assert!(
            (r - exact).abs() <= 4.0 * f64::EPSILON * exact,
            "{r} vs {exact}"
        );
        assert!(calls < 20, "{calls} evaluations");
        // Far side: cos is negative right of pi/2.
        assert!(r.cos() <= 0.0);
    }

    #[test]
    fn root_finder_survives_flat_and_steep_functions() {
        // Very flat near the root (multiplicity 5), then a step-like one.
        let (r, _) = root(0.0, 3.0, |t| (t - 1.0).powi(5));
        assert!((r - 1.0).abs() < 1e-2, "{r}");
        let (r, _) = root(-1.0, 1.0, |t| (1e6 * (t - 0.3)).tanh());
        assert!((r - 0.3).abs() <= 4.0 * f64::EPSILON, "{r}");
    }
}
