//! The state at a terminal event from fresh steps of the method that end on it.

use super::events::Event;
use super::options::Tolerances;
use super::stats::Stats;
use super::stepper::{Stepper, all_finite, rhs};
use super::system::OdeSystem;

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
/// interpolated state, and are within 1.0e-8 with this (`walker/tests/it/sim_stiff.rs`).
/// The usual cost is two steps (26 evaluations with DOP853) per event.
#[allow(clippy::too_many_arguments)]
pub(crate) fn settle<const N: usize, St: Stepper<N>, S: OdeSystem<N>>(
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
