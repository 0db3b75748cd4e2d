//! The public event types: the crossing [`Direction`] and the [`Event`] function with its
//! per-event bookkeeping between checked points.
//!
//! The detection rule is documented on [`Event`]; the machinery that applies it is in
//! the sibling module `locate`.

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
    pub(super) fn accepts(self, to: i8) -> bool {
        match self {
            Direction::Rising => to > 0,
            Direction::Falling => to < 0,
            Direction::Either => true,
        }
    }
}

/// Per-event bookkeeping between checked points.
pub(super) struct Track<const N: usize> {
    /// Sign of the last nonzero value (+1/-1), or 0 while on the guard since
    /// the start.
    pub(super) sign: i8,
    /// `g` at the start of the current step.
    pub(super) g_left: f64,
    /// `g` at the end of the current step.
    pub(super) g_right: f64,
    /// Last time `g` was seen to be exactly zero while `sign == 0`.
    pub(super) t_zero: f64,
    /// Located root in the current step, not yet reported.
    pub(super) root: Option<f64>,
    /// The `(t, y)` at which this event was last returned as terminal, and the sign of `g`
    /// past that crossing.
    pub(super) last_fired: Option<(f64, [f64; N], i8)>,
}

/// A boxed event function `g(t, y)`.
type EventFn<'a, const N: usize> = Box<dyn FnMut(f64, &[f64; N]) -> f64 + 'a>;

/// An event function `g(t, y)` whose zeros the integrator locates.
///
/// Terminal events stop the integration
/// ([`Outcome::Event`](crate::ode::Outcome::Event)); non-terminal ones are passed
/// to [`Observer::on_event`](crate::ode::Observer::on_event) and the integration
/// goes on. The event keeps a little state between calls (to recognise a
/// resumption from the point it last fired at): use one `Event` per guard and
/// reuse it across calls.
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
/// [`Outcome::Event`](crate::ode::Outcome::Event) (bitwise equal: the caller
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
/// the step size ([`Config::hmax`](crate::ode::Config::hmax)) if such grazing
/// matters.
pub struct Event<'a, const N: usize> {
    pub(super) g: EventFn<'a, N>,
    pub(super) direction: Direction,
    pub(super) terminal: bool,
    pub(super) track: Track<N>,
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

pub(super) fn sign_of(v: f64) -> i8 {
    if v > 0.0 {
        1
    } else if v < 0.0 {
        -1
    } else {
        0
    }
}
