//! A walk: stance phases one after another from an initial post-impact state, until a limit,
//! a failure or a periodic gait.

use crate::model::Model;
use crate::ode::{Integrator, Stats, Tolerances};
use crate::vector::Vector;

use super::config::{SimConfig, WalkLimits};
use super::failure::FailureKind;
use super::frame::Frames;
use super::gait::Walk;
use super::patches::patched_step;
use super::periodic::is_periodic;
use super::state::with_state_size;
use super::step::{Record, one_step};
use super::step_models::{Fixed, StepModels};

/// Simulate a walk of `model` from the post-impact state `initial` (`[q, qd]`, time 0 = the 0th
/// impact).
pub fn walk(model: &Model, cfg: &SimConfig, initial: &[f64], limits: &WalkLimits) -> Walk {
    walk_with_stats(model, cfg, initial, limits).0
}

/// [`walk`], also returning the integrator's work counters summed over the whole walk
/// (right-hand-side evaluations, accepted and rejected steps, events; for benchmarks).
pub fn walk_with_stats(
    model: &Model,
    cfg: &SimConfig,
    initial: &[f64],
    limits: &WalkLimits,
) -> (Walk, Stats) {
    let (walk, stats, _) = walk_recording(model, cfg, initial, limits, None, &|| false);
    (walk, stats)
}

/// A walk ended early because its caller asked (see [`walk_stoppable`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
#[error("the walk was stopped by its caller")]
pub struct Stopped;

/// [`walk`], asking `stop()` before every step of the walker and ending with [`Stopped`] when it
/// answers true: a front end's cancellation hook (Ctrl-C in Python), so that a long walk (up to
/// a million steps) is abandoned within one step of the walker, not at its end. The steps a
/// walk takes and their results do not depend on `stop` until it answers true.
///
/// # Errors
/// `stop()` answered true before the walk ended.
pub fn walk_stoppable(
    model: &Model,
    cfg: &SimConfig,
    initial: &[f64],
    limits: &WalkLimits,
    stop: &dyn Fn() -> bool,
) -> Result<Walk, Stopped> {
    match walk_recording(model, cfg, initial, limits, None, stop) {
        (_, _, true) => Err(Stopped),
        (walk, _, false) => Ok(walk),
    }
}

/// [`walk`] with the model of each step from `models`, asked before the step (a floor whose
/// friction changes between steps, `crate::floor`); each step's record carries the floor
/// `models` names for it. The walk ends before a step whose model `models` cannot give (the
/// implementation keeps why). With one model for every step and no floor this is [`walk`].
pub fn walk_by_step(
    models: &mut dyn StepModels,
    cfg: &SimConfig,
    initial: &[f64],
    limits: &WalkLimits,
) -> Walk {
    walk_models(models, cfg, initial, limits, None, &|| false).0
}

/// [`walk_by_step`], ending early (the second value true) when `stop()`, asked before every
/// step, answers true, or before a step whose model `models` cannot give.
pub fn walk_by_step_stoppable(
    models: &mut dyn StepModels,
    cfg: &SimConfig,
    initial: &[f64],
    limits: &WalkLimits,
    stop: &dyn Fn() -> bool,
) -> (Walk, bool) {
    let (walk, _, stopped) = walk_models(models, cfg, initial, limits, None, stop);
    (walk, stopped)
}

/// [`walk_with_stats`], also sampling the motion into `frames` if given, and ending early
/// (the third value true) when `stop()`, asked before every step, answers true. An initial
/// state of the wrong length is a non-finite start (nothing to integrate).
pub(super) fn walk_recording(
    model: &Model,
    cfg: &SimConfig,
    initial: &[f64],
    limits: &WalkLimits,
    frames: Option<&mut Frames>,
    stop: &dyn Fn() -> bool,
) -> (Walk, Stats, bool) {
    walk_models(&mut Fixed(model), cfg, initial, limits, frames, stop)
}

/// [`walk_recording`] with the model of each step from `models`; a step whose model cannot be
/// had ends the walk as a stop does (the third value true).
pub(super) fn walk_models(
    models: &mut dyn StepModels,
    cfg: &SimConfig,
    initial: &[f64],
    limits: &WalkLimits,
    frames: Option<&mut Frames>,
    stop: &dyn Fn() -> bool,
) -> (Walk, Stats, bool) {
    let n = models.n();
    if initial.len() != 2 * n {
        let failure = FailureKind::NonFinite.at(0, 0.0, Vector::from_slice(initial));
        return (Walk::failed(failure), Stats::default(), false);
    }
    with_state_size!(n, S => walk_sized::<S>(models, cfg, initial, limits, frames, stop),
        _ => (Walk::failed(FailureKind::NonFinite.at(0, 0.0, Vector::from_slice(initial))), Stats::default(), false))
}

/// `state` with the stance foot's position `(state[0], state[1])` moved by `sign` times `o`.
fn moved(state: &Vector, o: [f64; 2], sign: f64) -> Vector {
    let mut s = *state;
    s[0] += sign * o[0];
    s[1] += sign * o[1];
    s
}

fn walk_sized<const S: usize>(
    models: &mut dyn StepModels,
    cfg: &SimConfig,
    initial: &[f64],
    limits: &WalkLimits,
    mut frames: Option<&mut Frames>,
    stop: &dyn Fn() -> bool,
) -> (Walk, Stats, bool) {
    let mut integ = Integrator::<S>::new(cfg.method, Tolerances::new(cfg.rtol, cfg.atol));
    let mut steps = Vec::new();
    let mut samples = Vec::new();
    let mut state = Vector::from_slice(initial);
    let mut time = 0.0;
    let mut failure = None;
    let mut periodic = false;
    let mut stopped = false;
    for k in 0..limits.max_steps {
        if stop() {
            stopped = true;
            break;
        }
        // A step's floor may see the walker from a point of its own (`StepModels::origin`):
        // the step runs on the moved state, and what it reports is moved back.
        let origin = match models.origin(k, &state) {
            Ok(o) => o,
            Err(kind) => {
                failure = Some(kind.at(k, 0.0, state));
                break;
            }
        };
        let recorded = (samples.len(), frames.as_deref().map_or(0, Frames::len));
        let s0 = origin.map_or(state, |o| moved(&state, o, -1.0));
        let record = Record {
            samples: limits.record.then_some(&mut samples),
            frames: frames.as_deref_mut(),
            t_offset: time,
        };
        // A floor of patches by position changes the model inside a step (`super::patches`).
        let res = if let Some(patches) = models.patches() {
            patched_step(patches, cfg, &mut integ, k, &s0, record)
        } else {
            let Some(model) = models.model(k) else {
                stopped = true;
                break;
            };
            one_step(model, cfg, &mut integ, k, &s0, record)
        };
        if let Some(o) = origin {
            for s in &mut samples[recorded.0..] {
                s.state = moved(&s.state, o, 1.0);
            }
            if let Some(f) = frames.as_deref_mut() {
                f.move_from(recorded.1, o);
            }
        }
        let res = match origin {
            Some(o) => res
                .map(|mut r| {
                    (r.q_plus[0], r.q_plus[1]) = (r.q_plus[0] + o[0], r.q_plus[1] + o[1]);
                    r
                })
                .map_err(|mut f| {
                    f.state = moved(&f.state, o, 1.0);
                    f
                }),
            None => res,
        };
        match res {
            Ok(mut r) => {
                if r.floor.is_none() {
                    r.floor = models.floor();
                }
                time += r.period;
                state = r.state_plus();
                steps.push(r);
                if time >= limits.duration {
                    break;
                }
                if limits.periodic.is_some_and(|tol| is_periodic(&steps, tol)) {
                    periodic = true;
                    break;
                }
            }
            Err(f) => {
                failure = Some(f);
                break;
            }
        }
    }
    (
        Walk {
            steps,
            failure,
            samples,
            periodic,
        },
        *integ.stats(),
        stopped,
    )
}

#[cfg(test)]
mod tests {
    use std::cell::Cell;

    use super::{Stopped, walk, walk_stoppable};
    use crate::setup::Setup;
    use crate::sim::{SimConfig, WalkLimits};

    /// A stop that never answers true changes nothing; one that answers true before the
    /// fourth step ends the walk there, having been asked once per step.
    #[test]
    fn a_walk_asks_its_stop_before_every_step_and_ends_when_told() {
        let m = Setup::active_level()
            .and_then(|s| Ok(s.model()?))
            .expect("the built-in scene");
        let limits = WalkLimits {
            max_steps: 6,
            ..WalkLimits::default()
        };
        let cfg = SimConfig::default();
        let start = m.start_state();
        let plain = walk(&m, &cfg, &start, &limits);
        assert_eq!(plain.steps.len(), 6);
        let asked = Cell::new(0);
        let never = walk_stoppable(&m, &cfg, &start, &limits, &|| {
            asked.set(asked.get() + 1);
            false
        });
        assert_eq!(never, Ok(plain));
        assert_eq!(asked.get(), 6);
        asked.set(0);
        let told = walk_stoppable(&m, &cfg, &start, &limits, &|| {
            asked.set(asked.get() + 1);
            asked.get() > 3
        });
        assert_eq!(told, Err(Stopped));
        assert_eq!(asked.get(), 4);
    }
}
