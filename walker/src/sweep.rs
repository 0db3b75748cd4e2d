//! Parameter sweeps: procedures (P1a)-(P5a) (the active walker over `mu0`, Section 4.2) and
//! (P1b)-(P5b) (the passive wheel, Section 5.2), for any run-time parameter of any model.
//!
//! Each value is walked for a given duration; its steady post-impact state (with the stance foot
//! moved back to the origin: the dynamics do not depend on `x`, `z`) is the initial condition of
//! the next value, unless the sweep restarts every value from the initial condition or the
//! previous run failed. Independent chains (several `T_set` or `phi`) and restarted points run in
//! parallel with rayon.

use rayon::prelude::*;
use serde::Serialize;

use crate::model::Model;
use crate::sim::{Failure, SimConfig, StepResult, WalkLimits, walk};
use crate::vector::Vector;

/// The outcome of one value of a sweep.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SweepPoint {
    /// The swept parameter's value (`mu0` in the paper's sweeps).
    pub value: f64,
    /// Number of completed (simulated) steps.
    pub steps: usize,
    /// The last completed step (the steady descriptors if the walk converged).
    pub last: Option<StepResult>,
    /// The step before the last one (to judge convergence).
    pub previous: Option<StepResult>,
    /// Why the walk ended early, if it did.
    pub failure: Option<Failure>,
    /// The walk stopped before its duration because the gait had become periodic
    /// ([`WalkLimits::periodic`]): `last` stands for every later step.
    pub periodic: bool,
}

/// The values `from, from + step, ...` up to `to` (inclusive within rounding).
///
/// Returns an empty list when `step` is not a positive finite number or `to < from`.
pub fn mu0_grid(from: f64, to: f64, step: f64) -> Vec<f64> {
    if !(step.is_finite() && step > 0.0 && from.is_finite() && to.is_finite()) || to < from {
        return Vec::new();
    }
    let n = ((to - from) / step + 1e-9).floor() as usize;
    (0..=n).map(|k| from + step * k as f64).collect()
}

fn moved_to_origin(mut s: Vector) -> Vector {
    s[0] = 0.0;
    s[1] = 0.0;
    s
}

fn point(value: f64, walk: crate::sim::Walk) -> SweepPoint {
    let n = walk.steps.len();
    SweepPoint {
        value,
        steps: n,
        last: walk.steps.last().copied(),
        previous: n.checked_sub(2).map(|k| walk.steps[k]),
        failure: walk.failure,
        periodic: walk.periodic,
    }
}

/// Procedure (P4a): each value continues from the previous steady post-impact state (from
/// `initial` after a failure).
fn continuation(
    make: impl Fn(f64) -> Model,
    cfg: &SimConfig,
    grid: &[f64],
    initial: Vector,
    limits: &WalkLimits,
    progress: &(dyn Fn() + Sync),
) -> Vec<SweepPoint> {
    let mut out = Vec::with_capacity(grid.len());
    let mut state = initial;
    for &mu0 in grid {
        let w = walk(&make(mu0), cfg, &state, limits);
        state = match (&w.failure, w.last_state()) {
            (None, Some(s)) => moved_to_origin(s),
            _ => initial,
        };
        out.push(point(mu0, w));
        progress();
    }
    out
}

/// Several independent sweeps (one per entry of `chains`, for example one per `T_set`), run in
/// parallel; `make(chain, value)` is the model of a point (the caller checks beforehand that
/// every point's model can be built: see [`crate::setup::Setup::model_with`]); `progress` is
/// called once per finished point (from any thread).
///
/// With `restart`, every `(chain, mu0)` point is independent and all of them share the rayon
/// pool. Without, each chain is sequential (every `mu0` starts from the previous steady state),
/// so each chain gets its own thread: the operating system then shares the cores among all
/// chains, where a pool with fewer threads than chains would run some chains one after another
/// (three `T_set` chains on two cores: 1.5 chains of wall time instead of 2).
#[allow(clippy::too_many_arguments)]
pub fn sweep_chains<F>(
    chains: &[f64],
    make: F,
    cfg: &SimConfig,
    grid: &[f64],
    initial: impl Fn(f64) -> Vector + Sync,
    limits: &WalkLimits,
    restart: bool,
    progress: &(dyn Fn() + Sync),
) -> Vec<Vec<SweepPoint>>
where
    F: Fn(f64, f64) -> Model + Sync,
{
    if grid.is_empty() {
        return vec![Vec::new(); chains.len()];
    }
    if restart {
        let pairs: Vec<(f64, f64)> = chains
            .iter()
            .flat_map(|&c| grid.iter().map(move |&mu0| (c, mu0)))
            .collect();
        let flat: Vec<SweepPoint> = pairs
            .par_iter()
            .map(|&(c, mu0)| {
                let p = point(mu0, walk(&make(c, mu0), cfg, &initial(c), limits));
                progress();
                p
            })
            .collect();
        return flat
            .chunks(grid.len())
            .map(<[SweepPoint]>::to_vec)
            .collect();
    }
    let (make, initial) = (&make, &initial);
    std::thread::scope(|scope| {
        let handles: Vec<_> = chains
            .iter()
            .map(|&c| {
                scope.spawn(move || {
                    continuation(|mu0| make(c, mu0), cfg, grid, initial(c), limits, progress)
                })
            })
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
            .collect()
    })
}
