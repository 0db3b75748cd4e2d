//! What a design asks: the parameters to vary with their bounds and start, the objective and
//! the constraints' margins; checked once here for every front end.

use serde::Serialize;

use crate::setup::Setup;
use crate::sim::SimConfig;

use super::error::DesignError;

/// A parameter to vary, with its bounds and its start.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Vary {
    /// The run-time parameter.
    pub name: String,
    /// Lower bound.
    pub lo: f64,
    /// Upper bound.
    pub hi: f64,
    /// The value the design starts from.
    pub start: f64,
}

/// What a design minimises.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Objective {
    /// The specific resistance `SR = p / (m_t g V)` of the periodic gait (as `walker simulate`
    /// reports it per step).
    SpecificResistance,
    /// The mean input power `p` of the periodic gait.
    Power,
    /// The friction the gait needs: the larger of the stance's largest `|lambda_t| /
    /// lambda_n` and the heel strike's `|Lambda_t| / Lambda_n`.
    Friction,
}

impl Objective {
    /// The objective's name as the front ends spell it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Objective::SpecificResistance => "specific_resistance",
            Objective::Power => "power",
            Objective::Friction => "friction",
        }
    }

    /// Whether the objective needs the control inputs (an actuated walker).
    #[must_use]
    pub fn needs_inputs(self) -> bool {
        !matches!(self, Objective::Friction)
    }
}

/// The constraints' margins.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Margins {
    /// Every multiplier's modulus `<= 1 - multiplier`; in `[0, 1)`.
    pub multiplier: f64,
    /// The friction ratios `<= mu0 - friction`; `>= 0`.
    pub friction: f64,
    /// The normal force `>= normal` (N); `>= 0`.
    pub normal: f64,
    /// The strike at least this long after the end of the desired trajectories' last ramp
    /// (`T - T_set >= ramp`, s; for a model with ramps); `>= 0`.
    pub ramp: f64,
}

impl Default for Margins {
    fn default() -> Self {
        Margins {
            multiplier: 0.05,
            friction: 0.01,
            normal: 0.0,
            ramp: 0.01,
        }
    }
}

/// A design request.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DesignRequest {
    /// The parameters varied.
    pub vary: Vec<Vary>,
    /// The objective.
    pub objective: Objective,
    /// The margins of the constraints.
    pub margins: Margins,
    /// The solver's limit on objective evaluations (each with its gradient).
    pub max_evaluations: usize,
    /// The solver's relative tolerance on the objective (its `ftol_rel`).
    pub tol: f64,
    /// Bounds on the inputs along the stance, `max |u_i| <= U_i`: empty for none, one bound
    /// for every input, or one per input (N m or N, each finite and `> 0`).
    pub max_input: Vec<f64>,
}

impl DesignRequest {
    /// Checks the request against `setup`'s walker: each varied name a run-time parameter
    /// (once), finite bounds `lo < hi` within the parameter's own range, the start within the
    /// bounds, margins in range, input bounds finite and positive, one or one per input of an
    /// actuated walker, an objective the walker can have, and a `mu0`.
    ///
    /// # Errors
    /// The first [`DesignError`] found, naming the parameter or margin and the valid range.
    pub fn check(&self, setup: &Setup, cfg: &SimConfig) -> Result<(), DesignError> {
        let model = setup.walker.spec().name().to_owned();
        if self.vary.is_empty() {
            return Err(DesignError::NoParameters);
        }
        for (i, v) in self.vary.iter().enumerate() {
            if self.vary[..i].iter().any(|w| w.name == v.name) {
                return Err(DesignError::Twice {
                    name: v.name.clone(),
                });
            }
            crate::sensitivity::check_parameters(setup, cfg, &[&v.name]).map_err(|e| match e {
                crate::sensitivity::SensitivityError::NotAParameter { name, model, known } => {
                    DesignError::NotAParameter { name, model, known }
                }
                other => DesignError::BoundOutsideRange {
                    name: v.name.clone(),
                    value: v.start,
                    message: other.to_string(),
                },
            })?;
            for (what, value) in [
                ("lower bound", v.lo),
                ("upper bound", v.hi),
                ("start", v.start),
            ] {
                if !value.is_finite() {
                    return Err(DesignError::NotFinite {
                        name: v.name.clone(),
                        what,
                        value,
                    });
                }
            }
            if v.lo >= v.hi {
                return Err(DesignError::EmptyRange {
                    name: v.name.clone(),
                    lo: v.lo,
                    hi: v.hi,
                });
            }
            if !(v.lo..=v.hi).contains(&v.start) {
                return Err(DesignError::StartOutside {
                    name: v.name.clone(),
                    start: v.start,
                    lo: v.lo,
                    hi: v.hi,
                });
            }
            for value in [v.lo, v.hi] {
                setup
                    .with(&v.name, value)
                    .map_err(|e| DesignError::BoundOutsideRange {
                        name: v.name.clone(),
                        value,
                        message: e.to_string(),
                    })?;
            }
        }
        let m = &self.margins;
        if !(m.multiplier.is_finite() && (0.0..1.0).contains(&m.multiplier)) {
            return Err(DesignError::Margin {
                which: "multiplier",
                value: m.multiplier,
                must_be: "in [0, 1)",
            });
        }
        for (which, value) in [
            ("friction", m.friction),
            ("normal", m.normal),
            ("ramp", m.ramp),
        ] {
            if !(value.is_finite() && value >= 0.0) {
                return Err(DesignError::Margin {
                    which,
                    value,
                    must_be: "finite and >= 0",
                });
            }
        }
        let inputs = setup.walker.spec().inputs;
        if !self.max_input.is_empty() {
            if inputs == 0 {
                return Err(DesignError::NoInputsToBound { model });
            }
            if self.max_input.len() != 1 && self.max_input.len() != inputs {
                return Err(DesignError::MaxInputCount {
                    given: self.max_input.len(),
                    inputs,
                });
            }
            if let Some(&value) = self
                .max_input
                .iter()
                .find(|u| !(u.is_finite() && **u > 0.0))
            {
                return Err(DesignError::MaxInput { value });
            }
        }
        if setup.params.get("mu0").is_none() {
            return Err(DesignError::NoMu0 { model });
        }
        if self.objective.needs_inputs() && !setup.walker.spec().is_actuated() {
            return Err(DesignError::NoInputs {
                objective: self.objective.name(),
                model,
            });
        }
        Ok(())
    }
}
