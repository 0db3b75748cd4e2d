//! Settings of a simulation ([`SimConfig`]) and limits of a walk ([`WalkLimits`]).

use crate::ode::Method;

/// Settings of the simulation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SimConfig {
    /// Integration method: DOP853 by default, RODAS4 for stiff friction (large `mu0 c`).
    pub method: Method,
    /// Relative tolerance of the integrator.
    pub rtol: f64,
    /// Absolute tolerance of the integrator.
    pub atol: f64,
    /// Longest stance phase before [`FailureKind::NoImpact`](super::FailureKind::NoImpact) is reported (s).
    pub max_step_time: f64,
    /// `|lambda|` above this many times `m_t g` counts as a blow-up of the ground reaction:
    /// a vanishing denominator of Eq. 23
    /// ([`FailureKind::LambdaDenominatorZero`](super::FailureKind::LambdaDenominatorZero)) or
    /// a huge numerator
    /// ([`FailureKind::LambdaNumeratorHuge`](super::FailureKind::LambdaNumeratorHuge)).
    pub lambda_blowup: f64,
}

impl Default for SimConfig {
    fn default() -> Self {
        Self {
            method: Method::Dop853,
            rtol: 1e-10,
            atol: 1e-12,
            max_step_time: 10.0,
            lambda_blowup: 1e6,
        }
    }
}

/// Limits of a walk.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WalkLimits {
    /// Stop after this many steps.
    pub max_steps: usize,
    /// Stop after the step during which the total time passes this value (s).
    pub duration: f64,
    /// Record samples of the motion (for plots).
    pub record: bool,
    /// Stop early once the gait is periodic, so that the last step stands for every later one:
    /// when the relative change of the descriptors `T`, `dx` and `p` (the largest of the three)
    /// from one step to the next has shrunk twice in a row by a ratio below 0.9 (over the last
    /// four steps), and the last change continued as a geometric series with the larger of the
    /// two ratios adds up to at most this value. Period-2 and chaotic gaits and slowly converging ones never stop
    /// early. `None`: walk to `max_steps` or `duration`.
    pub periodic: Option<f64>,
}

impl Default for WalkLimits {
    fn default() -> Self {
        Self {
            max_steps: 100,
            duration: f64::INFINITY,
            record: false,
            periodic: None,
        }
    }
}
