//! The passive wheel's sweeps as the paper runs them ((P1b)-(P5b), Section 5.2), and beyond:
//! every `mu0` walks [`PASSIVE_DURATION`] = 100 s from (P2b) ((P3b); (P5b) "Repeat from (P2b)")
//! or from the previous `mu0`'s last state ((P4b)), and is stopped early once its gait is
//! periodic by the library's test ([`WalkLimits::periodic`] with [`PERIODIC_TOL`]; the rest of
//! the 100 s would repeat its last step). A walk that reaches 100 s without becoming periodic
//! keeps `periodic = false`. Beyond the paper: Table 1 for `mu0` up to 1.5 ([`LARGE_MU0`]) and
//! other wheel inertias ([`INERTIAS`]), for the paper's remark on large `mu0` and small inertia.

use walker::model::Model;
use walker::sim::{SimConfig, WalkLimits};
use walker::sweep::{SweepPoint, mu0_grid, sweep_chains};
use walker::vector::Vector;

use super::error::WriteError;
use super::models::{grid, model, passive, passive_setup, start};

/// Slope angles of Fig. 10.
pub const PHIS: [f64; 3] = [0.10, 0.15, 0.20];
/// The `mu0` grid `(from, to, step)` of Figs. 10 and 13 ((P1b)-(P5b)).
pub const PAPER_MU0: (f64, f64, f64) = (0.0, 0.7, 0.01);
/// How long each `mu0` of the passive sweeps walks ((P3b): "for over 100 s") (s).
pub const PASSIVE_DURATION: f64 = 100.0;
/// The periodic-gait tolerance of the passive sweeps ([`WalkLimits::periodic`]): a walk stops
/// once the relative change of `T` and `dx` from step to step, continued geometrically, adds up
/// to at most this. 1e-9 is near the integration tolerance (`rtol` 1e-10), so a periodic
/// point's descriptors are those of the full 100 s walk to about nine digits.
pub const PERIODIC_TOL: f64 = 1e-9;
/// `mu0` grid `(from, to, step)` of the passive wheel beyond the paper's `mu0 <= 0.7` (Table 1,
/// each `mu0` from (P2b)).
pub const LARGE_MU0: (f64, f64, f64) = (0.70, 1.50, 0.05);
/// Wheel inertias `I1` (kg m^2) other than Table 1's 0.5 for the paper's remark that a larger
/// inertia cures the failure at large `mu0`, walked on [`INERTIA_PHI`] over [`INERTIA_MU0`].
pub const INERTIAS: [f64; 2] = [0.25, 1.0];
/// The slope of the inertia sweeps (rad).
pub const INERTIA_PHI: f64 = 0.10;
/// `mu0` grid `(from, to, step)` of the inertia sweeps.
pub const INERTIA_MU0: (f64, f64, f64) = (0.50, 2.00, 0.05);

/// The passive sweeps: `(chain value, points)` per chain.
pub struct PassiveSweeps {
    /// Figs. 10 and 13: per `phi` of [`PHIS`], each `mu0` from (P2b).
    pub restart: Vec<(f64, Vec<SweepPoint>)>,
    /// Fig. 10 read the other way: each `mu0` from the previous one's last state ((P4b)).
    pub continued: Vec<(f64, Vec<SweepPoint>)>,
    /// Table 1 over [`LARGE_MU0`], per `phi` of [`PHIS`], each `mu0` from (P2b).
    pub large_mu0: Vec<(f64, Vec<SweepPoint>)>,
    /// `(I1, points)` for the inertias of [`INERTIAS`] on [`INERTIA_PHI`] over [`INERTIA_MU0`],
    /// each `mu0` from (P2b).
    pub inertia: Vec<(f64, Vec<SweepPoint>)>,
}

/// The number of walks of [`passive_sweeps`] (for a progress bar).
#[must_use]
pub fn passive_walks() -> usize {
    let n = |(a, b, s): (f64, f64, f64)| mu0_grid(a, b, s).len();
    PHIS.len() * (2 * n(PAPER_MU0) + n(LARGE_MU0)) + INERTIAS.len() * n(INERTIA_MU0)
}

/// The walk of each `mu0`: 100 s, stopped once periodic.
fn limits() -> WalkLimits {
    WalkLimits {
        max_steps: 100_000,
        duration: PASSIVE_DURATION,
        record: false,
        periodic: Some(PERIODIC_TOL),
    }
}

/// The passive wheel of Table 1 with the wheel inertia `I1 = i1` on [`INERTIA_PHI`] at `mu0`
/// (every parameter at run time).
fn with_inertia(i1: f64, mu0: f64) -> Result<Model, WriteError> {
    let mut s = passive_setup(mu0, INERTIA_PHI)?;
    s.set("I1", i1)
        .map_err(|e| WriteError::Setup(e.to_string()))?;
    model(&s)
}

/// The models of every passive sweep, built before any walk, and the start (P2b).
pub struct PassiveModels {
    paper: Box<dyn Fn(f64, f64) -> Model + Sync>,
    large: Box<dyn Fn(f64, f64) -> Model + Sync>,
    inertia: Box<dyn Fn(f64, f64) -> Model + Sync>,
    start: Vector,
}

impl PassiveModels {
    /// Builds them.
    ///
    /// # Errors
    /// The passive wheel cannot be set up (a defect of the shipped files).
    pub fn new() -> Result<PassiveModels, WriteError> {
        let over = |(from, to, step): (f64, f64, f64)| {
            grid(&PHIS, &mu0_grid(from, to, step), |phi, mu0| {
                passive(mu0, phi)
            })
        };
        let (from, to, step) = INERTIA_MU0;
        Ok(PassiveModels {
            paper: over(PAPER_MU0)?,
            large: over(LARGE_MU0)?,
            inertia: grid(&INERTIAS, &mu0_grid(from, to, step), with_inertia)?,
            start: start(&passive(0.0, PHIS[0])?, 0.5)?,
        })
    }
}

/// `(chain, points)` of [`sweep_chains`] over the passive wheel of Table 1, one chain per `phi`.
fn over_phi(
    models: &(dyn Fn(f64, f64) -> Model + Sync),
    start: Vector,
    cfg: &SimConfig,
    (from, to, step): (f64, f64, f64),
    restart: bool,
    tick: &(dyn Fn() + Sync),
) -> Vec<(f64, Vec<SweepPoint>)> {
    let points = sweep_chains(
        &PHIS,
        models,
        cfg,
        &mu0_grid(from, to, step),
        |_| start,
        &limits(),
        restart,
        tick,
    );
    PHIS.iter().copied().zip(points).collect()
}

/// Run every passive sweep; `tick` is called once per finished walk (from any thread). The
/// continued reading ((P4b), three sequential chains) runs on threads of its own next to the
/// others (independent walks on the rayon pool), so that both cores stay busy.
#[must_use]
pub fn passive_sweeps(
    m: &PassiveModels,
    cfg: &SimConfig,
    tick: &(dyn Fn() + Sync),
) -> PassiveSweeps {
    std::thread::scope(|scope| {
        let continued = scope.spawn(|| over_phi(&m.paper, m.start, cfg, PAPER_MU0, false, tick));
        let restart = over_phi(&m.paper, m.start, cfg, PAPER_MU0, true, tick);
        let large_mu0 = over_phi(&m.large, m.start, cfg, LARGE_MU0, true, tick);
        let (from, to, step) = INERTIA_MU0;
        let inertia = sweep_chains(
            &INERTIAS,
            &m.inertia,
            cfg,
            &mu0_grid(from, to, step),
            |_| m.start,
            &limits(),
            true,
            tick,
        );
        PassiveSweeps {
            restart,
            continued: continued
                .join()
                .unwrap_or_else(|e| std::panic::resume_unwind(e)),
            large_mu0,
            inertia: INERTIAS.iter().copied().zip(inertia).collect(),
        }
    })
}
