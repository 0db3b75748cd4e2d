//! The impact map's result ([`ImpactResult`]) and the state right after the impact in the new
//! stance leg's coordinates ([`PostImpact`]).

use serde::Serialize;

use super::friction_impact::ImpactRegime;
use crate::vector::Vector;

/// The result of an impact map evaluated at the pre-impact state.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ImpactResult {
    /// The striking foot's impulse `[Lambda_t, Lambda_n]` along the floor's unit tangent
    /// (towards `+x`; down the slope) and unit normal (N s); `Lambda_t = 0` for the paper's
    /// frictionless impact.
    pub foot_impulse: [f64; 2],
    /// The old stance foot's vertical impulse in the double-support test, the impact solved
    /// with that foot kept on the floor (Eq. 11; Eq. 46 on the slope, whose impulses the paper
    /// gives as their vertical components, as its `lambda`; with friction at the impact,
    /// [`super::friction_impact::rear_test`]): non-negative means the walker would stay in
    /// double support. Zero for a model without the test.
    pub rear_impulse: f64,
    /// Post-impact velocities of the old coordinates.
    pub qd: Vector,
    /// How the striking foot ends the impact.
    pub regime: ImpactRegime,
}

/// The state right after an impact in the new stance leg's coordinates (the model's
/// `relabel` kernel: the striking point becomes the stance foot, the other coordinates by the
/// model's relabelling; Eqs. 17-18, 45 corrected, for the paper's walkers).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PostImpact {
    /// `q+`.
    pub q_plus: Vector,
    /// `qd+`.
    pub qd_plus: Vector,
    /// The new stance foot's velocity normal to the floor (zero for an exact impact).
    pub foot_normal_velocity: f64,
}
