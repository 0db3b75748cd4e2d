//! The hybrid simulation: stance phases integrated with [`crate::ode`], heel strikes located as
//! events, the impact map and the change of stance leg, failure detection, and the per-step
//! gait descriptors of Section 4.2 (Eqs. 34, 47, the average input power and the specific
//! resistance).
//!
//! The simulator is written against a model ([`crate::model::Model`]): its kernels, its
//! guards, its impact law, its relabelling, its descriptors. The integrated state is
//! `[q, qd, E]` (`2n + 1` numbers for `n` coordinates) where `E` is the quadrature
//! `int |ydot u| dt` of the input power, accumulated up to the model's `power_until` (`T_set`
//! in the paper; zero for a passive walker), so that the average input power is under the
//! integrator's error control. The time is reset to zero at every impact; the ends of the
//! desired trajectories' ramps (`T_set`) are breakpoints of the integrator (the control
//! switches there).
//!
//! Files, each using only those listed before it: `state.rs` (the integrated state),
//! `config.rs` ([`SimConfig`], [`WalkLimits`]), `failure.rs` ([`Failure`], [`FailureKind`]), `gait.rs` ([`StepResult`], [`Sample`], [`Walk`]), `periodic.rs` (the
//! periodic stop), `foot.rs` (the stance foot, its contact and ground reaction), `stance.rs`
//! (the stance ODE system and the sampling observer), `guard.rs` (the stance events,
//! [`Guard`]), `blowup.rs` (which failure a blown-up `lambda` is), `step.rs` (one stance phase
//! and its impact), `patches.rs` (one step on a floor of patches by position, [`Patches`]:
//! the stance in pieces, one per patch), `step_models.rs` (the model of each step, [`StepModels`]), `walk.rs` ([`walk()`],
//! [`walk_with_stats`], [`walk_by_step`]), `trajectory.rs` (the walk
//! sampled at given times, [`trajectory()`], for animations). `frame.rs` ([`Frame`], the motion
//! at one time, and its collector) comes after `foot.rs`: the stance observer feeds it.

mod blowup;
mod config;
mod failure;
mod foot;
mod frame;
mod gait;
mod guard;
mod patches;
mod periodic;
mod stance;
mod state;
mod step;
mod step_models;
mod trajectory;
mod walk;

pub use config::{SimConfig, WalkLimits};
pub use failure::{Failure, FailureKind};
pub use foot::{control_input, ground_reaction};
pub use frame::Frame;
pub use gait::{Sample, StepFloor, StepResult, Walk};
pub use guard::{Guard, MAX_FALLS};
pub use patches::{Patches, region_at};
pub use step_models::StepModels;
pub use trajectory::{Trajectory, trajectory, trajectory_by_step, trajectory_stoppable};
pub use walk::{
    Stopped, walk, walk_by_step, walk_by_step_stoppable, walk_stoppable, walk_with_stats,
};
