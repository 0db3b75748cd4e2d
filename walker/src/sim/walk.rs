//! A walk: stance phases one after another from an initial post-impact state, until a limit,
//! a failure or a periodic gait.

use crate::model::Model;
use crate::ode::{Integrator, Stats, Tolerances};
use crate::vector::Vector;

use super::config::{SimConfig, WalkLimits};
use super::failure::FailureKind;
use super::frame::Frames;
use super::gait::Walk;
use super::periodic::is_periodic;
use super::state::with_state_size;
use super::step::{Record, one_step};

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
    walk_recording(model, cfg, initial, limits, None)
}

/// [`walk_with_stats`], also sampling the motion into `frames` if given. An initial state of
/// the wrong length is a non-finite start (nothing to integrate).
pub(super) fn walk_recording(
    model: &Model,
    cfg: &SimConfig,
    initial: &[f64],
    limits: &WalkLimits,
    frames: Option<&mut Frames>,
) -> (Walk, Stats) {
    let n = model.n();
    if initial.len() != 2 * n {
        let failure = FailureKind::NonFinite.at(0, 0.0, Vector::from_slice(initial));
        return (Walk::failed(failure), Stats::default());
    }
    with_state_size!(n, S => walk_sized::<S>(model, cfg, initial, limits, frames),
        _ => (Walk::failed(FailureKind::NonFinite.at(0, 0.0, Vector::from_slice(initial))), Stats::default()))
}

fn walk_sized<const S: usize>(
    model: &Model,
    cfg: &SimConfig,
    initial: &[f64],
    limits: &WalkLimits,
    mut frames: Option<&mut Frames>,
) -> (Walk, Stats) {
    let mut integ = Integrator::<S>::new(cfg.method, Tolerances::new(cfg.rtol, cfg.atol));
    let mut steps = Vec::new();
    let mut samples = Vec::new();
    let mut state = Vector::from_slice(initial);
    let mut time = 0.0;
    let mut failure = None;
    let mut periodic = false;
    for k in 0..limits.max_steps {
        let record = Record {
            samples: limits.record.then_some(&mut samples),
            frames: frames.as_deref_mut(),
            t_offset: time,
        };
        let res = one_step(model, cfg, &mut integ, k, &state, record);
        match res {
            Ok(r) => {
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
    )
}
