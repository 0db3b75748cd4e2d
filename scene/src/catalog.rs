//! The kernel names of `docs/kernels.md` and the walker structures each belongs to.
//!
//! This table only says *which* kernels exist and where they apply; what they compute is the
//! derivation's business (see `docs/kernels.md` for inputs, outputs and sign conventions).

use crate::structure::{Floor, Friction, Torso};

/// A kernel of the contract in `docs/kernels.md`.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub enum KernelName {
    /// `mass_matrix`: `M` (Eq. 2).
    MassMatrix,
    /// `bias`: `h` (Eq. 20).
    Bias,
    /// `lambda_level`: the ground reaction on the level floor (Eqs. 22-23).
    LambdaLevel,
    /// `projection_level`: `Y` (Eqs. 28-29).
    ProjectionLevel,
    /// `control_level`: `A, B` of the output-following control (Eqs. 30-31).
    ControlLevel,
    /// `accel_level`: `qdd` on the level floor (Eq. 27).
    AccelLevel,
    /// `lambda_slope`: the ground reaction on the slope (Eq. 22 with Eqs. 36, 38).
    LambdaSlope,
    /// `accel_slope`: `qdd` on the slope (Eq. 27 with Eqs. 36, 38).
    AccelSlope,
    /// `impact3_level`: impact with three constraints (Eqs. 6-10).
    Impact3Level,
    /// `impact2_level`: impact with the rear foot free (Eqs. 12-16).
    Impact2Level,
    /// `impact_slope`: the passive wheel's impact on the slope (Eqs. 39-42).
    ImpactSlope,
    /// `impact2_slope`: slope impact with the rear foot on the slope (Eq. 46).
    Impact2Slope,
    /// `closed_loop_level`: `qddot` and `u` under the output-following control (Eqs. 27, 31).
    ClosedLoopLevel,
    /// `closed_loop_level_jacobian`: partials of the closed-loop `qddot` by `(th1, th1d, mu, v)`.
    ClosedLoopLevelJacobian,
    /// `accel_slope_jacobian`: partials of the slope `qddot` by `(th1, th1d, mu)`.
    AccelSlopeJacobian,
    /// `impact2_level_jacobian`: partials of `qdot+` (Eqs. 12-16) by `(th1, xd, zd, th1d, th2d)`.
    Impact2LevelJacobian,
    /// `impact_slope_jacobian`: partials of `qdot+` (Eqs. 39-42) by `(th1, xd, zd, th1d, th2d)`.
    ImpactSlopeJacobian,
    /// `stick_level`: `qddot` and the ground force `[lambda_t, lambda_n]` with the stance foot
    /// stuck to the level floor (Coulomb friction's stick phase; not in the paper).
    StickLevel,
    /// `closed_loop_stick_level`: `qddot`, `u` and `[lambda_t, lambda_n]` with the foot stuck,
    /// under the output-following control recomputed for it (Eqs. 30-31 with the foot held;
    /// not in the paper).
    ClosedLoopStickLevel,
    /// `stick_slope`: `qddot` and `[lambda_t, lambda_n]` of the passive wheel with the foot
    /// stuck to the slope (not in the paper).
    StickSlope,
    /// `impact_coulomb_level`: the level impact's ingredients for Coulomb friction at the
    /// striking foot: the torso lock applied, the foot's velocity, the Delassus matrix and the
    /// velocity response to the foot's impulse (not in the paper; `docs/impacts.md`).
    ImpactCoulombLevel,
    /// `impact_coulomb_slope`: the same on the slope, without a torso lock.
    ImpactCoulombSlope,
    /// `fore_foot`: position and velocity of the fore foot (Eqs. 3, 39).
    ForeFoot,
    /// `energy`: kinetic and potential energy.
    Energy,
}

/// The equation reference of the impact kernels with friction: not in the paper.
pub const IMPACT_COULOMB_EQUATION: &str =
    "impact with Coulomb friction, not in the paper; Eqs. 6-10 with the foot's tangent added";

/// `(kernel, name, paper equations)`, in catalogue (and default file) order.
const TABLE: [(KernelName, &str, &str); 24] = [
    (KernelName::MassMatrix, "mass_matrix", "Eq. 2"),
    (KernelName::Bias, "bias", "Eq. 20"),
    (KernelName::LambdaLevel, "lambda_level", "Eqs. 22-23"),
    (
        KernelName::ProjectionLevel,
        "projection_level",
        "Eqs. 28-29",
    ),
    (KernelName::ControlLevel, "control_level", "Eqs. 30-31"),
    (KernelName::AccelLevel, "accel_level", "Eq. 27"),
    (
        KernelName::LambdaSlope,
        "lambda_slope",
        "Eq. 22 with Eqs. 36, 38",
    ),
    (
        KernelName::AccelSlope,
        "accel_slope",
        "Eq. 27 with Eqs. 36, 38",
    ),
    (KernelName::Impact3Level, "impact3_level", "Eqs. 6-10"),
    (KernelName::Impact2Level, "impact2_level", "Eqs. 12-16"),
    (KernelName::ImpactSlope, "impact_slope", "Eqs. 39-42"),
    (KernelName::Impact2Slope, "impact2_slope", "Eq. 46"),
    (
        KernelName::ClosedLoopLevel,
        "closed_loop_level",
        "Eqs. 27, 31",
    ),
    (
        KernelName::ClosedLoopLevelJacobian,
        "closed_loop_level_jacobian",
        "Eqs. 27, 31",
    ),
    (
        KernelName::AccelSlopeJacobian,
        "accel_slope_jacobian",
        "Eq. 27 with Eqs. 36, 38",
    ),
    (
        KernelName::Impact2LevelJacobian,
        "impact2_level_jacobian",
        "Eqs. 12-16",
    ),
    (
        KernelName::ImpactSlopeJacobian,
        "impact_slope_jacobian",
        "Eqs. 39-42",
    ),
    (
        KernelName::StickLevel,
        "stick_level",
        "stick phase, not in the paper; Eq. 19 with both foot coordinates held",
    ),
    (
        KernelName::ClosedLoopStickLevel,
        "closed_loop_stick_level",
        "stick phase, not in the paper; Eqs. 30-31 with both foot coordinates held",
    ),
    (
        KernelName::StickSlope,
        "stick_slope",
        "stick phase, not in the paper; Eq. 19 with both foot coordinates held",
    ),
    (
        KernelName::ImpactCoulombLevel,
        "impact_coulomb_level",
        IMPACT_COULOMB_EQUATION,
    ),
    (
        KernelName::ImpactCoulombSlope,
        "impact_coulomb_slope",
        IMPACT_COULOMB_EQUATION,
    ),
    (KernelName::ForeFoot, "fore_foot", "Eqs. 3, 39"),
    (KernelName::Energy, "energy", "-"),
];

impl KernelName {
    /// Every kernel, in catalogue order.
    pub const ALL: [KernelName; 24] = [
        KernelName::MassMatrix,
        KernelName::Bias,
        KernelName::LambdaLevel,
        KernelName::ProjectionLevel,
        KernelName::ControlLevel,
        KernelName::AccelLevel,
        KernelName::LambdaSlope,
        KernelName::AccelSlope,
        KernelName::Impact3Level,
        KernelName::Impact2Level,
        KernelName::ImpactSlope,
        KernelName::Impact2Slope,
        KernelName::ClosedLoopLevel,
        KernelName::ClosedLoopLevelJacobian,
        KernelName::AccelSlopeJacobian,
        KernelName::Impact2LevelJacobian,
        KernelName::ImpactSlopeJacobian,
        KernelName::StickLevel,
        KernelName::ClosedLoopStickLevel,
        KernelName::StickSlope,
        KernelName::ImpactCoulombLevel,
        KernelName::ImpactCoulombSlope,
        KernelName::ForeFoot,
        KernelName::Energy,
    ];

    fn row(self) -> (KernelName, &'static str, &'static str) {
        TABLE
            .iter()
            .copied()
            .find(|row| row.0 == self)
            .unwrap_or((self, "", ""))
    }

    /// The function name, as in `docs/kernels.md`.
    #[must_use]
    pub fn name(self) -> &'static str {
        self.row().1
    }

    /// The paper equations, as in `docs/kernels.md`.
    #[must_use]
    pub fn equation(self) -> &'static str {
        self.row().2
    }

    /// The kernel called `name`, if there is one.
    #[must_use]
    pub fn from_name(name: &str) -> Option<KernelName> {
        TABLE.iter().find(|row| row.1 == name).map(|row| row.0)
    }

    /// The floor the kernel is for; `None` if it applies to both.
    #[must_use]
    pub fn floor(self) -> Option<Floor> {
        match self {
            KernelName::MassMatrix
            | KernelName::Bias
            | KernelName::ForeFoot
            | KernelName::Energy => None,
            KernelName::LambdaLevel
            | KernelName::ProjectionLevel
            | KernelName::ControlLevel
            | KernelName::AccelLevel
            | KernelName::Impact3Level
            | KernelName::Impact2Level
            | KernelName::ClosedLoopLevel
            | KernelName::ClosedLoopLevelJacobian
            | KernelName::Impact2LevelJacobian
            | KernelName::StickLevel
            | KernelName::ClosedLoopStickLevel
            | KernelName::ImpactCoulombLevel => Some(Floor::Level),
            KernelName::LambdaSlope
            | KernelName::AccelSlope
            | KernelName::ImpactSlope
            | KernelName::Impact2Slope
            | KernelName::AccelSlopeJacobian
            | KernelName::ImpactSlopeJacobian
            | KernelName::StickSlope
            | KernelName::ImpactCoulombSlope => Some(Floor::Slope),
        }
    }

    /// The friction law the kernel exists for; `None` if it applies to every law. The stick
    /// kernels exist only with exact Coulomb friction, the only law under which the foot can
    /// stick (the tanh law of Eq. 26 always slides, however slowly).
    #[must_use]
    pub fn friction(self) -> Option<Friction> {
        match self {
            KernelName::StickLevel | KernelName::ClosedLoopStickLevel | KernelName::StickSlope => {
                Some(Friction::Coulomb)
            }
            _ => None,
        }
    }

    /// Whether the kernel exists only for an actuated torso.
    #[must_use]
    pub fn needs_actuation(self) -> bool {
        matches!(
            self,
            KernelName::ControlLevel
                | KernelName::ClosedLoopLevel
                | KernelName::ClosedLoopLevelJacobian
                | KernelName::ClosedLoopStickLevel
        )
    }

    /// Whether a walker with this floor, friction law and torso has the kernel.
    #[must_use]
    pub fn applies_to(self, floor: Floor, friction: Friction, torso: Torso) -> bool {
        self.floor().is_none_or(|f| f == floor)
            && self.friction().is_none_or(|f| f == friction)
            && (!self.needs_actuation() || torso == Torso::Actuated)
    }

    /// The kernels a walker with this floor, friction law and torso has, in catalogue order.
    #[must_use]
    pub fn for_structure(floor: Floor, friction: Friction, torso: Torso) -> Vec<KernelName> {
        Self::ALL
            .into_iter()
            .filter(|k| k.applies_to(floor, friction, torso))
            .collect()
    }
}

impl std::fmt::Display for KernelName {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for k in KernelName::ALL {
            assert_eq!(KernelName::from_name(k.name()), Some(k));
        }
    }

    #[test]
    fn control_only_when_actuated() {
        let passive = KernelName::for_structure(Floor::Level, Friction::Tanh, Torso::Passive);
        assert!(!passive.contains(&KernelName::ControlLevel));
        let active = KernelName::for_structure(Floor::Level, Friction::Tanh, Torso::Actuated);
        assert!(active.contains(&KernelName::ControlLevel));
        assert!(!active.contains(&KernelName::AccelSlope));
    }

    #[test]
    fn stick_kernels_only_with_coulomb_friction() {
        use KernelName::{ClosedLoopStickLevel, StickLevel, StickSlope};
        let stick = [StickLevel, ClosedLoopStickLevel, StickSlope];
        for floor in [Floor::Level, Floor::Slope] {
            for torso in [Torso::Actuated, Torso::Passive] {
                for friction in [Friction::None, Friction::Tanh] {
                    let ks = KernelName::for_structure(floor, friction, torso);
                    assert!(stick.iter().all(|k| !ks.contains(k)), "{friction}");
                }
            }
        }
        let level = |torso| KernelName::for_structure(Floor::Level, Friction::Coulomb, torso);
        assert!(level(Torso::Actuated).contains(&StickLevel));
        assert!(level(Torso::Actuated).contains(&ClosedLoopStickLevel));
        assert!(level(Torso::Passive).contains(&StickLevel));
        assert!(!level(Torso::Passive).contains(&ClosedLoopStickLevel));
        assert!(!level(Torso::Actuated).contains(&StickSlope));
        let slope = KernelName::for_structure(Floor::Slope, Friction::Coulomb, Torso::Passive);
        assert!(slope.contains(&StickSlope));
        assert!(!slope.contains(&StickLevel));
    }
}
