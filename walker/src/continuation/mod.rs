//! Continuation of gaits: whole branches of period-one (and period-two) cycles as a parameter
//! moves, stable or not, with the points where they turn, split or stop being physical.
//!
//! A [`GaitProblem`] is a one-parameter family of Poincare maps on the section's independent
//! coordinates (`problem.rs`); any model's walker fills it ([`WalkerProblem`],
//! `walker_problem.rs`, with the cheap map of `profile.rs`). [`continuation()`] follows the
//! fixed points by pseudo-arclength continuation (`arclength.rs`): tangent predictor, a chord
//! corrector on the fixed-point equations bordered by the arclength condition
//! (`corrector.rs`), step-size control. Between consecutive points test functions find folds,
//! branch points, period doubling, Neimark-Sacker points and the boundaries of the walking
//! region (lift-off, double support, heel strike before `T_set`, stick-slip structure), which
//! are located on the branch (`detect.rs`). The result is a typed [`Branch`] of [`Point`]s,
//! special ones with a [`Label`] (`branch.rs`), after AUTO and COCO. At a period doubling,
//! [`period_two()`] switches to the branch of fixed points of `P o P` ([`SecondIterate`],
//! `period_two.rs`).
//!
//! `docs/continuation.md` states the method, the conventions, the tolerances and the limits.

mod arclength;
mod branch;
mod corrector;
mod detect;
mod period_two;
mod problem;
mod profile;
mod walker_problem;

pub use arclength::{ContinuationError, ContinuationOptions, SeedTry, continuation};
pub use branch::{Branch, EndReason, Label, LabelKind, Point, Stability};
pub use period_two::{SecondIterate, period_two};
pub use problem::{Cycle, GaitProblem, MapValue, ProblemError, SlipStructure, Tests};
pub use walker_problem::WalkerProblem;
