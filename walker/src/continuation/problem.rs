//! The interface continuation works against: a [`GaitProblem`] is a family of Poincare maps
//! `P(r, p)` on the section's independent coordinates `r`, with one free parameter `p`, that
//! can say what the cycle through `r` looks like (its [`Cycle`] descriptors and physical
//! [`Tests`]). The paper's walkers fill it in `walker_problem.rs`; a model-driven walker, a
//! constructed map in a test, or the second iterate `P o P` ([`super::SecondIterate`]) fill it
//! the same way.

use nalgebra::DMatrix;
use serde::Serialize;

use crate::model::ImpactRegime;
use crate::poincare::MapError;
use crate::sim::{Failure, FailureKind};

/// What one step of the gait from `r` looks like: the descriptors drawn in the diagrams.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Cycle {
    /// Step period `T` (s).
    #[serde(rename = "T")]
    pub period: f64,
    /// Step length `dx` (Eq. 34; along the slope, Eq. 47) (m).
    pub dx: f64,
    /// Average walking speed `V = dx / T` (m/s): the ordinate of the bifurcation diagrams.
    #[serde(rename = "V")]
    pub speed: f64,
}

/// Which stick-slip structure a step of exact Coulomb friction has: the coarse signature
/// whose change along a branch is labelled [`super::LabelKind::SlipChange`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct SlipStructure {
    /// The stance foot is stuck for part of the step.
    pub sticks: bool,
    /// How the striking foot ends the impact.
    pub impact: ImpactRegime,
}

/// The physical test functions of the step from `r`: each is positive where the gait is
/// physical and changes sign on a boundary of the walking region (`None`: the problem has no
/// such boundary).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Tests {
    /// The smallest normal force on the stance foot over the stance phase (N): lift-off where
    /// it touches 0 (Eq. 23's `lambda`; on the slope `lambda / cos phi`).
    pub min_normal_force: Option<f64>,
    /// Minus the rear foot's impulse of the double-support test (Eq. 11, Eq. 46): the rear leg
    /// leaves the floor where it is positive.
    pub rear_release: Option<f64>,
    /// `T - T_set` (s): the heel strikes before the ramp ends where it is negative.
    pub strike_after_t_set: Option<f64>,
    /// The stick-slip structure (exact Coulomb friction only).
    pub structure: Option<SlipStructure>,
}

impl Tests {
    /// Whether every test says the gait is physical.
    #[must_use]
    pub fn physical(&self) -> bool {
        [
            self.min_normal_force,
            self.rear_release,
            self.strike_after_t_set,
        ]
        .iter()
        .all(|t| t.is_none_or(|v| v >= 0.0))
    }
}

/// One evaluation of the map without its Jacobian.
#[derive(Clone, Debug, PartialEq)]
pub struct MapValue {
    /// `P(r, p)` in the section's independent coordinates.
    pub image: Vec<f64>,
    /// The step's descriptors.
    pub cycle: Cycle,
    /// The step's physical tests.
    pub tests: Tests,
}

/// Why a [`GaitProblem`] could not evaluate its map.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ProblemError {
    /// The Poincare map with its variational equations failed.
    #[error(transparent)]
    Map(#[from] MapError),
    /// A step of the simulator failed (maps evaluated by walking one step: exact Coulomb
    /// friction, or physical parameters other than Table 1's).
    #[error("the step failed at t = {}: {}", .0.t, .0.name())]
    Walk(Box<Failure>),
    /// One of the model's falls (`[[fall]]`; the paper's wheel rolling back onto its rear
    /// spoke is `fell-backward`).
    #[error("{name} at t = {t}")]
    Fall {
        /// The fall's name in the model file.
        name: String,
        /// Time since the impact (s).
        t: f64,
    },
    /// The impact with friction has no rigid-body solution (`docs/impacts.md`).
    #[error("the impact jams at t = {t}")]
    ImpactJam {
        /// Time of the heel strike (s).
        t: f64,
    },
    /// The walker has no such run-time parameter.
    #[error("{name} is not a run-time parameter of model `{model}`; its parameters: {known}")]
    NotAParameter {
        /// The parameter's name.
        name: String,
        /// The model.
        model: String,
        /// The parameters that may be free, comma-separated.
        known: String,
    },
    /// The model at a parameter value cannot be built (its kernels cannot be prepared, or the
    /// value is out of the parameter's range).
    #[error("the model at {name} = {value} cannot be built: {message}")]
    Setup {
        /// The free parameter.
        name: String,
        /// Its value.
        value: f64,
        /// Why.
        message: String,
    },
}

impl ProblemError {
    /// Where the walker itself failed during the step, after it began: the time since the
    /// step's start of a failure of the walker's physics (it lifts off, falls, hits a contact
    /// with no consistent solution, a singular or jammed contact, a strike out of order), as
    /// opposed to a numerical one (non-finite, the integrator giving up, no strike) or a
    /// failure at the step's very start (a start the map could not take). A branch that ends
    /// at such a failure ends at a physical boundary of the walking region.
    #[must_use]
    pub fn physical_at(&self) -> Option<f64> {
        let (t, physical) = match self {
            ProblemError::Walk(f) => (
                f.t,
                !matches!(
                    f.kind,
                    FailureKind::NonFinite
                        | FailureKind::Integrator { .. }
                        | FailureKind::NoImpact
                        | FailureKind::ImpactAtStart
                ),
            ),
            ProblemError::Fall { t, .. } | ProblemError::ImpactJam { t } => (*t, true),
            _ => (0.0, false),
        };
        (physical && t > 0.0).then_some(t)
    }
}

/// A one-parameter family of Poincare maps `r -> P(r, p)` on the independent coordinates of a
/// section, with what continuation needs: the map, its Jacobian `D_r P`, its derivative in the
/// parameter `d P / d p`, and the step's descriptors and physical tests.
///
/// The fixed points of `P(., p)` are the period-one gaits; the eigenvalues of `D_r P` there
/// are their Floquet multipliers (the trivial ones removed by the choice of coordinates).
pub trait GaitProblem: Sync {
    /// The number of independent coordinates `n` of the section.
    fn dim(&self) -> usize;

    /// The free parameter's name (as the parameter table writes it: `mu0`, `T_set`, ...).
    fn parameter_name(&self) -> &str;

    /// `P(r, p)`, the step's descriptors and its tests, without the Jacobian (the cheap
    /// evaluation the corrector iterates on).
    ///
    /// # Errors
    /// The step could not be taken (named in [`ProblemError`]).
    fn map(&self, r: &[f64], p: f64) -> Result<MapValue, ProblemError>;

    /// `P(r, p)` alone, without the descriptors and the physical tests: what the corrector's
    /// iterates and the parameter derivative need. It must equal [`GaitProblem::map`]'s image
    /// exactly (the corrector returns the map's value at the iterate it accepts on this
    /// image). The default takes it from [`GaitProblem::map`]; a problem whose tests cost
    /// extra work skips it.
    ///
    /// # Errors
    /// As [`GaitProblem::map`].
    fn image(&self, r: &[f64], p: f64) -> Result<Vec<f64>, ProblemError> {
        Ok(self.map(r, p)?.image)
    }

    /// `D_r P (r, p)`, row `i` holding `d P_i / d r_j`.
    ///
    /// # Errors
    /// As [`GaitProblem::map`].
    fn jacobian(&self, r: &[f64], p: f64) -> Result<DMatrix<f64>, ProblemError>;

    /// `d P / d p (r, p)` given `P(r, p) = image`. The default is the forward difference
    /// `(P(r, p + h) - P(r, p)) / h` with `h = direction * 1e-6 * max(1, |p|)`; `direction`
    /// (`+1` or `-1`) points into the parameter's valid range. Its error, about
    /// `h |P_pp| / 2` from truncation and `eps_map / h` from the map's own error, is near
    /// `1e-6` relative: it steers the predictor and the corrector (a chord method, which
    /// converges to the same fixed point with any nearby matrix) and never enters a returned
    /// fixed point.
    ///
    /// # Errors
    /// As [`GaitProblem::map`].
    fn parameter_derivative(
        &self,
        r: &[f64],
        p: f64,
        image: &[f64],
        direction: f64,
    ) -> Result<Vec<f64>, ProblemError> {
        let h = direction.signum() * 1e-6 * p.abs().max(1.0);
        let shifted = self.image(r, p + h)?;
        Ok(shifted
            .iter()
            .zip(image)
            .map(|(a, b)| (a - b) / h)
            .collect())
    }

    /// Whether a multiplier at 1 at parameter `p` is structural (a family of cycles, as the
    /// paper's walkers at `mu0 = 0`, whose horizontal momentum is conserved) rather than a
    /// fold or a branch point. The default: never.
    fn has_family_at(&self, p: f64) -> bool {
        let _ = p;
        false
    }

    /// The index in `r` of a velocity that a sticking impact sets exactly to zero and that
    /// the map cannot take slightly off zero (the stance foot's velocity along the floor under
    /// exact Coulomb friction: a foot at rest is `xd == 0` exactly, and a foot sliding at
    /// `1e-17` m/s may be a contact Painleve's paradox forbids). Where an iterate and its image
    /// both have it exactly zero, the continuation keeps it there (`continuation/corrector.rs`). The
    /// default: none.
    fn held_coordinate(&self) -> Option<usize> {
        None
    }

    /// A first guess of a fixed point at `p` (for the paper's walkers, the end of a warm-up
    /// walk), or `None` if the problem has none to offer.
    fn guess(&self, p: f64) -> Option<Vec<f64>>;

    /// The first guesses of a fixed point at `p` to try in order, each with a name for a
    /// message. The default: [`GaitProblem::guess`], named `guess`.
    fn guesses(&self, p: f64) -> Vec<(String, Vec<f64>)> {
        self.guess(p)
            .map(|g| vec![("guess".to_owned(), g)])
            .unwrap_or_default()
    }
}
