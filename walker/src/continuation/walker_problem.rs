//! The paper's two walkers as a [`GaitProblem`]: the active walker on level ground and the
//! passive wheel on the slope, with any of their parameters free.
//!
//! The section's independent coordinates are `r = (xd+, th1d+)` ([`crate::poincare::embed`]).
//! With smooth (tanh) friction and Table 1 the map is one stance phase of `profile.rs` (no
//! validity test stops it, so the physical tests are evaluated beyond the walking region too;
//! its image alone, for the corrector's iterates, skips following the normal force) and its
//! Jacobian comes from the variational equations ([`crate::poincare::poincare_map`]).
//! Otherwise (exact Coulomb friction, other physical parameters) the map is one step of
//! [`crate::sim::walk`], whose failures end the branch, and the Jacobian is by central
//! differences; the smallest normal force is then the smallest seen at the ends of the stance
//! segments (the walk's `lambda_min`), not located between them.

use nalgebra::DMatrix;
use walker_scene::Param;

use crate::jacobian::Jac;
use crate::model::{FrictionLaw, ImpactLaw, Model};
use crate::poincare::{embed, poincare_map, reduce, reduced_jacobian};
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

/// One of the paper's walkers with one parameter free.
#[derive(Clone, Debug)]
pub struct PaperWalker {
    setup: Setup,
    param: Param,
    cfg: SimConfig,
    omega0: Option<f64>,
}

impl PaperWalker {
    /// The walker of `setup` with `param` free, simulated with `cfg`.
    ///
    /// # Errors
    /// [`ProblemError::NotAParameter`] if the walker has no such parameter (`phi` on level
    /// ground, `T_set`, `K_P`, `K_D` for the passive wheel, `c` under exact Coulomb friction).
    pub fn new(setup: Setup, param: Param, cfg: SimConfig) -> Result<Self, ProblemError> {
        let active = setup.model().is_active();
        let absent = match param {
            Param::Phi => active,
            Param::TSet | Param::KP | Param::KD => !active,
            Param::C => setup.friction == FrictionLaw::Coulomb,
            _ => false,
        };
        if absent {
            return Err(ProblemError::NotAParameter { name: param.name() });
        }
        Ok(Self {
            setup,
            param,
            cfg,
            omega0: None,
        })
    }

    /// The same walker whose warm-up walks start with `th1d = omega0` (Eq. 33) instead of the
    /// model's default.
    #[must_use]
    pub fn with_omega0(self, omega0: f64) -> Self {
        Self {
            omega0: Some(omega0),
            ..self
        }
    }

    /// The free parameter.
    #[must_use]
    pub fn param(&self) -> Param {
        self.param
    }

    /// The model at parameter value `p`.
    #[must_use]
    pub fn model_at(&self, p: f64) -> Model {
        let mut setup = self.setup.clone();
        if setup.physical.set(self.param, p) {
            // The fast kernels have Table 1 compiled in.
            setup.fast = false;
        } else {
            setup.runtime.set(self.param, p);
        }
        setup.model()
    }

    /// The simulation settings.
    #[must_use]
    pub fn config(&self) -> &SimConfig {
        &self.cfg
    }

    fn r2(r: &[f64]) -> [f64; 2] {
        [
            r.first().copied().unwrap_or(f64::NAN),
            r.get(1).copied().unwrap_or(f64::NAN),
        ]
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

impl GaitProblem for PaperWalker {
    fn dim(&self) -> usize {
        2
    }

    fn parameter_name(&self) -> &str {
        self.param.name()
    }

    fn map(&self, r: &[f64], p: f64) -> Result<MapValue, ProblemError> {
        let model = self.model_at(p);
        let s = embed(&model, Self::r2(r));
        let cphi = model.runtime.phi.cos();
        let strike = |t: f64| model.is_active().then_some(t - model.runtime.t_set);
        if Jac::new(&model).is_ok() {
            let step = profile::step(&model, &self.cfg, &s, true)?;
            let dx = step.state_plus[0] / cphi;
            return Ok(MapValue {
                image: reduce(&step.state_plus).to_vec(),
                cycle: Cycle {
                    period: step.period,
                    dx,
                    speed: dx / step.period,
                },
                tests: Tests {
                    min_normal_force: Some(step.min_normal_force),
                    rear_release: Some(-step.rear_impulse),
                    strike_after_t_set: strike(step.period),
                    structure: structure(&model, false, step.impact),
                },
            });
        }
        let limits = WalkLimits {
            max_steps: 1,
            ..WalkLimits::default()
        };
        let w = walk(&model, &self.cfg, s, &limits);
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
            image: reduce(&last.state_plus()).to_vec(),
            cycle: Cycle {
                period: last.period,
                dx: last.dx,
                speed: last.speed,
            },
            tests: Tests {
                min_normal_force: Some(last.lambda_min / cphi),
                rear_release: Some(-last.rear_impulse),
                strike_after_t_set: strike(last.period),
                structure: structure(&model, last.stuck_time > 0.0, last.impact),
            },
        })
    }

    fn image(&self, r: &[f64], p: f64) -> Result<Vec<f64>, ProblemError> {
        let model = self.model_at(p);
        if Jac::new(&model).is_ok() {
            // The same integration as `map`'s without following the normal force (a third of
            // the cheap map's work).
            let step = profile::step(&model, &self.cfg, &embed(&model, Self::r2(r)), false)?;
            return Ok(reduce(&step.state_plus).to_vec());
        }
        Ok(self.map(r, p)?.image)
    }

    fn jacobian(&self, r: &[f64], p: f64) -> Result<DMatrix<f64>, ProblemError> {
        let model = self.model_at(p);
        // Only the variational equations; the central differences of the other walkers keep
        // their own tolerances.
        let cfg = if Jac::new(&model).is_ok() {
            SimConfig {
                rtol: self.cfg.rtol.max(JACOBIAN_RTOL),
                atol: self.cfg.atol.max(JACOBIAN_RTOL / 100.0),
                ..self.cfg
            }
        } else {
            self.cfg
        };
        let m = poincare_map(&model, &cfg, &embed(&model, Self::r2(r)))?;
        let j = reduced_jacobian(&model, &m.jacobian);
        Ok(DMatrix::from_fn(2, 2, |i, k| j[i][k]))
    }

    fn has_family_at(&self, p: f64) -> bool {
        let mu0 = if self.param == Param::Mu0 {
            p
        } else {
            self.setup.runtime.mu0
        };
        mu0 == 0.0
    }

    fn guess(&self, p: f64) -> Option<Vec<f64>> {
        let model = self.model_at(p);
        let omega0 = self.omega0.unwrap_or_else(|| model.default_omega0());
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
        let w = walk(&model, &cfg, model.initial_state(omega0), &limits);
        w.last_state().map(|s| reduce(&s).to_vec())
    }
}
