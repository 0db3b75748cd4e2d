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
    /// The gait's mean speed `V = dx / T`, maximised (the program minimises `-V`); on an
    /// actuated walker with an effort bound ([`GaitBounds::max_power`]).
    Speed,
}

impl Objective {
    /// The objective's name as the front ends spell it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Objective::SpecificResistance => "specific_resistance",
            Objective::Power => "power",
            Objective::Friction => "friction",
            Objective::Speed => "speed",
        }
    }

    /// The sign the program minimises the objective with: `-1` for [`Objective::Speed`]
    /// (maximised), `1` for the others.
    #[must_use]
    pub fn sign(self) -> f64 {
        if self == Objective::Speed { -1.0 } else { 1.0 }
    }

    /// Whether the objective needs the control inputs (an actuated walker).
    #[must_use]
    pub fn needs_inputs(self) -> bool {
        matches!(self, Objective::SpecificResistance | Objective::Power)
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

/// Bounds on the gait besides the margins: the swing foot's clearance, a least and a most mean
/// speed and a most mean input power. Each `None` (the default) leaves the design as it is
/// without it (no row, no change to the result).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct GaitBounds {
    /// The swing foot's clearance `H` (m, finite and `> 0`): its height above the floor (normal
    /// to the floor line) at least `H 4 s (1 - s)` at every interior stance sample, `s = t / T`
    /// (`docs/design.md`, "The swing foot's clearance"). Only for a walker whose striking
    /// point moves relative to the stance foot.
    pub clearance: Option<f64>,
    /// The gait's mean speed `V >= min_speed` (m/s, finite and `> 0`). Not with
    /// [`Objective::Speed`], which maximises `V`.
    pub min_speed: Option<f64>,
    /// The gait's mean speed `V <= max_speed` (m/s, finite, `> 0` and at least
    /// [`GaitBounds::min_speed`]; equal to it for a gait at one speed). Not with
    /// [`Objective::Speed`].
    pub max_speed: Option<f64>,
    /// The gait's mean input power `p <= max_power` (W, finite and `> 0`), the effort bound of
    /// [`Objective::Speed`]. Only for an actuated walker, and not with [`Objective::Power`],
    /// which minimises `p`.
    pub max_power: Option<f64>,
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
    /// The swing foot's clearance, a least speed and a most power (none by default).
    pub bounds: GaitBounds,
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
        self.check_bounds(setup, &model)
    }

    /// The checks of [`DesignRequest::bounds`]: each value finite and `> 0`; the least speed
    /// at most the most speed; the clearance on a walker with a swing foot; the power bound on
    /// an actuated walker and the speed objective with it there; no bound on the quantity the
    /// objective itself optimises.
    fn check_bounds(&self, setup: &Setup, model: &str) -> Result<(), DesignError> {
        let b = &self.bounds;
        for (which, value) in [
            ("clearance", b.clearance),
            ("min-speed", b.min_speed),
            ("max-speed", b.max_speed),
            ("max-power", b.max_power),
        ] {
            if let Some(value) = value
                && !(value.is_finite() && value > 0.0)
            {
                return Err(DesignError::Bound {
                    which,
                    value,
                    must_be: "finite and > 0",
                });
            }
        }
        if let (Some(min), Some(max)) = (b.min_speed, b.max_speed)
            && max < min
        {
            return Err(DesignError::SpeedRange { min, max });
        }
        let actuated = setup.walker.spec().is_actuated();
        if let (Objective::Speed, Some(_)) = (self.objective, b.max_speed) {
            return Err(DesignError::BoundOnObjective {
                which: "max-speed",
                objective: "speed",
            });
        }
        match (self.objective, b.min_speed, b.max_power) {
            (Objective::Speed, Some(_), _) => {
                return Err(DesignError::BoundOnObjective {
                    which: "min-speed",
                    objective: "speed",
                });
            }
            (Objective::Power, _, Some(_)) => {
                return Err(DesignError::BoundOnObjective {
                    which: "max-power",
                    objective: "power",
                });
            }
            (Objective::Speed, _, None) if actuated => {
                return Err(DesignError::SpeedNeedsEffort {
                    model: model.to_owned(),
                });
            }
            (_, _, Some(_)) if !actuated => {
                return Err(DesignError::NoInputsForPower {
                    model: model.to_owned(),
                });
            }
            _ => {}
        }
        if b.clearance.is_some() {
            let m = setup.model().map_err(|e| DesignError::NoSwingFoot {
                model: model.to_owned(),
                why: e.to_string(),
            })?;
            if let Some(why) = super::swing::rigid_strike_point(&m) {
                return Err(DesignError::NoSwingFoot {
                    model: model.to_owned(),
                    why,
                });
            }
        }
        Ok(())
    }
}
