//! Initial step size and step-size controllers, after Hairer's codes.

use super::options::{Config, Tolerances};
use super::stats::Stats;
use super::stepper::{ControlKind, rhs};
use super::system::OdeSystem;

/// Rounding unit used in the "step size too small" test (Hairer uses
/// 2.3e-16).
pub(crate) const UROUND: f64 = f64::EPSILON;

/// Initial step size guess, a transcription of `HINIT` from Hairer's
/// `dopri5.f` / `dop853.f`.
///
/// First guess `h = 0.01 * ||y0|| / ||f0||` (norms weighted with
/// `atol + rtol |y0|`), then one explicit Euler step estimates the second
/// derivative, and `h` is chosen such that
/// `h^order * max(||f0||, ||y''||) = 0.01`, with `h <= 100 h_first` and
/// `h <= hmax`. Costs one evaluation of the right-hand side.
#[allow(clippy::too_many_arguments)]
pub(crate) fn hinit<S: OdeSystem<N>, const N: usize>(
    sys: &mut S,
    t: f64,
    y: &[f64; N],
    f0: &[f64; N],
    order: i32,
    hmax: f64,
    tol: &Tolerances,
    stats: &mut Stats,
) -> f64 {
    let sk = |i: usize| tol.atol + tol.rtol * y[i].abs();
    let mut dnf = 0.0;
    let mut dny = 0.0;
    for i in 0..N {
        dnf += (f0[i] / sk(i)).powi(2);
        dny += (y[i] / sk(i)).powi(2);
    }
    let mut h = if dnf <= 1e-10 || dny <= 1e-10 {
        1.0e-6
    } else {
        (dny / dnf).sqrt() * 0.01
    };
    h = h.min(hmax);
    // Explicit Euler step.
    let y1: [f64; N] = core::array::from_fn(|i| y[i] + h * f0[i]);
    let mut f1 = [0.0; N];
    rhs(sys, stats, t + h, &y1, &mut f1);
    // Estimate of the second derivative.
    let mut der2 = 0.0;
    for i in 0..N {
        der2 += ((f1[i] - f0[i]) / sk(i)).powi(2);
    }
    let der2 = der2.sqrt() / h;
    let der12 = der2.abs().max(dnf.sqrt());
    let h1 = if der12 <= 1e-15 {
        (1.0e-6f64).max(h.abs() * 1.0e-3)
    } else {
        (0.01 / der12).powf(1.0 / f64::from(order))
    };
    let h = (100.0 * h.abs()).min(h1).min(hmax);
    // A non-finite guess (f1 not finite, say) falls back to a tiny step; the
    // step loop then reports the non-finite values properly.
    if h.is_finite() && h > 0.0 {
        h
    } else {
        1.0e-6f64.min(hmax)
    }
}

/// `x^e` for the controller's exponents: the methods' `1/4` (RODAS) and `1/8` (DOP853 without
/// stabilisation) by square roots, which cost a fraction of `powf` (a few percent of a whole
/// walk with DOP853) and differ from it by an ulp or two, irrelevant for a step-size factor.
fn pow(x: f64, e: f64) -> f64 {
    if e == 0.25 {
        x.sqrt().sqrt()
    } else if e == 0.125 {
        x.sqrt().sqrt().sqrt()
    } else {
        x.powf(e)
    }
}

/// Step-size controller state.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Controller {
    /// Hairer's DOPRI5/DOP853 controller with Lund stabilisation.
    Lund {
        expo1: f64,
        beta: f64,
        facold: f64,
        safe: f64,
        facc1: f64,
        facc2: f64,
    },
    /// Hairer's RODAS controller with Gustafsson's predictive correction.
    Predictive {
        exponent: f64,
        first: bool,
        h_acc: f64,
        err_acc: f64,
        safe: f64,
        facc1: f64,
        facc2: f64,
    },
}

impl Controller {
    /// A fresh controller (no step accepted yet).
    pub(crate) fn new(kind: ControlKind, cfg: &Config) -> Self {
        let facc1 = 1.0 / cfg.facmin;
        let facc2 = 1.0 / cfg.facmax;
        match kind {
            ControlKind::Lund { base, weight } => Controller::Lund {
                expo1: base - cfg.beta * weight,
                beta: cfg.beta,
                facold: 1.0e-4,
                safe: cfg.safety,
                facc1,
                facc2,
            },
            ControlKind::Predictive { exponent } => Controller::Predictive {
                exponent,
                first: true,
                h_acc: 0.0,
                err_acc: 1.0,
                safe: cfg.safety,
                facc1,
                facc2,
            },
        }
    }

    /// Decide on a step of size `h` with scaled error `err` (finite, >= 0):
    /// returns whether it is accepted and the next step size (before the
    /// `hmax` and after-rejection limits, which the caller applies).
    pub(crate) fn propose(&mut self, err: f64, h: f64) -> (bool, f64) {
        match self {
            Controller::Lund {
                expo1,
                beta,
                facold,
                safe,
                facc1,
                facc2,
            } => {
                let fac11 = pow(err, *expo1);
                // Lund stabilisation.
                let fac = if *beta == 0.0 {
                    fac11
                } else {
                    fac11 / facold.powf(*beta)
                };
                // We require facmin <= hnew/h <= facmax.
                let fac = (fac / *safe).min(*facc1).max(*facc2);
                if err <= 1.0 {
                    *facold = err.max(1.0e-4);
                    (true, h / fac)
                } else {
                    (false, h / facc1.min(fac11 / *safe))
                }
            }
            Controller::Predictive {
                exponent,
                first,
                h_acc,
                err_acc,
                safe,
                facc1,
                facc2,
            } => {
                let mut fac = (pow(err, *exponent) / *safe).min(*facc1).max(*facc2);
                if err <= 1.0 {
                    if !*first {
                        // Predictive controller of Gustafsson.
                        let facgus = (*h_acc / h) * pow(err * err / *err_acc, *exponent) / *safe;
                        fac = fac.max(facgus.min(*facc1).max(*facc2));
                    }
                    *first = false;
                    *h_acc = h;
                    *err_acc = err.max(1.0e-2);
                    (true, h / fac)
                } else {
                    (false, h / fac)
                }
            }
        }
    }
}
