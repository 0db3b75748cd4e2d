//! The view of one accepted step with its dense output ([`Step`]) and the observers that
//! receive the steps and the non-terminal events.

use super::stepper::Dense;

/// One accepted step as shown to an [`Observer`], with its dense output.
///
/// The step covers `[t_start, t_end]`. When a terminal event truncates the
/// step, `t_end` is the event time and `y_end` the state there as returned in
/// [`Outcome::Event`](super::Outcome::Event) (from a step ending on the event, so it can differ from
/// the interpolant at `t_end` by the interpolant's error).
pub struct Step<'a, const N: usize> {
    pub(crate) t_start: f64,
    pub(crate) t_end: f64,
    pub(crate) h: f64,
    pub(crate) y_start: &'a [f64; N],
    pub(crate) y_end: &'a [f64; N],
    pub(crate) dense: &'a dyn Dense<N>,
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
    /// [`Outcome::Event`](super::Outcome::Event) instead.
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
