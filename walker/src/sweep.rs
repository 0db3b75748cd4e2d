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
use crate::sim::{Failure, SimConfig, StepResult, Stopped, Walk, WalkLimits, walk, walk_stoppable};
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

/// Where a chain's next value starts (procedure P4a): the previous value's steady post-impact
/// state moved to the origin; at the first value, after a failure, and for every value of a
/// restarted sweep, the start of the value's own model (`initial(model)`: the model's `[start]`
/// at that value's parameters, with a caller's replaced components).
#[derive(Clone, Debug, Default)]
pub struct Carry {
    state: Option<Vector>,
}

impl Carry {
    /// Walks `model` from where the chain stands and moves the chain on.
    pub fn walk(
        &mut self,
        model: &Model,
        cfg: &SimConfig,
        limits: &WalkLimits,
        restart: bool,
        initial: &(dyn Fn(&Model) -> Vector + Sync),
    ) -> Walk {
        let w = walk(model, cfg, &self.start(model, restart, initial), limits);
        self.moved_on(w)
    }

    /// Where the chain's walk of `model` starts.
    fn start(
        &self,
        model: &Model,
        restart: bool,
        initial: &(dyn Fn(&Model) -> Vector + Sync),
    ) -> Vector {
        match self.state {
            Some(s) if !restart => s,
            _ => initial(model),
        }
    }

    /// Moves the chain on past the walk `w` and returns it.
    fn moved_on(&mut self, w: Walk) -> Walk {
        self.state = match (&w.failure, w.last_state()) {
            (None, Some(s)) => Some(moved_to_origin(s)),
            _ => None,
        };
        w
    }

    /// [`Carry::walk`], asking `stop()` before every step of the walker
    /// ([`walk_stoppable`]): a stopped walk leaves the chain where it stood.
    ///
    /// # Errors
    /// `stop()` answered true before the walk ended.
    pub fn walk_stoppable(
        &mut self,
        model: &Model,
        cfg: &SimConfig,
        limits: &WalkLimits,
        restart: bool,
        initial: &(dyn Fn(&Model) -> Vector + Sync),
        stop: &dyn Fn() -> bool,
    ) -> Result<Walk, Stopped> {
        let start = self.start(model, restart, initial);
        Ok(self.moved_on(walk_stoppable(model, cfg, &start, limits, stop)?))
    }
}

/// Procedure (P4a): each value continues from the previous steady post-impact state (see
/// [`Carry`]).
fn continuation(
    make: impl Fn(f64) -> Model,
    cfg: &SimConfig,
    grid: &[f64],
    initial: &(dyn Fn(&Model) -> Vector + Sync),
    limits: &WalkLimits,
    progress: &(dyn Fn() + Sync),
) -> Vec<SweepPoint> {
    let mut carry = Carry::default();
    let mut out = Vec::with_capacity(grid.len());
    for &value in grid {
        let w = carry.walk(&make(value), cfg, limits, false, initial);
        out.push(point(value, w));
        progress();
    }
    out
}

/// Several independent sweeps (one per entry of `chains`, for example one per `T_set`), run in
/// parallel; `make(chain, value)` is the model of a point (the caller checks beforehand that
/// every point's model can be built: see [`crate::setup::Setup::model_with`]), `initial(model)`
/// a point's start where it does not continue (see [`Carry`]); `progress` is called once per
/// finished point (from any thread).
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
    initial: impl Fn(&Model) -> Vector + Sync,
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
                let model = make(c, mu0);
                let p = point(mu0, walk(&model, cfg, &initial(&model), limits));
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
                    continuation(|mu0| make(c, mu0), cfg, grid, initial, limits, progress)
                })
            })
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
            .collect()
    })
}

#[cfg(test)]
#[allow(clippy::unwrap_used, reason = "tests")]
mod tests {
    use std::sync::Mutex;

    use super::*;
    use crate::setup::Setup;

    /// A point that does not continue starts from its own model's start: the compass gait's
    /// `[start]` puts the swing foot on the slope (`th_sw = 2 phi - th_st`), so a chain over
    /// `phi` must not start every chain from one slope's start.
    #[test]
    fn every_chain_starts_from_its_own_models_start() {
        let text = include_str!("../../models/compass-gait.toml");
        let file = walker_scene::model::Model::from_toml(text, "compass-gait.toml").unwrap();
        let walker = crate::setup::walker_of(file, None).unwrap();
        let setup = Setup {
            params: walker.defaults(),
            walker,
            name: "compass-gait".into(),
            friction: walker_scene::Friction::Coulomb,
            impact: walker_scene::ImpactLaw::Frictionless,
            fixed: Vec::new(),
        };
        let make = |phi: f64, mu0: f64| {
            let p = setup
                .params
                .with("phi", phi)
                .and_then(|p| p.with("mu0", mu0));
            setup.model_with(&p.unwrap()).unwrap()
        };
        let limits = WalkLimits {
            max_steps: 1,
            duration: f64::INFINITY,
            record: false,
            periodic: None,
        };
        let chains = [0.04, 0.06];
        for restart in [false, true] {
            let seen = Mutex::new(Vec::new());
            let initial = |m: &Model| {
                let s = m.start_state();
                let phi = m.params().get("phi").unwrap();
                seen.lock().unwrap().push((phi, s[2] + s[3]));
                s
            };
            let cfg = SimConfig::default();
            let res = sweep_chains(
                &chains,
                make,
                &cfg,
                &[5.0],
                initial,
                &limits,
                restart,
                &|| {},
            );
            // One step from each chain's start: both walk.
            assert!(
                res.iter()
                    .all(|c| c[0].failure.is_none() && c[0].steps == 1)
            );
            let mut seen = seen.into_inner().unwrap();
            seen.sort_by(|a, b| a.0.total_cmp(&b.0));
            assert_eq!(seen.len(), 2);
            for ((phi, feet), want) in seen.into_iter().zip(chains) {
                assert_eq!(phi, want);
                assert!((feet - 2.0 * want).abs() < 1e-15, "th_st + th_sw = {feet}");
            }
        }
    }
}
