//! What a design returns: the parameters, the gait, the objective, every constraint with its
//! slack, and the solver's status and optimality measure.

use serde::Serialize;

use super::evaluate::Evaluation;

/// How a design ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum DesignStatus {
    /// The solver converged (its tolerance on the objective or the parameters reached) at a
    /// point where every constraint holds.
    Optimal,
    /// Every constraint holds, but the solver stopped without converging (its evaluation
    /// limit, or a line search that could make no progress).
    Feasible,
    /// No point the solver visited meets every constraint; [`Design::violated`] names the one
    /// violated most at the returned point.
    Infeasible,
}

/// A varied parameter's designed value and its bounds.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct VariedValue {
    /// The parameter.
    pub name: String,
    /// Its designed value.
    pub value: f64,
    /// Lower bound.
    pub lo: f64,
    /// Upper bound.
    pub hi: f64,
    /// The derivative of the objective in it (the solver's gradient, central differences).
    pub gradient: f64,
}

/// One constraint at the design: `value <= limit` (or `>=` for the normal force) and its
/// slack (positive: holds with room; negative: violated by that much).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ConstraintSlack {
    /// The constraint's name (`multipliers`, `impact-friction`, `normal-force`,
    /// `stance-friction`, `strike-after-ramp`, `input-I`, `clearance`, `min-speed`,
    /// `max-power`).
    pub name: String,
    /// What it measures at the design.
    pub value: f64,
    /// Its bound.
    pub limit: f64,
    /// `<=` or `>=`.
    pub sense: &'static str,
    /// `limit - value` for `<=`, `value - limit` for `>=`.
    pub slack: f64,
    /// Whether it holds (slack `>= -1e-8`, the solver's feasibility tolerance).
    pub holds: bool,
    /// Its Lagrange multiplier in the KKT measure (0 where inactive).
    pub lagrange: f64,
}

/// A finished design.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Design {
    /// How it ended.
    pub status: DesignStatus,
    /// The constraint violated most, for an infeasible design.
    pub violated: Option<String>,
    /// The solver's own termination status (SLSQP's, as NLopt names them).
    pub solver: String,
    /// The objective's name.
    pub objective: &'static str,
    /// The objective at the design (for [`super::Objective::Speed`] the speed itself, which the
    /// design maximises).
    pub value: f64,
    /// The objective at the start.
    pub start_value: f64,
    /// The varied parameters.
    pub parameters: Vec<VariedValue>,
    /// The friction coefficient the constraints hold the foot against.
    pub mu0: f64,
    /// The gait at the design, with the quantities the constraints read.
    pub gait: Evaluation,
    /// Every constraint with its slack.
    pub constraints: Vec<ConstraintSlack>,
    /// The KKT residual: the largest component of the gradient of the Lagrangian, projected
    /// on the bounds, with least-squares multipliers (non-negative) of the active constraints.
    pub kkt_residual: f64,
    /// Gait evaluations (fixed-point solves and sampled steps) the design took.
    pub evaluations: usize,
    /// With restarts, every solve in order (the request's start first), so that one sees
    /// whether the design is a local optimum; empty (and left out of the JSON) without.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub restarts: Vec<Restart>,
}

/// One solve of a design with restarts: where it started and how it ended.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Restart {
    /// The parameters it started from, in the order of the request's `vary`.
    pub start: Vec<f64>,
    /// How it ended; `None` where the start has no periodic gait.
    pub status: Option<DesignStatus>,
    /// The objective at its design (`None` without a gait at the start).
    pub value: Option<f64>,
    /// The designed parameters (empty without a gait at the start).
    pub parameters: Vec<f64>,
    /// The KKT residual at its design (`None` without a gait at the start).
    pub kkt_residual: Option<f64>,
    /// Why there was no design from this start, if there was none.
    pub error: Option<String>,
    /// Gait evaluations it took.
    pub evaluations: usize,
}
