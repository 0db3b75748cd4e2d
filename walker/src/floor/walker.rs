//! A walker on a floor ([`FloorWalker`]): the checks that the floor can set the walker's
//! friction coefficient, and walks whose step `k` runs on the floor's `mu0_k`.

use walker_scene::FloorSpec;

use crate::model::{Model, Parameters};
use crate::setup::Setup;
use crate::sim::{
    SimConfig, StepFloor, StepModels, Trajectory, Walk, WalkLimits, trajectory_by_step,
    walk_by_step, walk_by_step_stoppable,
};

use super::error::FloorError;
use super::steps::FloorSteps;

/// A walker and a floor it can walk on: its friction coefficient is a run-time parameter, and
/// every value the floor gives lies in the parameter's range and prepares kernels.
#[derive(Clone, Debug)]
pub struct FloorWalker<'s> {
    setup: &'s Setup,
    floor: FloorSpec,
    /// The friction coefficient's index among the parameters, and its name.
    mu0: (usize, String),
}

impl<'s> FloorWalker<'s> {
    /// The walker of `setup` on `floor`.
    ///
    /// # Errors
    /// The model has no friction coefficient, the friction law is `none`, the scene fixes the
    /// coefficient at generation, a value of the floor is outside its range, or the kernels
    /// cannot be prepared at the floor's smallest or largest value.
    pub fn new(setup: &'s Setup, floor: FloorSpec) -> Result<FloorWalker<'s>, FloorError> {
        let spec = setup.walker.spec();
        let Some(index) = spec.mu0 else {
            return Err(FloorError::NoFriction {
                model: spec.name().to_owned(),
            });
        };
        if setup.friction == walker_scene::Friction::None {
            return Err(FloorError::Frictionless);
        }
        let param = &spec.model.parameters[index];
        let name = param.name.name.clone();
        if let Some((_, value)) = setup.fixed.iter().find(|(n, _)| *n == name) {
            return Err(FloorError::Fixed {
                name,
                value: *value,
            });
        }
        let out_of_range = |field: String, value: f64| FloorError::OutOfRange {
            field,
            value,
            name: name.clone(),
            range: param.range.to_string(),
            model: spec.name().to_owned(),
        };
        let values: Vec<(String, f64)> = match &floor {
            FloorSpec::Uniform { mu0 } => vec![("mu0".to_owned(), *mu0)],
            FloorSpec::Steps { mu0 } => mu0
                .iter()
                .enumerate()
                .map(|(i, &x)| (format!("mu0[{i}]"), x))
                .collect(),
            FloorSpec::Random { mu0, .. } => {
                let (lo, hi) = mu0.bounds();
                let names = match mu0 {
                    walker_scene::Distribution::Markov { dry, .. } if *dry <= lo => {
                        ("mu0.dry", "mu0.icy")
                    }
                    walker_scene::Distribution::Markov { .. } => ("mu0.icy", "mu0.dry"),
                    _ => ("mu0.lo", "mu0.hi"),
                };
                vec![(names.0.to_owned(), lo), (names.1.to_owned(), hi)]
            }
        };
        if let Some((field, value)) = values.iter().find(|(_, x)| !param.range.contains(*x)) {
            return Err(out_of_range(field.clone(), *value));
        }
        let (lo, hi) = floor.bounds();
        for value in [lo, hi] {
            let mut params = setup.params.clone();
            params
                .set(&name, value)
                .map_err(|_| out_of_range("mu0".to_owned(), value))?;
            setup
                .model_with(&params)
                .map_err(|source| FloorError::Kernels { value, source })?;
        }
        Ok(FloorWalker {
            setup,
            floor,
            mu0: (index, name),
        })
    }

    /// The floor.
    #[must_use]
    pub fn floor(&self) -> &FloorSpec {
        &self.floor
    }

    /// The friction coefficients of walk `index`'s steps.
    #[must_use]
    pub fn steps(&self, index: u64) -> FloorSteps<'_> {
        FloorSteps::new(&self.floor, index)
    }

    /// Walk number `index` (the stream of a random floor) from the post-impact state
    /// `initial`: step `k`'s stance and the strike that ends it run on the floor's `mu0_k`,
    /// set between steps; each step's record carries its `mu0`. The periodic stop of
    /// `limits` is not used (the floor may change after any step).
    ///
    /// # Errors
    /// A step's kernels cannot be prepared ([`FloorWalker::new`] checked the floor's extremes,
    /// so this is not expected).
    pub fn walk(
        &self,
        index: u64,
        cfg: &SimConfig,
        initial: &[f64],
        limits: &WalkLimits,
    ) -> Result<Walk, FloorError> {
        let limits = WalkLimits {
            periodic: None,
            ..*limits
        };
        let mut models = self.per_step(index);
        let walk = walk_by_step(&mut models, cfg, initial, &limits);
        match models.error {
            Some(e) => Err(e),
            None => Ok(walk),
        }
    }

    /// Walk number `index` as [`FloorWalker::walk`] walks it, sampled every `dt` from the dense
    /// output for an animation ([`crate::sim::trajectory()`], at most `max_frames` frames).
    ///
    /// # Errors
    /// As [`FloorWalker::walk`].
    pub fn trajectory(
        &self,
        index: u64,
        cfg: &SimConfig,
        initial: &[f64],
        limits: &WalkLimits,
        dt: f64,
        max_frames: usize,
    ) -> Result<Trajectory, FloorError> {
        let limits = WalkLimits {
            periodic: None,
            ..*limits
        };
        let mut models = self.per_step(index);
        let tr = trajectory_by_step(&mut models, cfg, initial, &limits, dt, max_frames);
        match models.error {
            Some(e) => Err(e),
            None => Ok(tr),
        }
    }

    /// The walker's model on a floor of friction `mu0` (the mesh of `super::mesh` prepares
    /// one per floor sample).
    ///
    /// # Errors
    /// `mu0` is outside the parameter's range or the kernels cannot take it.
    pub(crate) fn model_at(&self, mu0: f64) -> Result<Model, FloorError> {
        let mut params = self.setup.params.clone();
        params
            .set(&self.mu0.1, mu0)
            .map_err(|source| FloorError::Kernels {
                value: mu0,
                source: crate::model::NoKernels::Source {
                    model: self.setup.walker.spec().name().to_owned(),
                    message: source.to_string(),
                },
            })?;
        self.setup
            .model_with(&params)
            .map_err(|source| FloorError::Kernels { value: mu0, source })
    }

    /// The models of walk `index`'s steps.
    fn per_step(&self, index: u64) -> PerStep<'_, 's> {
        PerStep {
            walker: self,
            params: self.setup.params.clone(),
            steps: self.steps(index),
            current: None,
            error: None,
        }
    }

    /// [`FloorWalker::walk`], abandoned (`None`) when `stop()`, asked before every step,
    /// answers true.
    ///
    /// # Errors
    /// As [`FloorWalker::walk`].
    pub fn walk_stoppable(
        &self,
        index: u64,
        cfg: &SimConfig,
        initial: &[f64],
        limits: &WalkLimits,
        stop: &dyn Fn() -> bool,
    ) -> Result<Option<Walk>, FloorError> {
        let limits = WalkLimits {
            periodic: None,
            ..*limits
        };
        let mut models = self.per_step(index);
        let (walk, stopped) = walk_by_step_stoppable(&mut models, cfg, initial, &limits, stop);
        match models.error {
            Some(e) => Err(e),
            None if stopped => Ok(None),
            None => Ok(Some(walk)),
        }
    }
}

/// The model of each step of a walk on a floor: prepared again when `mu0` changes.
struct PerStep<'w, 's> {
    walker: &'w FloorWalker<'s>,
    params: Parameters,
    steps: FloorSteps<'w>,
    /// The last step's `mu0` and model.
    current: Option<(f64, Model)>,
    /// Why a step's model could not be prepared.
    error: Option<FloorError>,
}

impl StepModels for PerStep<'_, '_> {
    fn n(&self) -> usize {
        self.walker.setup.walker.spec().n
    }

    fn model(&mut self, _step: usize) -> Option<&Model> {
        let mu0 = self.steps.next()?;
        let same = self
            .current
            .as_ref()
            .is_some_and(|(m, _)| m.to_bits() == mu0.to_bits());
        if !same {
            let (index, name) = &self.walker.mu0;
            debug_assert_eq!(self.params.spec().parameter(name), Some(*index));
            let prepared = self
                .params
                .set(name, mu0)
                .map_err(|source| FloorError::Kernels {
                    value: mu0,
                    source: crate::model::NoKernels::Source {
                        model: self.walker.setup.walker.spec().name().to_owned(),
                        message: source.to_string(),
                    },
                })
                .and_then(|()| {
                    self.walker
                        .setup
                        .model_with(&self.params)
                        .map_err(|source| FloorError::Kernels { value: mu0, source })
                });
            match prepared {
                Ok(model) => self.current = Some((mu0, model)),
                Err(e) => {
                    self.error = Some(e);
                    return None;
                }
            }
        }
        self.current.as_ref().map(|(_, m)| m)
    }

    fn floor(&self) -> Option<StepFloor> {
        self.current
            .as_ref()
            .map(|(mu0, _)| StepFloor { mu0: *mu0 })
    }
}
