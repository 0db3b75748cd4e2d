//! The walker, written once from its physics, and everything the paper derives from it.
//!
//! Geometry (Fig. 1): the stance-leg end is at `(x, z)`; the hip at
//! `(x + l sin th1, z + l cos th1)`; the torso turns about the hip and has its centre of mass
//! there; the fore leg is the spoke at angle `th1 - alpha`. Kinetic and potential energy give
//! `M(q)` and `h(q, qdot)` through the Euler-Lagrange equations; contact geometry gives every
//! constraint Jacobian by differentiation.
//!
//! Files, imports one way: `terms` holds the building blocks (coordinate symbols, constants,
//! trigonometry, time derivative); `dynamics` (geometry, energies, `M`, `h`, `S`) uses it;
//! `floor` (the floor's contact geometry) stands alone; `stance` (sliding and stuck stance,
//! control terms) and `impact` (impact maps, the paper's posture) use those three; `output`
//! (the desired output `y_d`) uses `terms` only.

mod dynamics;
mod floor;
mod impact;
mod output;
mod stance;
mod terms;

/// The floor the stance foot slides on: level ground `z = 0` (Section 3) or a slope of angle
/// `phi` descending towards `+x`, `z = -x tan phi` (Section 5). The shared vocabulary's
/// [`walker_scene::Floor`], re-exported so that `walker_symbolic::mechanics::Floor` keeps working.
pub use walker_scene::Floor;

pub use dynamics::{Dynamics, Geometry, dynamics, geometry};
pub use floor::{floor_gap, floor_tangent};
pub use impact::{
    CoulombImpact, Impact, ImpactConstraint, at_impact_posture, coulomb_impact, impact,
    paper_pre_impact,
};
pub use output::{check_desired_output, desired_output};
pub use stance::{
    Contact, Control, Stance, Stick, control, stance, stance_contact, stick, stick_control,
};
pub use terms::{
    Q_SYMS, QD_SYMS, QDD_SYMS, cos, frac, int, sin, sin_half_alpha, sym, tan_phi, time_derivative,
    total_inertia, total_mass,
};
