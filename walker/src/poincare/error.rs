//! Why the Poincare map or the fixed-point search failed: typed errors that keep the time since
//! the impact where it happened and their source.

use crate::ode::GaveUp;
use crate::sim::Failure;

/// Why the map could not be evaluated. `t` is the time since the impact (s).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum MapError {
    /// The state given to the map is not finite.
    #[error("Poincare map failed at t = 0: non-finite initial state")]
    NonFiniteStart,
    /// A state, a start's rate or the seeds given to the map do not have the model's shape (a
    /// caller's mistake: `2n` numbers, or `2n` rows of equal length).
    #[error("Poincare map: {what} has {got} entries where {expected} are needed")]
    Shape {
        /// What was given: `the state`, `the start's rate`, `the seeds`, `a seed row`.
        what: &'static str,
        /// Its length.
        got: usize,
        /// The length it must have.
        expected: usize,
    },
    /// One of the model's falls (`[[fall]]`) within the stance: the walker has no next step.
    #[error("Poincare map failed at t = {t}: fall `{name}`")]
    Fall {
        /// The fall's name in the model file.
        name: String,
        /// The time since the impact (s).
        t: f64,
    },
    /// The ground reaction blew up within the stance (`|lambda|` beyond the simulator's
    /// threshold, [`SimConfig::lambda_blowup`](crate::sim::SimConfig::lambda_blowup) times the
    /// weight): a singular control or contact.
    #[error("Poincare map failed at t = {t}: the ground reaction blew up (lambda = {lambda})")]
    BlowUp {
        /// The time since the impact (s).
        t: f64,
        /// The vertical ground reaction there (N).
        lambda: f64,
    },
    /// No heel strike before [`SimConfig::max_step_time`](crate::sim::SimConfig::max_step_time).
    #[error("Poincare map failed at t = {t}: no heel strike")]
    NoHeelStrike {
        /// Time reached.
        t: f64,
    },
    /// The stance dynamics (or the variational equations) produced a non-finite value.
    #[error("Poincare map failed at t = {t}: non-finite state")]
    NonFinite {
        /// Time of the last finite point.
        t: f64,
    },
    /// The integrator gave up before the heel strike.
    #[error("Poincare map failed at t = {t}: {cause}")]
    Integrator {
        /// Time reached.
        t: f64,
        /// What stopped it.
        #[source]
        cause: GaveUp,
    },
    /// The heel strike is grazing (`th1d = 0`): the saltation correction divides by it.
    #[error("Poincare map failed at t = {t}: grazing heel strike (th1d = 0)")]
    GrazingHeelStrike {
        /// Time of the heel strike.
        t: f64,
    },
    /// An event that switches the stance phase (the foot comes to rest or starts to slip) is
    /// grazed: its saltation matrix divides by the guard's rate, which vanishes.
    #[error(
        "Poincare map failed at t = {t}: a stick-slip event is grazed (its guard's rate is zero)"
    )]
    GrazingEvent {
        /// Time of the event.
        t: f64,
    },
    /// A foot at rest can neither stick nor slide (Painleve's paradox under exact Coulomb
    /// friction).
    #[error(
        "Poincare map failed at t = {t}: contact-inconsistent (the foot at rest can neither stick nor slide)"
    )]
    ContactInconsistent {
        /// Time of the event.
        t: f64,
    },
    /// The state or the Jacobian after the impact and the reset is not finite.
    #[error("Poincare map failed at t = {t}: non-finite impact or reset")]
    NonFiniteImpact {
        /// Time of the heel strike.
        t: f64,
    },
    /// A step of the simulator failed (the map by finite differences, which walks one step
    /// with every validity test of the walk).
    #[error("Poincare map failed at t = {}: {}", .0.t, .0.name())]
    Walk(Box<Failure>),
}

/// Why no fixed point could be searched for.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FixedPointError {
    /// The warm-up walk failed before completing a step.
    #[error("the warm-up walk failed before the first impact: {}", .0.name())]
    Warmup(Failure),
    /// The warm-up walk ended without completing a step and without a failure.
    #[error("the warm-up walk failed before the first impact: no step")]
    NoWarmupStep,
    /// The map failed at the guess or at every damped Newton step.
    #[error(transparent)]
    Map(#[from] MapError),
}
