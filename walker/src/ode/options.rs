//! The integration method, its error tolerances and its step-size control settings.

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

    pub(crate) fn validate(&self) -> Result<(), &'static str> {
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
    /// [`Integrator::integrate`](super::Integrator::integrate) (Hairer's `NMAX`, default 100 000).
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

    pub(crate) fn validate(&self) -> Result<(), &'static str> {
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
