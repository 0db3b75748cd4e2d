//! What one evaluation of the Poincare map gives ([`MapResult`]) and how its Jacobian was
//! computed ([`JacobianMethod`]): the variational equations (`map.rs`) or central differences of
//! a simulated step (`finite_difference.rs`).

use serde::Serialize;

use crate::model::ImpactRegime;
use crate::vector::Vector;

/// One evaluation of the Poincare map.
#[derive(Clone, Debug, PartialEq)]
pub struct MapResult {
    /// The next post-impact state `[q, qd]`, measured from the new stance foot (`x = z = 0`).
    pub state_plus: Vector,
    /// The step period `T` (s).
    pub period: f64,
    /// The step length (Eq. 34; along the slope, Eq. 47) (m).
    pub dx: f64,
    /// `d state_plus_i / d state_j` (row `i`, column `j`).
    pub jacobian: Vec<Vec<f64>>,
    /// How the Jacobian was computed.
    pub method: JacobianMethod,
    /// How the striking foot ended the impact.
    pub impact: ImpactRegime,
}

/// How the Poincare map's Jacobian is computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum JacobianMethod {
    /// Variational equations with the generated Jacobian kernels (the module documentation).
    Variational,
    /// Central differences of one simulated step (`poincare::finite_difference`).
    FiniteDifferences,
    /// Central differences at the steps `h` and `h / 2`, extrapolated (`(4 J(h/2) - J(h)) /
    /// 3`): how `walker fixed-point` evaluates a differenced Jacobian once more at the fixed
    /// point it found ([`super::FixedPointOptions::refine`]).
    ExtrapolatedDifferences,
}

/// Whether the map exists only where the simulator's step does.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum StepCheck {
    /// The stance is integrated through what the simulator stops at (a lift-off, double
    /// support): the map is then not the walker's, but smooth across the boundary, so that
    /// continuation follows a branch past it and locates it by the normal force's sign.
    #[default]
    Through,
    /// The simulator's step from the start is taken first, and its failure (a lift-off, a fall,
    /// double support, ...) is the map's ([`super::MapError::Walk`]), as for the map by
    /// differences, which walks: for Newton's method in a gait design, whose iterates must walk.
    /// An iterate past such a failure, integrated on, can turn stiff (the three-link biped held
    /// with `mu0 = 1e4`, falling backwards: 20 000 to 80 000 steps a map); the check costs one
    /// plain step.
    Walk,
}
