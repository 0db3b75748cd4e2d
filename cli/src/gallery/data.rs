//! The gallery's experiments: per model, its held gait on each slope ([`super::held`]) and the
//! `mu0` sweeps under each of the [`LAWS`], collected into [`ModelRun`]s for the CSV files, the
//! figures and the claims.
//!
//! Every `mu0` starts from the slope's held gait (its post-impact state; or the model's own
//! start, on its gait, where the entry says so: [`Start`]) and walks [`DURATION`], stopped once
//! periodic: each point is the walker in its gait stepping onto a floor of that friction,
//! independent of the sweep's order (`sweep_chains` with `restart`).
//! Continuing each `mu0` from the previous one's last state, as the paper's (P4a), would carry a
//! walk that slides away or has not settled into the next `mu0` (the rimless wheel's lift-off
//! at 0.30 on `phi = 0.2` in a continued sweep starts from such a state) and runs each slope's
//! chain on one core; restarted, all points share the rayon pool.

use walker::model::Model;
use walker::sim::{SimConfig, Walk, WalkLimits, walk};
use walker::sweep::{SweepPoint, mu0_grid, sweep_chains};
use walker::vector::Vector;

use super::designed::{self, Designed};
use super::entries::{ENTRIES, Entry, Start};
use super::held::{Held, held};
use super::laws::{LAWS, Laws};
use super::outcome::Outcome;
use crate::progress::Progress;
use crate::reproduce::WriteError;
use crate::reproduce::models::grid;
use crate::reproduce::passive::PERIODIC_TOL;

/// How long each `mu0` walks at most (s): a few dozen steps of either walker.
pub const DURATION: f64 = 20.0;

/// The `mu0` grid `(from, to, step)` of the sweeps.
pub const MU0: (f64, f64, f64) = (0.0, 1.0, 0.02);

/// One slope of a model: its value (NaN for a level walker) and its held gait, or why it has
/// none.
#[derive(Clone, Debug)]
pub struct Slope {
    /// The slope angle (rad), NaN on a level floor.
    pub phi: f64,
    /// The held gait.
    pub held: Result<Held, String>,
}

/// The sweeps of one model under one pair of laws: per slope, its points.
#[derive(Clone, Debug)]
pub struct Sweep {
    /// The laws.
    pub laws: Laws,
    /// Per slope (in the order of [`ModelRun::slopes`]), the points.
    pub chains: Vec<Vec<SweepPoint>>,
}

/// Everything the gallery computed for one model.
#[derive(Clone, Debug)]
pub struct ModelRun {
    /// The gallery's entry.
    pub entry: Entry,
    /// The name of its slope parameter (`None`: level).
    pub slope_param: Option<String>,
    /// The slopes and their held gaits.
    pub slopes: Vec<Slope>,
    /// The index in [`ModelRun::slopes`] of the model's own slope (its default), else 0.
    pub nominal: usize,
    /// The `mu0` grid.
    pub grid: Vec<f64>,
    /// One sweep per pair of [`LAWS`], in that order.
    pub sweeps: Vec<Sweep>,
    /// The designed gait beside the hand-made one, for the models of [`designed::MODELS`]
    /// (else `None`), or why there is none.
    pub designed: Option<Result<Designed, String>>,
}

impl ModelRun {
    /// The held gait's speed on slope `i`, if it has one.
    #[must_use]
    pub fn held_speed(&self, i: usize) -> Option<f64> {
        self.slopes[i].held.as_ref().ok().map(|h| h.step.speed)
    }

    /// The outcome of point `p` on slope `i`.
    #[must_use]
    pub fn outcome(&self, i: usize, p: &SweepPoint) -> Outcome {
        Outcome::of(p, self.held_speed(i))
    }

    /// The sweep under `laws`.
    #[must_use]
    pub fn sweep(&self, laws: Laws) -> Option<&Sweep> {
        self.sweeps.iter().find(|s| s.laws == laws)
    }

    /// Where the walks of slope `i` start for the model `m` (of this entry, on that slope): the
    /// held gait's post-impact state, or the model's own start ([`Start`]); `None` where the
    /// entry starts from the held gait and the slope has none.
    #[must_use]
    pub fn start(&self, i: usize, m: &Model) -> Option<Vector> {
        match self.entry.start {
            Start::Held => self.slopes[i].held.as_ref().ok().map(|h| h.start),
            Start::Own => Some(m.start_state()),
        }
    }

    /// A walk of at most `steps` steps under `laws` at `mu0` on slope `i` from where its sweeps
    /// start ([`ModelRun::start`]; no time limit, not stopped when periodic), for a claim that
    /// needs more than a sweep's last two steps; `None` where there is no start or the model
    /// cannot be built.
    #[must_use]
    pub fn walk(&self, i: usize, laws: Laws, mu0: f64, steps: usize) -> Option<Walk> {
        let setup = self.entry.setup().ok()?;
        let m = laws.model(&setup, self.slopes[i].phi, mu0).ok()?;
        let start = self.start(i, &m)?;
        let limits = WalkLimits {
            max_steps: steps,
            ..WalkLimits::default()
        };
        Some(walk(&m, &SimConfig::default(), &start, &limits))
    }

    /// `phi = 0.2` (or `level`) for slope `i`, with degrees where the slope is a whole number
    /// of them.
    #[must_use]
    pub fn slope_label(&self, i: usize) -> String {
        let phi = self.slopes[i].phi;
        if phi.is_nan() {
            return "level".to_owned();
        }
        let deg = phi.to_degrees();
        if (deg - deg.round()).abs() < 1e-9 {
            format!("phi = {deg:.0} deg")
        } else {
            format!("phi = {phi}")
        }
    }
}

/// The held gaits and the sweeps of `entry` on the grid `mu0s`; `tick` after each walk.
fn run_model(entry: Entry, mu0s: &[f64], tick: &(dyn Fn() + Sync)) -> Result<ModelRun, WriteError> {
    let setup = entry.setup()?;
    let spec = setup.walker.spec().clone();
    let slope_param = spec
        .slope
        .map(|i| spec.model.parameters[i].name.name.clone());
    let phis: Vec<f64> = match &slope_param {
        Some(_) if !entry.slopes.is_empty() => entry.slopes.to_vec(),
        _ => vec![f64::NAN],
    };
    let own = slope_param.as_deref().and_then(|n| setup.params.get(n));
    let nominal = phis.iter().position(|&p| Some(p) == own).unwrap_or(0);
    let slopes: Vec<Slope> = phis
        .iter()
        .map(|&phi| Slope {
            phi,
            held: held(&setup, phi),
        })
        .collect();
    let starts: Vec<Option<Vector>> = slopes
        .iter()
        .map(|s| s.held.as_ref().ok().map(|h| h.start))
        .collect();
    let limits = WalkLimits {
        max_steps: 100_000,
        duration: DURATION,
        record: false,
        periodic: Some(PERIODIC_TOL),
    };
    let cfg = SimConfig::default();
    let mut sweeps = Vec::new();
    for laws in LAWS {
        let make = grid(&phis, mu0s, |phi, mu0| {
            laws.model(&setup, phi, mu0)
                .map_err(|e| WriteError::Setup(format!("{}: {e}", entry.model)))
        })?;
        // A point starts from its slope's held gait (the model's start where there is none),
        // or from the model's own start where the entry says so.
        let initial = |m: &Model| {
            let phi = slope_param.as_deref().and_then(|n| m.params().get(n));
            let i = phis.iter().position(|&p| Some(p) == phi).unwrap_or(0);
            match entry.start {
                Start::Held => starts[i].unwrap_or_else(|| m.start_state()),
                Start::Own => m.start_state(),
            }
        };
        let chains = sweep_chains(&phis, &make, &cfg, mu0s, initial, &limits, true, tick);
        sweeps.push(Sweep { laws, chains });
    }
    let designed = designed::MODELS
        .contains(&entry.model)
        .then(|| designed::designed(&setup));
    Ok(ModelRun {
        entry,
        slope_param,
        slopes,
        nominal,
        grid: mu0s.to_vec(),
        sweeps,
        designed,
    })
}

/// Run every model of [`ENTRIES`] on the grid [`MU0`].
///
/// # Errors
/// A model cannot be set up (a defect of the shipped files).
pub fn collect() -> Result<Vec<ModelRun>, WriteError> {
    let (from, to, step) = MU0;
    let mu0s = mu0_grid(from, to, step);
    let chains: usize = ENTRIES.iter().map(|e| e.slopes.len().max(1)).sum();
    let bar = Progress::new("gallery sweeps", chains * LAWS.len() * mu0s.len());
    let tick = || bar.tick();
    let runs = ENTRIES
        .iter()
        .map(|&e| run_model(e, &mu0s, &tick))
        .collect::<Result<Vec<_>, _>>()?;
    bar.finish();
    Ok(runs)
}
