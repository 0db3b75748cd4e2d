//! The Markov-chain (mesh) approximation of the mean first-passage time (Byl and Tedrake,
//! "Metastable walking machines", IJRR 28(8), 2009; `docs/floors.md`): for walkers that fall
//! too rarely for Monte Carlo ([`super::survive`]) to see it.
//!
//! The Poincare section's independent coordinates ([`crate::poincare::Section`]) are meshed on
//! a box around the gait's fixed point; from every mesh point the walker takes one step on
//! every floor sample (a quadrature of the per-step `mu0` and `phi` distributions; a Markov
//! floor's state joins the mesh state, and so does the slope sample of the step before on a
//! floor that sets the slope, since the section depends on it); the step's end is
//! interpolated onto the mesh (barycentric weights), or absorbed in a single 'fallen' state on
//! a failure of the walker or out of the box. The mean first-passage time is read off the
//! chain twice: from its second eigenvalue, `1 / (1 - lambda_2)`, and from `(I - Q) t = 1` at
//! the fixed point.
//!
//! Files, each using only those listed before it: `grid.rs` ([`Grid`], the mesh and its
//! interpolation), `samples.rs` ([`FloorSamples`]), `joint.rs` (the floor of friction and
//! slope together, the slope before in the floor state), `chain.rs` ([`Chain`], the absorbing
//! chain and its passage times), `error.rs` ([`MeshError`]), `options.rs` ([`MeshOptions`] and
//! its limits), `report.rs` ([`MeshReport`]), `build.rs` ([`mesh_mfpt`], [`start_setup`]).

mod build;
mod chain;
mod error;
mod grid;
mod joint;
mod options;
mod report;
mod samples;

pub use build::{mesh_mfpt, start_setup, start_slope};
pub use chain::{Chain, MAX_RESOLVED_STEPS, Passage};
pub use error::MeshError;
pub use grid::Grid;
pub use options::{
    MAX_BOX_SCALE, MAX_MESH_STATES, MAX_MESH_STEPS, MAX_POINTS, MAX_SAMPLES, MeshBox, MeshOptions,
    PILOT_STEPS, PILOT_WALKS,
};
pub use report::{MeshMfpt, MeshReport};
pub use samples::FloorSamples;

#[cfg(test)]
mod tests;
