//! Floors that change under the walker (`docs/floors.md`): the friction coefficient `mu0` of
//! each step, from a floor file (`walker_scene::floor`: uniform, a list per step, or drawn per
//! step at random), and the walks and survival statistics on it.
//!
//! Step `k`'s stance and the strike that ends it run on `mu0_k`, and on the line of slope
//! `phi_k` through its stance foot where the floor sets the slope: the parameters are set
//! between steps, never inside one, and the model prepared again when they change; a step on
//! a new slope is the model's step from the state moved so that its stance foot is at the
//! model's origin, moved back after (`translate.rs` checks the symmetry this rests on). A floor is checked
//! against the walker once ([`FloorWalker::new`]): the friction coefficient must be a
//! run-time parameter and every value the floor gives within its range.
//!
//! Files, each using only those listed before it: `draw.rs` (the portable random numbers of a
//! step), `steps.rs` ([`FloorSteps`], the values of one walk's steps), `error.rs`
//! ([`FloorError`]), `translate.rs` (the check that a model moves with its stance foot),
//! `patches.rs` (a floor of patches by position prepared for a walker: its regions and their
//! models, for the simulator's [`crate::sim::Patches`]), `walker.rs` ([`FloorWalker`], walks
//! on a floor), `stats.rs` (survival
//! statistics of walks that end by failure or at a step limit), `survive.rs` ([`survive`],
//! many seeded walks on all cores), `mesh/` (the Markov-chain approximation of the mean
//! first-passage time, [`mesh::mesh_mfpt`]).

pub(crate) mod draw;
mod error;
pub mod mesh;
mod patches;
mod stats;
mod steps;
mod survive;
mod translate;
mod walker;

pub use error::FloorError;
pub use stats::{
    Estimate, Mfpt, Survival, SurvivalPoint, SurvivalSummary, SurviveOutcome, survival,
};
pub use steps::FloorSteps;
pub use survive::{MAX_SURVIVE_STEPS, MAX_WALKS, SurviveReport, survive, survive_stoppable};
pub use walker::FloorWalker;
pub use walker_scene::{Distribution, FloorFile, FloorFileError, FloorPatch, FloorPlan, FloorSpec};
