//! A walker on a floor ([`FloorWalker`]): the checks that the floor can set the walker's
//! friction coefficient and slope, and walks whose step `k` runs on the floor's `mu0_k` and
//! `phi_k`.
//!
//! A slope per step rests on a symmetry (`super::translate`): the model's floor is the line of
//! slope `phi` through the origin, and its dynamics see the stance foot only through a
//! translation, so step `k` on the line of slope `phi_k` through its stance foot `p_k` is the
//! model's step at `phi = phi_k` from the state moved by `-p_k`, moved back by `+p_k`. The
//! point the step is seen from only changes with the slope: while `phi_k` is the slope of the
//! step before, the step's floor is that step's line, and it is seen from the same point (so a
//! floor of one slope is the walk without a floor, bit for bit).

use walker_scene::{Distribution, FloorPlan, FloorSpec};

use crate::model::{Model, Parameters};
use crate::setup::Setup;
use crate::sim::{
    FailureKind, Patches, SimConfig, StepFloor, StepModels, Trajectory, Walk, WalkLimits,
    trajectory_by_step, walk_by_step, walk_by_step_stoppable,
};

use super::error::FloorError;
use super::patches::PatchModels;
use super::steps::FloorSteps;
use super::translate::check_translation;

/// A walker and a floor it can walk on: the friction coefficient (and the slope, if the floor
/// sets it) is a run-time parameter, every value the floor gives lies in the parameter's range
/// and prepares kernels, and (for a slope) the model moves with its stance foot.
#[derive(Clone, Debug)]
pub struct FloorWalker<'s> {
    setup: &'s Setup,
    floor: FloorPlan,
    /// The friction coefficient's name among the parameters, if the floor sets it.
    mu0: Option<String>,
    /// The slope's name among the parameters, if the floor sets it.
    phi: Option<String>,
    /// A floor of patches by position, prepared: its regions and their models.
    patches: Option<PatchModels>,
}

/// The values a floor's `quantity` part can give a step, named by their fields (`mu0`,
/// `mu0[2]`, `mu0.lo`, `mu0.dry`).
fn extremes(spec: &FloorSpec, quantity: &str) -> Vec<(String, f64)> {
    match spec {
        FloorSpec::Uniform { mu0 } => vec![(quantity.to_owned(), *mu0)],
        FloorSpec::Steps { mu0 } => mu0
            .iter()
            .enumerate()
            .map(|(i, &x)| (format!("{quantity}[{i}]"), x))
            .collect(),
        FloorSpec::Random { mu0, .. } => {
            let (lo, hi) = mu0.bounds();
            let names = match mu0 {
                Distribution::Markov { dry, .. } if *dry <= lo => ("dry", "icy"),
                Distribution::Markov { .. } => ("icy", "dry"),
                _ => ("lo", "hi"),
            };
            vec![
                (format!("{quantity}.{}", names.0), lo),
                (format!("{quantity}.{}", names.1), hi),
            ]
        }
        FloorSpec::Patches { mu0, patches } => std::iter::once((quantity.to_owned(), *mu0))
            .chain(
                patches
                    .iter()
                    .enumerate()
                    .map(|(i, p)| (format!("patch[{i}].{quantity}"), p.mu0)),
            )
            .collect(),
    }
}

impl<'s> FloorWalker<'s> {
    /// The walker of `setup` on `floor` (a [`FloorSpec`] is a floor of friction only).
    ///
    /// # Errors
    /// For the friction: the model has no friction coefficient, the friction law is `none`,
    /// the scene fixes the coefficient at generation. For the slope: the model has no slope
    /// angle, the scene fixes it, or the model does not move with its stance foot. For both: a
    /// value of the floor is outside the parameter's range, or the kernels cannot be prepared
    /// at the floor's smallest or largest value.
    pub fn new(
        setup: &'s Setup,
        floor: impl Into<FloorPlan>,
    ) -> Result<FloorWalker<'s>, FloorError> {
        let floor = floor.into();
        let spec = setup.walker.spec();
        let model = spec.name().to_owned();
        let mu0 = match &floor.mu0 {
            None => None,
            Some(part) => {
                let Some(index) = spec.mu0 else {
                    return Err(FloorError::NoFriction { model });
                };
                if setup.friction == walker_scene::Friction::None {
                    return Err(FloorError::Frictionless);
                }
                Some(Self::check_part(setup, part, index, "mu0")?)
            }
        };
        let phi = match &floor.phi {
            None => None,
            Some(part) => {
                let Some(index) = spec.slope else {
                    return Err(FloorError::NoSlope { model });
                };
                let name = Self::check_part(setup, part, index, "phi")?;
                check_translation(&spec.model)
                    .map_err(|what| FloorError::NotTranslationInvariant { model, what })?;
                Some(name)
            }
        };
        let patches = match (&floor.mu0, &mu0) {
            (Some(part), Some(name)) => PatchModels::of(setup, name, part)?,
            _ => None,
        };
        Ok(FloorWalker {
            setup,
            floor,
            mu0,
            phi,
            patches,
        })
    }

    /// Checks that `part` can set the parameter `index` (the floor's `quantity`): not fixed
    /// at generation, every value in its range, kernels at the extremes. Returns its name.
    fn check_part(
        setup: &Setup,
        part: &FloorSpec,
        index: usize,
        quantity: &'static str,
    ) -> Result<String, FloorError> {
        let spec = setup.walker.spec();
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
        let values = extremes(part, quantity);
        if let Some((field, value)) = values.iter().find(|(_, x)| !param.range.contains(*x)) {
            return Err(out_of_range(field.clone(), *value));
        }
        let (lo, hi) = part.bounds();
        for value in [lo, hi] {
            let mut params = setup.params.clone();
            params
                .set(&name, value)
                .map_err(|_| out_of_range(quantity.to_owned(), value))?;
            setup
                .model_with(&params)
                .map_err(|source| FloorError::Kernels {
                    name: quantity,
                    value,
                    source,
                })?;
        }
        Ok(name)
    }

    /// The floor.
    #[must_use]
    pub fn floor(&self) -> &FloorPlan {
        &self.floor
    }

    /// The regions of a floor of patches by position, `(from, to, mu0)` in order along the
    /// floor (m; the outer ends infinite; neighbours of one value joined); `None` for a floor
    /// by step.
    #[must_use]
    pub fn regions(&self) -> Option<Vec<(f64, f64, f64)>> {
        self.patches.as_ref().map(PatchModels::regions)
    }

    /// Whether the floor gives the friction by position along the floor (a floor of patches),
    /// not by step: a walk on it is the same for every walk index (no random numbers).
    #[must_use]
    pub fn by_position(&self) -> bool {
        self.patches.is_some()
    }

    /// The friction coefficients of walk `index`'s steps: the floor's, or the walker's own
    /// `mu0` at every step if the floor does not set it.
    pub fn steps(&self, index: u64) -> impl Iterator<Item = f64> + '_ {
        let own = self.own("mu0");
        let mut floor = self.floor.mu0.as_ref().map(|f| FloorSteps::new(f, index));
        std::iter::from_fn(move || Some(floor.as_mut().and_then(Iterator::next).unwrap_or(own)))
    }

    /// The slopes of walk `index`'s steps (rad), where the floor sets the slope (`None` where
    /// it does not): step `k` on the line of slope `phi_k` through its stance foot where the
    /// slope changed (module doc).
    pub fn slopes(&self, index: u64) -> Option<impl Iterator<Item = f64> + '_> {
        let mut floor = FloorSteps::new(self.floor.phi.as_ref()?, index);
        Some(std::iter::from_fn(move || floor.next().or(Some(f64::NAN))))
    }

    /// The walker's own value of the parameter of the floor's `quantity` (`mu0`, `phi`; 0 if
    /// the model has none).
    fn own(&self, quantity: &str) -> f64 {
        let spec = self.setup.walker.spec();
        let index = if quantity == "mu0" {
            spec.mu0
        } else {
            spec.slope
        };
        index.map_or(0.0, |i| self.setup.params.at(i))
    }

    /// Walk number `index` (the stream of a random floor) from the post-impact state
    /// `initial`: step `k`'s stance and the strike that ends it run on the floor's `mu0_k`
    /// and on the line of slope `phi_k` through its stance foot, set between steps; each
    /// step's record carries its `mu0` (and `phi`). A foot that slides at the start of a step
    /// onto a floor of another slope ends the walk ([`FailureKind::SlopeKink`]). The periodic
    /// stop of `limits` is not used (the floor may change after any step).
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

    /// The walker's model on a step of friction `mu0` and slope `phi`, each set only where
    /// given (the mesh of `super::mesh` on a floor that sets the slope).
    ///
    /// # Errors
    /// A value is outside its parameter's range or the kernels cannot take it.
    pub(crate) fn model_on(&self, mu0: Option<f64>, phi: Option<f64>) -> Result<Model, FloorError> {
        let mut params = self.setup.params.clone();
        if let (Some(mu0), Some(name)) = (mu0, &self.mu0) {
            set(self.setup, &mut params, "mu0", name, mu0)?;
        }
        if let (Some(phi), Some(name)) = (phi, &self.phi) {
            set(self.setup, &mut params, "phi", name, phi)?;
        }
        self.setup
            .model_with(&params)
            .map_err(|source| FloorError::Kernels {
                name: if phi.is_some() { "phi" } else { "mu0" },
                value: phi.or(mu0).unwrap_or(f64::NAN),
                source,
            })
    }

    /// The models of walk `index`'s steps.
    fn per_step(&self, index: u64) -> PerStep<'_, 's> {
        PerStep {
            walker: self,
            params: self.setup.params.clone(),
            mu0: self
                .floor
                .mu0
                .as_ref()
                .map(|f| FloorSteps::in_lane(f, index, 0)),
            phi: self
                .floor
                .phi
                .as_ref()
                .map(|f| FloorSteps::in_lane(f, index, 1)),
            next: None,
            current: None,
            step: None,
            seen: None,
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

/// Sets the parameter `name` (the floor's `quantity`) of `params` to `value`.
///
/// # Errors
/// `value` is outside the parameter's range.
fn set(
    setup: &Setup,
    params: &mut Parameters,
    quantity: &'static str,
    name: &str,
    value: f64,
) -> Result<(), FloorError> {
    params
        .set(name, value)
        .map_err(|source| FloorError::Kernels {
            name: quantity,
            value,
            source: crate::model::NoKernels::Source {
                model: setup.walker.spec().name().to_owned(),
                message: source.to_string(),
            },
        })
}

/// The walker's model with the parameter `name` (the floor's `quantity`) of `params` set to
/// `value`.
///
/// # Errors
/// `value` is outside the parameter's range or the kernels cannot take it.
pub(super) fn prepare(
    setup: &Setup,
    params: &mut Parameters,
    quantity: &'static str,
    name: &str,
    value: f64,
) -> Result<Model, FloorError> {
    set(setup, params, quantity, name, value)?;
    setup
        .model_with(params)
        .map_err(|source| FloorError::Kernels {
            name: quantity,
            value,
            source,
        })
}

/// The model of each step of a walk on a floor: prepared again when `mu0` or `phi` changes;
/// for a floor that sets the slope, the point each step is seen from.
struct PerStep<'w, 's> {
    walker: &'w FloorWalker<'s>,
    params: Parameters,
    /// The floor's friction and slope of each step (those it sets).
    mu0: Option<FloorSteps<'w>>,
    phi: Option<FloorSteps<'w>>,
    /// The values of the next step, drawn early by [`StepModels::origin`].
    next: Option<(f64, f64)>,
    /// The last step's `(mu0, phi)` and model.
    current: Option<((f64, f64), Model)>,
    /// The step `current` was asked for: asked again (the failure's frame of a trajectory,
    /// after the walk), the same model, not the next step's.
    step: Option<usize>,
    /// The slope of the last step seen by [`StepModels::origin`] and the point its floor was
    /// seen from.
    seen: Option<(f64, [f64; 2])>,
    /// Why a step's model could not be prepared.
    error: Option<FloorError>,
}

impl PerStep<'_, '_> {
    /// The next step's `(mu0, phi)`: the floor's, or the walker's own where the floor sets
    /// none.
    fn draw(&mut self) -> (f64, f64) {
        let mu0 = match &mut self.mu0 {
            Some(f) => f.next().unwrap_or(f64::NAN),
            None => self.walker.own("mu0"),
        };
        let phi = match &mut self.phi {
            Some(f) => f.next().unwrap_or(f64::NAN),
            None => self.walker.own("phi"),
        };
        (mu0, phi)
    }
}

impl StepModels for PerStep<'_, '_> {
    fn n(&self) -> usize {
        self.walker.setup.walker.spec().n
    }

    fn model(&mut self, step: usize) -> Option<&Model> {
        if self.step == Some(step) && self.next.is_none() {
            return self.current.as_ref().map(|(_, m)| m);
        }
        let values = match self.next.take() {
            Some(v) => v,
            None => self.draw(),
        };
        let same = self.current.as_ref().is_some_and(|((m, p), _)| {
            m.to_bits() == values.0.to_bits() && p.to_bits() == values.1.to_bits()
        });
        if !same {
            let w = self.walker;
            let params = &mut self.params;
            let prepared = w
                .mu0
                .as_ref()
                .map_or(Ok(()), |name| set(w.setup, params, "mu0", name, values.0))
                .and_then(|()| {
                    w.phi
                        .as_ref()
                        .map_or(Ok(()), |name| set(w.setup, params, "phi", name, values.1))
                })
                .and_then(|()| {
                    w.setup.model_with(params).map_err(|source| {
                        // The parameter that changed names the error (the slope if both).
                        let (name, value) = if w.phi.is_some() {
                            ("phi", values.1)
                        } else {
                            ("mu0", values.0)
                        };
                        FloorError::Kernels {
                            name,
                            value,
                            source,
                        }
                    })
                });
            match prepared {
                Ok(model) => self.current = Some((values, model)),
                Err(e) => {
                    self.error = Some(e);
                    return None;
                }
            }
        }
        self.step = Some(step);
        self.current.as_ref().map(|(_, m)| m)
    }

    fn floor(&self) -> Option<StepFloor> {
        self.current.as_ref().map(|((mu0, phi), _)| StepFloor {
            crossings: None,
            mu0: *mu0,
            mu0_strike: None,
            phi: self.walker.phi.as_ref().map(|_| *phi),
        })
    }

    fn patches(&self) -> Option<&dyn Patches> {
        self.walker.patches.as_ref().map(|p| p as &dyn Patches)
    }

    /// The point step `step` is seen from (module doc): while the slope stays, the point of
    /// the step before (the step's floor is that step's line); where it changes, the stance
    /// foot, unless the foot slides there ([`FailureKind::SlopeKink`]). Step 0 comes after the
    /// walker's own slope (its start is on that floor). `None` for a floor without a slope
    /// and while the point is the origin (the model's own floor: no move at all).
    fn origin(&mut self, _step: usize, state: &[f64]) -> Result<Option<[f64; 2]>, FailureKind> {
        if self.walker.phi.is_none() {
            return Ok(None);
        }
        let values = self.draw();
        self.next = Some(values);
        let phi = values.1;
        let (before, point) = self.seen.unwrap_or((self.walker.own("phi"), [0.0, 0.0]));
        let n = self.n();
        let point = if phi.to_bits() == before.to_bits() {
            point
        } else {
            let (xd, zd) = (state[n], state[n + 1]);
            if xd != 0.0 || zd != 0.0 {
                return Err(FailureKind::SlopeKink {
                    from: before,
                    to: phi,
                    speed: xd.hypot(zd),
                });
            }
            [state[0], state[1]]
        };
        self.seen = Some((phi, point));
        Ok((point != [0.0, 0.0]).then_some(point))
    }
}

#[cfg(test)]
mod tests {
    use walker_scene::FloorSpec;

    use super::FloorWalker;
    use crate::setup::Setup;
    use crate::sim::StepModels;

    /// A trajectory asks for the failing step's model again after the walk (to draw the frame
    /// at the failure): that is the step's own model, not the next step's.
    #[test]
    fn the_model_of_a_step_asked_again_is_that_steps_not_the_next() {
        let mut setup = Setup::active_level().expect("the built-in scene");
        setup
            .set("T_set", 0.3)
            .expect("T_set is a run-time parameter");
        let walker = FloorWalker::new(
            &setup,
            FloorSpec::Steps {
                mu0: vec![0.4, 0.05, 0.6],
            },
        )
        .expect("the floor carries the walker");
        let mut steps = walker.per_step(0);
        let mu0 = |m: Option<&crate::model::Model>| m.expect("a model").mu0();
        assert_eq!(mu0(steps.model(0)), 0.4);
        assert_eq!(mu0(steps.model(1)), 0.05);
        assert_eq!(mu0(steps.model(1)), 0.05, "asked again");
        assert_eq!(mu0(steps.model(2)), 0.6);
    }
}
