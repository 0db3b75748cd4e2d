//! A walk sampled at given times ([`Trajectory`], [`trajectory()`]): the [`Frame`]s at
//! `0, dt, 2 dt, ..` since the start of the walk, for animations and stick diagrams. Nothing
//! here draws.

use serde::Serialize;

use crate::model::Model;

use super::config::{SimConfig, WalkLimits};
use super::frame::{Frame, Frames};
use super::gait::Walk;
use super::walk::walk_recording;

/// A walk with its motion sampled every `dt`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Trajectory {
    /// The walk (its steps and its failure, if any), as [`super::walk()`] returns it.
    pub walk: Walk,
    /// The interval between frames (s).
    pub dt: f64,
    /// The frames at `0, dt, 2 dt, ..` up to the walk's end (its last impact or its failure),
    /// at most `max_frames` of them.
    pub frames: Vec<Frame>,
    /// The walk went on beyond the last frame: `max_frames` was reached.
    pub truncated: bool,
}

impl Trajectory {
    /// Time since the start of the walk at which each step began (the impacts): `0`, `T_0`,
    /// `T_0 + T_1`, .. (one more entry than completed steps).
    #[must_use]
    pub fn impact_times(&self) -> Vec<f64> {
        let mut times = vec![0.0];
        let mut sum = 0.0;
        for s in &self.walk.steps {
            sum += s.period;
            times.push(sum);
        }
        times
    }

    /// Time since the start of the walk at which the walk ended: at its failure or at its last
    /// impact.
    #[must_use]
    pub fn end_time(&self) -> f64 {
        let last_impact = self.impact_times().last().copied().unwrap_or(0.0);
        last_impact + self.walk.failure.as_ref().map_or(0.0, |f| f.t)
    }
}

/// Walk `model` from the post-impact state `initial` as [`super::walk()`] does, and sample the
/// motion at `0, dt, 2 dt, ..` from the dense output, at most `max_frames` frames (the walk is
/// completed either way; [`Trajectory::truncated`] says whether frames are missing at its end).
/// A `dt` that is not finite and positive gives no frames.
#[must_use]
pub fn trajectory(
    model: &Model,
    cfg: &SimConfig,
    initial: [f64; 8],
    limits: &WalkLimits,
    dt: f64,
    max_frames: usize,
) -> Trajectory {
    let mut frames = Frames::new(dt, max_frames);
    let (walk, _) = walk_recording(model, cfg, initial, limits, Some(&mut frames));
    let (frames, truncated) = frames.finish();
    Trajectory {
        walk,
        dt,
        frames,
        truncated,
    }
}
