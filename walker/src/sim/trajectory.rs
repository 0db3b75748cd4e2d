//! A walk sampled at given times ([`Trajectory`], [`trajectory()`]): the [`Frame`]s at
//! `0, dt, 2 dt, ..` since the start of the walk, for animations and stick diagrams. Nothing
//! here draws.

use serde::Serialize;

use crate::model::Model;

use super::config::{SimConfig, WalkLimits};
use super::frame::{Frame, Frames, at_failure};
use super::gait::Walk;
use super::patches::region_at;
use super::step_models::StepModels;
use super::walk::{Stopped, walk_models, walk_recording};

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
    /// The walk at the moment of its failure, if it failed (at [`Trajectory::end_time`],
    /// usually between two frames): the failure's state, the contact of its step.
    pub failure_frame: Option<Frame>,
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
    initial: &[f64],
    limits: &WalkLimits,
    dt: f64,
    max_frames: usize,
) -> Trajectory {
    sampled(model, cfg, initial, limits, dt, max_frames, &|| false).0
}

/// [`trajectory()`], asking `stop()` before every step of the walker and ending with
/// [`Stopped`] when it answers true (see [`super::walk_stoppable`]).
///
/// # Errors
/// `stop()` answered true before the walk ended.
pub fn trajectory_stoppable(
    model: &Model,
    cfg: &SimConfig,
    initial: &[f64],
    limits: &WalkLimits,
    dt: f64,
    max_frames: usize,
    stop: &dyn Fn() -> bool,
) -> Result<Trajectory, Stopped> {
    match sampled(model, cfg, initial, limits, dt, max_frames, stop) {
        (_, true) => Err(Stopped),
        (tr, false) => Ok(tr),
    }
}

/// The trajectory of [`trajectory_stoppable`], and whether `stop` ended it early.
fn sampled(
    model: &Model,
    cfg: &SimConfig,
    initial: &[f64],
    limits: &WalkLimits,
    dt: f64,
    max_frames: usize,
    stop: &dyn Fn() -> bool,
) -> (Trajectory, bool) {
    let mut frames = Frames::new(dt, max_frames);
    let (walk, _, stopped) = walk_recording(model, cfg, initial, limits, Some(&mut frames), stop);
    (finished(walk, frames, dt, |_| Some(model)), stopped)
}

/// [`trajectory()`] with the model of each step from `models`, asked before the step (a floor
/// whose friction changes between steps, `crate::floor`), as [`super::walk_by_step`] walks.
#[must_use]
pub fn trajectory_by_step(
    models: &mut dyn StepModels,
    cfg: &SimConfig,
    initial: &[f64],
    limits: &WalkLimits,
    dt: f64,
    max_frames: usize,
) -> Trajectory {
    let mut frames = Frames::new(dt, max_frames);
    let (walk, _, _) = walk_models(models, cfg, initial, limits, Some(&mut frames), &|| false);
    // On a floor of patches, the failure's frame is drawn with the model of the patch under
    // the stance foot there.
    let foot = walk.failure.as_ref().map(|f| f.state[0]);
    finished(walk, frames, dt, |step| match foot {
        Some(x) if models.patches().is_some() => models
            .patches()
            .map(|p| p.model(region_at(p, x / p.model(0).phi().cos()))),
        _ => models.model(step),
    })
}

/// The trajectory of `walk` sampled into `frames`, with the frame at its failure from the
/// model of the failing step (`model_of(step)`).
fn finished<'m>(
    walk: Walk,
    frames: Frames,
    dt: f64,
    model_of: impl FnOnce(usize) -> Option<&'m Model>,
) -> Trajectory {
    let (frames, truncated) = frames.finish();
    let mut tr = Trajectory {
        walk,
        dt,
        frames,
        truncated,
        failure_frame: None,
    };
    if let Some(f) = &tr.walk.failure
        && let Some(model) = model_of(f.step)
    {
        tr.failure_frame = Some(at_failure(model, f, tr.end_time(), tr.frames.last()));
    }
    tr
}

#[cfg(test)]
mod tests {
    use super::trajectory;
    use crate::model::Model;
    use crate::setup::Setup;
    use crate::sim::{SimConfig, WalkLimits, walk};
    use crate::vector::Vector;

    /// Fig. 5's walker (`mu0 = 0.4`, `T_set = 0.3`, `omega0 = 0.8`), two steps.
    fn fig5() -> (Model, Vector, WalkLimits) {
        let m = Setup::active_level()
            .and_then(|s| Ok(s.model()?))
            .expect("the built-in scene");
        let limits = WalkLimits {
            max_steps: 2,
            ..WalkLimits::default()
        };
        let s0 = m.start_state();
        (m, s0, limits)
    }

    #[test]
    fn sampling_frames_leaves_the_walk_unchanged() {
        let (m, s0, limits) = fig5();
        let cfg = SimConfig::default();
        let tr = trajectory(&m, &cfg, &s0, &limits, 0.01, 10_000);
        assert_eq!(tr.walk, walk(&m, &cfg, &s0, &limits));
    }

    #[test]
    fn frames_are_at_exact_multiples_of_dt_up_to_the_last_impact() {
        let (m, s0, limits) = fig5();
        let tr = trajectory(&m, &SimConfig::default(), &s0, &limits, 0.01, 10_000);
        assert_eq!(tr.frames[0].state, s0);
        for (k, f) in tr.frames.iter().enumerate() {
            assert_eq!(f.time, k as f64 * 0.01);
        }
        let end = tr.end_time();
        assert_eq!(tr.frames.len(), (end / 0.01).floor() as usize + 1);
        assert!(!tr.truncated);
        let short = trajectory(&m, &SimConfig::default(), &s0, &limits, 0.01, 5);
        assert_eq!((short.frames.len(), short.truncated), (5, true));
    }

    /// The frames are the dense output at their times, not the nearest accepted step: frames of
    /// the same walk at `rtol = 1e-10` and `1e-13` agree to the looser walk's global error,
    /// measured 9e-11 over these two steps (about 1 s; the README gives a median 2.6e-10 over
    /// 100 s walks at these tolerances); the bound `1e-8` leaves a factor 100 above that, while
    /// a frame taken at an accepted step's end instead of its own time would be off by the
    /// angular velocity (about 1 rad/s) times the gap to that end, up to a whole integration
    /// step.
    #[test]
    fn frames_agree_with_a_tighter_integration_at_the_same_times() {
        let (m, s0, limits) = fig5();
        let loose = trajectory(&m, &SimConfig::default(), &s0, &limits, 0.01, 10_000);
        let tight_cfg = SimConfig {
            rtol: 1e-13,
            atol: 1e-15,
            ..SimConfig::default()
        };
        let tight = trajectory(&m, &tight_cfg, &s0, &limits, 0.01, 10_000);
        let n = loose.frames.len().min(tight.frames.len());
        assert!(n > 50, "{n} frames");
        let mut worst = 0.0_f64;
        for (a, b) in loose.frames[..n - 1].iter().zip(&tight.frames) {
            assert_eq!(a.step, b.step);
            for (x, y) in a.state.iter().zip(b.state.iter()) {
                worst = worst.max((x - y).abs());
            }
        }
        assert!(worst < 1e-8, "worst difference {worst:e}");
    }

    /// Fig. 14 (`phi = 0.10`, `mu0 = 0.19`, `omega0 = 0.5`): the wheel falls backward in its
    /// second step (Section 5.3); the trajectory ends with the frame at that moment.
    #[test]
    fn a_failed_walk_ends_with_the_frame_at_its_failure() {
        let m = Setup::passive_slope()
            .and_then(|mut s| {
                s.set("mu0", 0.19)?;
                s.set("phi", 0.10)?;
                Ok(s.model()?)
            })
            .expect("the built-in scene");
        let limits = WalkLimits {
            max_steps: 5,
            ..WalkLimits::default()
        };
        let tr = trajectory(
            &m,
            &SimConfig::default(),
            &m.start_state(),
            &limits,
            0.01,
            10_000,
        );
        let failure = tr.walk.failure.as_ref().expect("Fig. 14 falls backward");
        assert_eq!((failure.name(), failure.step), ("fell-backward", 1));
        let last = tr.frames.last().expect("frames before the fall");
        let ff = tr.failure_frame.expect("the frame at the failure");
        assert_eq!(
            (ff.time, ff.step, ff.state),
            (tr.end_time(), 1, failure.state)
        );
        assert!(ff.time >= last.time && ff.time - last.time < 0.01);
        assert!(ff.reaction.lambda.is_finite());
    }
}
