//! Many seeded walks on a floor ([`survive`]): walk `i` runs on the floor's stream `i`, each
//! up to a step limit, on all cores; the outcomes in walk order and their survival statistics.
//! The walks are independent and collected in order, so the result does not depend on the
//! number of threads. A batch is any range of walks: the walks `a..b` of a batch are the same
//! as a batch of those walks alone, so a large batch can be split into ranges (run anywhere)
//! whose outcomes, put back in order, give the statistics of the whole ([`survival`]).
//! A floor of patches by position draws nothing, so its walks are one walk, walked once.

use std::ops::Range;

use rayon::prelude::*;
use serde::Serialize;

use crate::sim::{SimConfig, WalkLimits};

use super::error::FloorError;
use super::stats::{Survival, SurviveOutcome, survival};
use super::walker::FloorWalker;

pub use crate::request::{MAX_SURVIVE_STEPS, MAX_WALKS};

/// The walks of a batch and their statistics.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SurviveReport {
    /// The step limit of each walk.
    pub max_steps: usize,
    /// Each walk's end, in walk order.
    pub outcomes: Vec<SurviveOutcome>,
    /// Their statistics.
    pub survival: Survival,
}

/// The walks `walks` (their indices, `0..n` for a batch of `n`) of `walker` from `initial`,
/// walk `i` on the floor's stream `i`, each of at most `max_steps` steps, run on rayon's
/// threads (all cores unless the caller installs a pool of its own). Check the counts first
/// with [`crate::request::survive_counts`] and [`crate::request::walk_range`].
///
/// # Errors
/// A step's kernels cannot be prepared (the first such walk's error).
pub fn survive(
    walker: &FloorWalker<'_>,
    cfg: &SimConfig,
    initial: &[f64],
    walks: Range<u64>,
    max_steps: usize,
) -> Result<SurviveReport, FloorError> {
    Ok(
        survive_stoppable(walker, cfg, initial, walks, max_steps, &|| false)?.unwrap_or_else(
            || SurviveReport {
                max_steps,
                outcomes: Vec::new(),
                survival: survival(&[]),
            },
        ),
    )
}

/// [`survive`], abandoned (`None`) when `stop()`, asked before every step of every walk,
/// answers true.
///
/// # Errors
/// As [`survive`].
pub fn survive_stoppable(
    walker: &FloorWalker<'_>,
    cfg: &SimConfig,
    initial: &[f64],
    walks: Range<u64>,
    max_steps: usize,
    stop: &(dyn Fn() -> bool + Sync),
) -> Result<Option<SurviveReport>, FloorError> {
    let limits = WalkLimits {
        max_steps,
        ..WalkLimits::default()
    };
    if walker.by_position() {
        // A floor of patches draws nothing: every walk is the same walk, walked once.
        let Some(first) = walks.clone().next() else {
            return Ok(Some(SurviveReport {
                max_steps,
                outcomes: Vec::new(),
                survival: survival(&[]),
            }));
        };
        let Some(w) = walker.walk_stoppable(first, cfg, initial, &limits, stop)? else {
            return Ok(None);
        };
        let outcomes: Vec<SurviveOutcome> = walks
            .map(|i| SurviveOutcome {
                walk: i,
                steps: w.steps.len(),
                failure: w.failure.as_ref().map(|f| f.name().to_owned()),
            })
            .collect();
        return Ok(Some(SurviveReport {
            max_steps,
            survival: survival(&outcomes),
            outcomes,
        }));
    }
    let outcomes = walks
        .into_par_iter()
        .map(|i| {
            let Some(w) = walker.walk_stoppable(i, cfg, initial, &limits, stop)? else {
                return Ok(None);
            };
            Ok(Some(SurviveOutcome {
                walk: i,
                steps: w.steps.len(),
                failure: w.failure.as_ref().map(|f| f.name().to_owned()),
            }))
        })
        .collect::<Result<Option<Vec<_>>, FloorError>>()?;
    Ok(outcomes.map(|outcomes| SurviveReport {
        max_steps,
        survival: survival(&outcomes),
        outcomes,
    }))
}
