//! Any model's walker as a [`GaitProblem`] ([`WalkerProblem`]): a [`Setup`] with one of its
//! run-time parameters free (the paper's active walker over `mu0` or `T_set`, the passive
//! wheel over `mu0` or `phi`, the compass gait over the slope).
//!
//! The section's independent coordinates are the model's (`[section]`, [`Section`]; the
//! paper's `r = (xd+, th1d+)`). Where the model's kernels give the stance Jacobian (smooth
//! friction, a closed form, the parameters of a compiled fast variant) the map is one stance
//! phase of `profile.rs` (no validity test stops it, so the physical tests are evaluated beyond
//! the walking region too; its image alone, for the corrector's iterates, skips following the
//! normal force) and its Jacobian comes from the variational equations
//! ([`crate::poincare::poincare_map`]). Otherwise (exact Coulomb friction, parameters at run
//! time, models without closed forms) the map is one step of [`crate::sim::walk`], whose
//! failures end the branch, and the Jacobian is by central differences; the smallest normal
//! force is then the smallest seen at the ends of the stance segments (the walk's
//! `lambda_min`), not located between them.

use nalgebra::DMatrix;
use walker_scene::Friction;

use crate::jacobian::StanceJacobian;
use crate::model::{FrictionLaw, ImpactLaw, Model};
use crate::poincare::Section;
use crate::setup::Setup;
use crate::sim::{SimConfig, WalkLimits, walk};

use super::problem::{Cycle, GaitProblem, MapValue, ProblemError, SlipStructure, Tests};
use super::profile;

/// The relative tolerance of the variational equations behind [`GaitProblem::jacobian`] (the
/// absolute one is a hundredth of it, as the simulator's defaults). The Jacobian only gives the
/// multipliers, the tangent and the corrector's starting matrix; no fixed point depends on it.
/// Against the variational equations at `rtol = 1e-13` its entries differ by at most 6.5e-10 at
/// `1e-9` (by 1.4e-7 at `1e-8`) on points of Figs. 8 and 10, far below the `1e-6` that tells a
/// multiplier on the unit circle ([`crate::poincare::UNIT_MULTIPLIER_TOL`]), for a quarter to
/// two fifths less time than at the simulator's `1e-10` (docs/continuation.md).
const JACOBIAN_RTOL: f64 = 1e-9;

/// Steps of the warm-up walk that gives a first guess ([`GaitProblem::guess`]).
const WARMUP_STEPS: usize = 30;

/// The warm-up walk stops earlier once its gait is periodic to this ([`WalkLimits::periodic`]):
/// close enough for Newton's method, which the seed then runs with the exact Jacobian.
const WARMUP_PERIODIC: f64 = 1e-3;

/// The relative tolerance of the warm-up walk: it only gives Newton's method a start within
/// about [`WARMUP_PERIODIC`] of the cycle, where the walk's own error is a thousandth of that.
const WARMUP_RTOL: f64 = 1e-6;

/// A model's walker with one run-time parameter free.
#[derive(Clone, Debug)]
pub struct WalkerProblem {
    setup: Setup,
    param: String,
    cfg: SimConfig,
    dim: usize,
    /// The section's index of the stance foot's velocity along the floor, under exact Coulomb
    /// friction in stance or at the impact ([`GaitProblem::held_coordinate`]).
    held: Option<usize>,
    /// Components of the start replaced ([`WalkerProblem::with_start`]).
    start: Vec<(usize, f64)>,
}

impl WalkerProblem {
    /// The walker of `setup` with the parameter `param` free, simulated with `cfg`.
    ///
    /// # Errors
    /// [`ProblemError::NotAParameter`] if the model has no such parameter, or it is a
    /// parameter of the start, or of a friction law the setup does not use (`c` under exact
    /// Coulomb friction, `mu0` on a frictionless floor); [`ProblemError::Setup`] if the model
    /// cannot be built.
    pub fn new(setup: Setup, param: &str, cfg: SimConfig) -> Result<Self, ProblemError> {
        let spec = setup.walker.spec();
        let index = spec.parameter(param);
        let unused = match index {
            None => true,
            Some(i) => {
                spec.model.parameters[i].stage == walker_scene::model::Stage::Start
                    || (spec.c == Some(i) && setup.friction != Friction::Tanh)
                    || (spec.mu0 == Some(i) && setup.friction == Friction::None)
            }
        };
        if unused {
            let known: Vec<&str> = spec.dynamic_parameters().collect();
            return Err(ProblemError::NotAParameter {
                name: param.to_owned(),
                model: spec.name().to_owned(),
                known: known.join(", "),
            });
        }
        let model = setup.model().map_err(|e| ProblemError::Setup {
            name: param.to_owned(),
            value: setup.params.get(param).unwrap_or(f64::NAN),
            message: e.to_string(),
        })?;
        let section = Section::of(&model);
        let dim = section.dim();
        let n = model.n();
        let coulomb =
            model.friction_law() == FrictionLaw::Coulomb || model.impact_law == ImpactLaw::Coulomb;
        let held = coulomb
            .then(|| section.free().iter().position(|&i| i == n))
            .flatten();
        Ok(Self {
            param: param.to_owned(),
            setup,
            cfg,
            dim,
            held,
            start: Vec::new(),
        })
    }

    /// The free parameter.
    #[must_use]
    pub fn param(&self) -> &str {
        &self.param
    }

    /// The setup (the free parameter at its value in it).
    #[must_use]
    pub fn setup(&self) -> &Setup {
        &self.setup
    }

    /// The model at parameter value `p`.
    ///
    /// # Errors
    /// [`ProblemError::Setup`]: `p` is out of the parameter's range, or the kernels cannot be
    /// prepared.
    pub fn model_at(&self, p: f64) -> Result<Model, ProblemError> {
        let err = |message: String| ProblemError::Setup {
            name: self.param.clone(),
            value: p,
            message,
        };
        let params = self
            .setup
            .params
            .with(&self.param, p)
            .map_err(|e| err(e.to_string()))?;
        self.setup
            .model_with(&params)
            .map_err(|e| err(e.to_string()))
    }

    /// The same walker started from the model's `[start]` with the components `(index into
    /// [q, qd], value)` replaced (a user's `--init`), for the guesses of a branch's start.
    #[must_use]
    pub fn with_start(mut self, components: Vec<(usize, f64)>) -> Self {
        self.start = components;
        self
    }

    /// The start at the model of a parameter value: its `[start]` with the replaced
    /// components.
    fn start_of(&self, model: &Model) -> crate::vector::Vector {
        model.start_state_replacing(&self.start)
    }

    /// The simulation settings.
    #[must_use]
    pub fn config(&self) -> &SimConfig {
        &self.cfg
    }
}

/// The structure signature when stick-slip can occur, else `None`.
fn structure(
    model: &Model,
    sticks: bool,
    impact: crate::model::ImpactRegime,
) -> Option<SlipStructure> {
    (model.friction_law() == FrictionLaw::Coulomb || model.impact_law == ImpactLaw::Coulomb)
        .then_some(SlipStructure { sticks, impact })
}

impl GaitProblem for WalkerProblem {
    fn dim(&self) -> usize {
        self.dim
    }

    fn parameter_name(&self) -> &str {
        &self.param
    }

    fn map(&self, r: &[f64], p: f64) -> Result<MapValue, ProblemError> {
        let model = self.model_at(p)?;
        let section = Section::of(&model);
        let s = section.embed(r);
        let cphi = model.phi().cos();
        let strike = |t: f64| model.ramps_end().map(|t_set| t - t_set);
        if StanceJacobian::new(&model).is_ok() {
            let step = profile::step(&model, &self.cfg, &s, true)?;
            let dx = step.state_plus[0] / cphi;
            return Ok(MapValue {
                image: section.reduce(&step.state_plus),
                cycle: Cycle {
                    period: step.period,
                    dx,
                    speed: dx / step.period,
                },
                tests: Tests {
                    min_normal_force: Some(step.min_normal_force),
                    rear_release: model.spec().double_support().then_some(-step.rear_impulse),
                    strike_after_t_set: strike(step.period),
                    structure: structure(&model, false, step.impact),
                },
            });
        }
        let limits = WalkLimits {
            max_steps: 1,
            ..WalkLimits::default()
        };
        let w = walk(&model, &self.cfg, &s, &limits);
        if let Some(f) = w.failure {
            return Err(ProblemError::Walk(Box::new(f)));
        }
        let last =
            w.steps
                .last()
                .ok_or(ProblemError::Map(crate::poincare::MapError::NoHeelStrike {
                    t: self.cfg.max_step_time,
                }))?;
        Ok(MapValue {
            image: section.reduce(&last.state_plus()),
            cycle: Cycle {
                period: last.period,
                dx: last.dx,
                speed: last.speed,
            },
            tests: Tests {
                min_normal_force: Some(last.lambda_min / cphi),
                rear_release: model.spec().double_support().then_some(-last.rear_impulse),
                strike_after_t_set: strike(last.period),
                structure: structure(&model, last.stuck_time > 0.0, last.impact),
            },
        })
    }

    fn image(&self, r: &[f64], p: f64) -> Result<Vec<f64>, ProblemError> {
        let model = self.model_at(p)?;
        if StanceJacobian::new(&model).is_ok() {
            // The same integration as `map`'s without following the normal force (a third of
            // the cheap map's work).
            let section = Section::of(&model);
            let step = profile::step(&model, &self.cfg, &section.embed(r), false)?;
            return Ok(section.reduce(&step.state_plus));
        }
        Ok(self.map(r, p)?.image)
    }

    fn jacobian(&self, r: &[f64], p: f64) -> Result<DMatrix<f64>, ProblemError> {
        let model = self.model_at(p)?;
        // Only the variational equations; the central differences of the other walkers keep
        // their own tolerances.
        let cfg = if StanceJacobian::new(&model).is_ok() {
            SimConfig {
                rtol: self.cfg.rtol.max(JACOBIAN_RTOL),
                atol: self.cfg.atol.max(JACOBIAN_RTOL / 100.0),
                ..self.cfg
            }
        } else {
            self.cfg
        };
        let section = Section::of(&model);
        let j = section.reduced(&section.map(&cfg, r)?.jacobian);
        let k = self.dim;
        Ok(DMatrix::from_fn(k, k, |i, c| j[i][c]))
    }

    fn has_family_at(&self, p: f64) -> bool {
        let spec = self.setup.walker.spec();
        let mu0 = match spec.mu0 {
            Some(i) if spec.model.parameters[i].name.name == self.param => p,
            Some(i) => self.setup.params.at(i),
            None => 0.0,
        };
        mu0 == 0.0 || self.setup.friction == Friction::None
    }

    fn held_coordinate(&self) -> Option<usize> {
        self.held
    }

    fn guess(&self, p: f64) -> Option<Vec<f64>> {
        let model = self.model_at(p).ok()?;
        let limits = WalkLimits {
            max_steps: WARMUP_STEPS,
            periodic: Some(WARMUP_PERIODIC),
            ..WalkLimits::default()
        };
        let cfg = SimConfig {
            rtol: self.cfg.rtol.max(WARMUP_RTOL),
            atol: self.cfg.atol.max(WARMUP_RTOL / 100.0),
            ..self.cfg
        };
        let w = walk(&model, &cfg, &self.start_of(&model), &limits);
        w.last_state().map(|s| Section::of(&model).reduce(&s))
    }

    /// The end of the warm-up walk ([`GaitProblem::guess`]), then the start itself (the
    /// model's `[start]` at `p`, with [`WalkerProblem::with_start`]'s components): where the
    /// gait is unstable the warm-up walk wanders off or falls, and Newton's method from the
    /// start, a gait's post-impact state for the model's default parameters, may still
    /// converge.
    fn guesses(&self, p: f64) -> Vec<(String, Vec<f64>)> {
        let mut out = Vec::new();
        if let Some(g) = self.guess(p) {
            out.push(("warm-up walk".to_owned(), g));
        }
        if let Ok(model) = self.model_at(p) {
            let section = Section::of(&model);
            let start = self.start_of(&model);
            let on_section = section.embed(&section.reduce(&start));
            // Only a start on the section is a guess of a fixed point (the paper's walkers
            // start at `omega0`, off the controller's manifold).
            let r = section.reduce(&start);
            if on_section
                .iter()
                .zip(start.iter())
                .all(|(a, b)| (a - b).abs() <= 1e-9 * b.abs().max(1.0))
                && out.iter().all(|(_, g)| *g != r)
            {
                out.push(("start".to_owned(), r));
            }
        }
        out
    }
}
