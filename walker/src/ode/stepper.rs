//! The one-step method interface shared by the three methods: dense output, attempt and
//! accept, step-size control kind, and the counted right-hand side and Hairer's error norm.

use super::options::Tolerances;
use super::stats::Stats;
use super::system::OdeSystem;

/// Continuous extension of one step, `theta = (t - t_start) / h`.
pub(crate) trait Dense<const N: usize> {
    /// Interpolated state at `theta`.
    fn eval(&self, theta: f64, out: &mut [f64; N]);
    /// Derivative of the interpolant with respect to `theta`.
    fn eval_dtheta(&self, theta: f64, out: &mut [f64; N]);
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

/// Whether every component of `y` is finite.
pub(crate) fn all_finite<const N: usize>(y: &[f64; N]) -> bool {
    y.iter().all(|v| v.is_finite())
}
