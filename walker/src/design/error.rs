//! Why a design request is invalid, or why no design could start.

/// A design request that cannot be run.
#[derive(Debug, thiserror::Error)]
pub enum DesignError {
    /// No parameter to vary.
    #[error("no parameter to vary: give at least one NAME=LO:HI")]
    NoParameters,
    /// A varied name is not a run-time parameter of the model.
    #[error("`{name}` is not a run-time parameter of model `{model}`; valid: {known}")]
    NotAParameter {
        /// The name given.
        name: String,
        /// The model.
        model: String,
        /// The valid names.
        known: String,
    },
    /// A parameter varied twice.
    #[error("`{name}` is varied twice")]
    Twice {
        /// The parameter.
        name: String,
    },
    /// A bound or start that is not a finite number.
    #[error("{what} of `{name}` is {value}: must be finite")]
    NotFinite {
        /// The parameter.
        name: String,
        /// `lower bound`, `upper bound` or `start`.
        what: &'static str,
        /// The value.
        value: f64,
    },
    /// Bounds with `lo >= hi`.
    #[error("bounds of `{name}` are [{lo}, {hi}]: the lower bound must be below the upper")]
    EmptyRange {
        /// The parameter.
        name: String,
        /// Lower bound.
        lo: f64,
        /// Upper bound.
        hi: f64,
    },
    /// The start lies outside the bounds.
    #[error("start of `{name}` is {start}: must be in [{lo}, {hi}]")]
    StartOutside {
        /// The parameter.
        name: String,
        /// The start.
        start: f64,
        /// Lower bound.
        lo: f64,
        /// Upper bound.
        hi: f64,
    },
    /// A bound outside the parameter's own valid range.
    #[error("bound {value} of `{name}`: {message}")]
    BoundOutsideRange {
        /// The parameter.
        name: String,
        /// The bound.
        value: f64,
        /// The parameter's range, as the model states it.
        message: String,
    },
    /// A margin out of range.
    #[error("{which} margin is {value}: must be {must_be}")]
    Margin {
        /// `multiplier`, `friction`, `normal` or `ramp`.
        which: &'static str,
        /// The value.
        value: f64,
        /// The valid range.
        must_be: &'static str,
    },
    /// The objective needs the control inputs of an actuated walker.
    #[error("objective `{objective}` needs an actuated walker; model `{model}` has no inputs")]
    NoInputs {
        /// The objective.
        objective: &'static str,
        /// The model.
        model: String,
    },
    /// An input bound that is not a finite positive number.
    #[error("input bound is {value}: must be finite and > 0")]
    MaxInput {
        /// The bound.
        value: f64,
    },
    /// Input bounds for a walker without inputs.
    #[error("input bounds need an actuated walker; model `{model}` has no inputs")]
    NoInputsToBound {
        /// The model.
        model: String,
    },
    /// Input bounds neither one for all inputs nor one per input.
    #[error(
        "{given} input bounds for a walker with {inputs} input(s): give one for all or one per input"
    )]
    MaxInputCount {
        /// The number of bounds given.
        given: usize,
        /// The walker's inputs.
        inputs: usize,
    },
    /// The model has no friction coefficient `mu0` to hold the foot against.
    #[error("model `{model}` has no parameter `mu0`: the friction constraints need one")]
    NoMu0 {
        /// The model.
        model: String,
    },
    /// No periodic gait at the start: nothing to design from.
    #[error("no periodic gait at the start ({at}): {message}")]
    NoGaitAtStart {
        /// The start, as `NAME=VALUE, ...`.
        at: String,
        /// Why.
        message: String,
    },
    /// Too many restarts.
    #[error("{count} restarts: the number of restarts must be a whole number in [0, {max}]")]
    Restarts {
        /// The number asked.
        count: usize,
        /// The most allowed.
        max: usize,
    },
    /// A gait bound (`clearance`, `min-speed`, `max-speed`, `max-power`) out of range.
    #[error("{which} is {value}: must be {must_be}")]
    Bound {
        /// `clearance`, `min-speed`, `max-speed` or `max-power`.
        which: &'static str,
        /// The value.
        value: f64,
        /// The valid range.
        must_be: &'static str,
    },
    /// A most speed below the least speed: no gait meets both.
    #[error(
        "max-speed is {max}, below min-speed {min}: must be at least min-speed (equal to it for a gait at one speed)"
    )]
    SpeedRange {
        /// The least speed asked (m/s).
        min: f64,
        /// The most speed asked (m/s).
        max: f64,
    },
    /// A bound on the quantity the objective itself optimises.
    #[error(
        "{which} bounds what objective `{objective}` optimises: the bound could only be inactive or make the design infeasible; give one or the other"
    )]
    BoundOnObjective {
        /// `min-speed`, `max-speed` or `max-power`.
        which: &'static str,
        /// The objective.
        objective: &'static str,
    },
    /// The speed objective on an actuated walker without an effort bound.
    #[error(
        "objective `speed` on model `{model}` needs an effort bound: give max-power (the mean input power, W, finite and > 0)"
    )]
    SpeedNeedsEffort {
        /// The model.
        model: String,
    },
    /// A power bound on a walker without inputs.
    #[error("max-power needs an actuated walker; model `{model}` has no inputs")]
    NoInputsForPower {
        /// The model.
        model: String,
    },
    /// A clearance asked of a walker without a swing foot.
    #[error("clearance needs a swing foot; model `{model}` has none: {why}")]
    NoSwingFoot {
        /// The model.
        model: String,
        /// Why (the striking point moves with the stance foot).
        why: String,
    },
}
