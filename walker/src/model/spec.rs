//! [`Spec`]: what the simulator reads from a model file besides its kernels: the sizes, the
//! names of the coordinates, points and falls, which parameters are the floor's slope, gravity,
//! friction and gains, the strike's rule, the impact law, the desired trajectories, the start
//! and the descriptors. Everything here comes from the file ([`walker_scene::model::Model`]);
//! nothing is derived.

use std::sync::Arc;

use walker_scene::model::{Descriptor, FallCondition, Model, ModelExpr, Stage};
use walker_scene::{Friction, ImpactLaw};

use crate::vector::MAX_COORDINATES;

/// Why a model file cannot be simulated.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SpecError {
    /// More coordinates than the simulator's state holds.
    #[error("model `{model}` has {n} coordinates; the simulator takes at most {MAX_COORDINATES}")]
    TooManyCoordinates {
        /// The model's name.
        model: String,
        /// Its number of coordinates.
        n: usize,
    },
    /// The strike names a point the model does not declare.
    #[error("model `{model}`: strike point `{point}` is not a declared point")]
    UnknownStrikePoint {
        /// The model's name.
        model: String,
        /// The point.
        point: String,
    },
}

/// A component of the start, given by name (`--init NAME=VALUE`), that cannot be set.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum InitError {
    /// The model has no coordinate or velocity of that name.
    #[error(
        "`{}` is not a coordinate or velocity of model `{model}`; they are: {known}",
        crate::request::shown::name(name)
    )]
    Unknown {
        /// The name given.
        name: String,
        /// The model's name.
        model: String,
        /// Its state's names, comma-separated.
        known: String,
    },
    /// The value is not finite.
    #[error("{name} = {value}: must be finite")]
    NotFinite {
        /// The component.
        name: String,
        /// The value given.
        value: f64,
    },
}

impl InitError {
    /// The component the error is about.
    #[must_use]
    pub fn name(&self) -> &str {
        match self {
            InitError::Unknown { name, .. } | InitError::NotFinite { name, .. } => name,
        }
    }
}

/// A model file as the simulator reads it (shared by every [`super::Model`] built from it).
#[derive(Debug)]
pub struct Spec {
    /// The model file, checked.
    pub model: Model,
    /// The number of coordinates `n`.
    pub n: usize,
    /// The number of inputs (and of outputs) `m`.
    pub inputs: usize,
    /// The number of constraint rows of the frictionless impact (the striking point and the
    /// locks).
    pub impact_rows: usize,
    /// The index of the striking point among the points.
    pub strike_point: usize,
    /// The index of the slope angle among the parameters (`None`: level floor).
    pub slope: Option<usize>,
    /// The index of gravity among the parameters.
    pub gravity: usize,
    /// The index of the friction coefficient `mu0` among the parameters.
    pub mu0: Option<usize>,
    /// The index of the tanh law's sharpness `c` among the parameters.
    pub c: Option<usize>,
    /// The indices of the gains `K_P`, `K_D` among the parameters.
    pub gains: Option<(usize, usize)>,
}

impl Spec {
    /// The spec of `model`.
    ///
    /// # Errors
    /// More than [`MAX_COORDINATES`] coordinates.
    pub fn new(model: Model) -> Result<Arc<Spec>, SpecError> {
        let n = model.coordinates.len();
        if n > MAX_COORDINATES {
            return Err(SpecError::TooManyCoordinates {
                model: model.name.clone(),
                n,
            });
        }
        let param = |name: &str| model.parameters.iter().position(|p| p.name.name == name);
        let strike_point = model
            .points
            .iter()
            .position(|p| p.name.name == model.strike.point.name)
            .ok_or_else(|| SpecError::UnknownStrikePoint {
                model: model.name.clone(),
                point: model.strike.point.name.clone(),
            })?;
        // The loader resolved these names against the parameters.
        let slope = model.floor.slope.as_ref().and_then(|s| param(&s.name));
        let gravity = param(&model.floor.gravity.name).unwrap_or(0);
        let mu0 = model.stance.mu0.as_ref().and_then(|s| param(&s.name));
        let c = model.stance.c.as_ref().and_then(|s| param(&s.name));
        let gains = model
            .control
            .as_ref()
            .and_then(|c| Some((param(&c.kp.name)?, param(&c.kd.name)?)));
        Ok(Arc::new(Spec {
            n,
            inputs: model.inputs.len(),
            impact_rows: 1 + model.impact.locks.len(),
            strike_point,
            slope,
            gravity,
            mu0,
            c,
            gains,
            model,
        }))
    }

    /// The model's name.
    #[must_use]
    pub fn name(&self) -> &str {
        &self.model.name
    }

    /// The coordinates' names, in the order of `q`.
    pub fn coordinates(&self) -> impl Iterator<Item = &str> {
        self.model.coordinates.iter().map(|c| c.name.name.as_str())
    }

    /// The names of the mechanical state's components: the coordinates, then their velocities
    /// (`th1`, then `th1d`).
    #[must_use]
    pub fn state_names(&self) -> Vec<String> {
        let q: Vec<String> = self.coordinates().map(str::to_owned).collect();
        let qd = q.iter().map(|c| format!("{c}d"));
        q.iter().cloned().chain(qd).collect()
    }

    /// The index of state component `name` (a coordinate or a velocity) in `[q, qd]`.
    #[must_use]
    pub fn state_index(&self, name: &str) -> Option<usize> {
        self.state_names().iter().position(|s| s == name)
    }

    /// The components `(name, value)` of a start given by name, as indices in `[q, qd]` with
    /// their values (apply them with [`super::Model::start_state_replacing`]).
    ///
    /// # Errors
    /// A name that is not a coordinate or velocity, or a value that is not finite.
    pub fn start_components(&self, init: &[(String, f64)]) -> Result<Vec<(usize, f64)>, InitError> {
        init.iter()
            .map(|(name, value)| {
                let i = self.state_index(name).ok_or_else(|| InitError::Unknown {
                    name: name.clone(),
                    model: self.name().to_owned(),
                    known: self.state_names().join(", "),
                })?;
                if !value.is_finite() {
                    return Err(InitError::NotFinite {
                        name: name.clone(),
                        value: *value,
                    });
                }
                Ok((i, *value))
            })
            .collect()
    }

    /// The names of the points, in the order of the `points` kernel.
    pub fn points(&self) -> impl Iterator<Item = &str> {
        self.model.points.iter().map(|p| p.name.name.as_str())
    }

    /// The falls' names, in the order of the `events` kernel's `fall_*` outputs.
    pub fn falls(&self) -> impl Iterator<Item = &str> {
        self.model.falls.iter().map(|f| f.name.name.as_str())
    }

    /// The point a fall watches, if it watches a point (else a guard).
    #[must_use]
    pub fn fall_point(&self, fall: usize) -> Option<&str> {
        match &self.model.falls.get(fall)?.condition {
            FallCondition::Point(p) => Some(&p.name),
            FallCondition::Guard(_) => None,
        }
    }

    /// Whether the model has inputs (and so the output-following control).
    #[must_use]
    pub fn is_actuated(&self) -> bool {
        self.inputs > 0
    }

    /// Whether the model's friction laws include `law`.
    #[must_use]
    pub fn has_friction(&self, law: Friction) -> bool {
        self.model.stance.friction.contains(&law)
    }

    /// The model's default impact law.
    #[must_use]
    pub fn default_impact(&self) -> ImpactLaw {
        self.model.impact.law
    }

    /// Whether the double-support test applies at the impact.
    #[must_use]
    pub fn double_support(&self) -> bool {
        self.model.impact.double_support
    }

    /// Whether the model reports `d`.
    #[must_use]
    pub fn reports(&self, d: Descriptor) -> bool {
        self.model.descriptors.contains(&d)
    }

    /// The names of the parameters of the dynamics (every stage but `start`), in file order.
    pub fn dynamic_parameters(&self) -> impl Iterator<Item = &str> {
        self.model
            .parameters
            .iter()
            .filter(|p| p.stage != Stage::Start)
            .map(|p| p.name.name.as_str())
    }

    /// The index of the parameter called `name`.
    #[must_use]
    pub fn parameter(&self, name: &str) -> Option<usize> {
        self.model
            .parameters
            .iter()
            .position(|p| p.name.name == name)
    }

    /// The value of `e` at the parameter values `values` (by index), NaN where it cannot be
    /// evaluated (it names something that is not a parameter).
    #[must_use]
    pub fn eval(&self, e: &ModelExpr, values: &[f64]) -> f64 {
        e.expr
            .eval(&|name| self.parameter(name).and_then(|i| values.get(i).copied()))
            .unwrap_or(f64::NAN)
    }
}
