//! `walker floor-study`: the paper's question recast for floors that change under the walker
//! (`docs/floors.md`, "The paper's question on a changing floor"). Fig. 8 asks how the paper's
//! walker does on a floor of one `mu0` for each ramp duration `T_set`; here the floor changes
//! from step to step, and the study asks which `T_set` walks farthest on it, against the answer
//! for uniform floors, and how long an ice patch on a dry floor each `T_set` crosses.
//!
//! Files, imports one way: [`cases`] (what is walked: the `T_set` grid, the contact laws, the
//! random floors and the ice patch) -> [`data`] (the walks, on all cores, and their
//! statistics) -> [`claims`] (what the run checks) -> [`job`] (CSV files, figures, summary).
//! The statistics are the library's ([`walker::floor::survival`]), the figures and the claim
//! type the gallery's.
//!
//! The passive part (metastable passive walking: the rimless wheel and the compass gait on
//! random slopes and random friction, by Monte Carlo and by the mesh): [`passive`] (its cases,
//! walks and meshes) -> [`passive_claims`] -> [`passive_report`] (its CSV file, figure and
//! summary section), written by [`job`] with the rest.

pub mod cases;
pub mod claims;
pub mod data;
pub mod job;
pub mod passive;
pub mod passive_claims;
pub mod passive_report;

pub use data::{MAX_STEPS, MAX_WALKS, Size, size_of};
pub use job::run;
