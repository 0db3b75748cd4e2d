//! Crossing detection on the accepted steps and root location on their dense output: the
//! crate-internal machinery the driver calls for the [`Event`]s of an integration.

use super::event::{Direction, Event, sign_of};
use super::root::find_root;
use crate::ode::observer::Observer;
use crate::ode::stepper::Dense;
use crate::ode::system::OdeSystem;

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

/// The most events whose values at a step's end a system gives in one call
/// ([`OdeSystem::event_values`]); with more, each event's function is called.
const MAX_BATCH: usize = 24;

/// Evaluate every `g` at the end of an accepted step: all at once where the system gives
/// them ([`OdeSystem::event_values`]), otherwise one by one. Returns whether some
/// event needs the dense output of the step (a matching crossing to locate,
/// or an event still on the guard). `Err` if some `g` is not finite.
pub(crate) fn check_end<const N: usize, S: OdeSystem<N>>(
    events: &mut [Event<'_, N>],
    sys: &mut S,
    t1: f64,
    y1: &[f64; N],
) -> Result<bool, ()> {
    let mut values = [0.0; MAX_BATCH];
    let batch = events.len() <= MAX_BATCH && sys.event_values(t1, y1, &mut values[..events.len()]);
    let mut need = false;
    for (i, ev) in events.iter_mut().enumerate() {
        let g1 = if batch { values[i] } else { (ev.g)(t1, y1) };
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
