//! The experiments behind the paper's figures: the walks and `mu0` sweeps of Figs. 3-8 and
//! 10-14 with the paper's settings ([`OMEGAS`], [`T_SETS`], [`PHIS`]; the passive sweeps in
//! [`super::passive`]), collected once into [`Data`] for the CSV files, the figures and the
//! summary.

use walker::model::{Friction, ImpactLaw};
use walker::sim::{SimConfig, Walk, WalkLimits, walk};
use walker::sweep::{SweepPoint, mu0_grid, sweep_chains};
use walker::vector::Vector;

use super::error::WriteError;
use super::models::{Table1, active, active_setup, grid, model, passive, start};
pub use super::passive::PHIS;
use super::passive::{PassiveSweeps, passive_sweeps, passive_walks};
use crate::progress::Progress;

/// Omega0 values of Figs. 4 and 6.
pub const OMEGAS: [f64; 3] = [0.6, 0.7, 0.8];
/// `T_set` values of Fig. 8.
pub const T_SETS: [f64; 3] = [0.2, 0.3, 0.4];

/// The collected data of every figure.
pub struct Data {
    /// Table 1, as the built-in scenes fix it.
    pub table1: Table1,
    /// Fig. 3 (`mu0 = 0`) and Fig. 5 (`mu0 = 0.4`) motions, `T_set = 0.3`, `omega0 = 0.8`.
    pub motion: [Walk; 2],
    /// Figs. 4 and 6: steps for three `omega0` at `mu0 = 0` and `mu0 = 0.4`.
    pub omega_series: [Vec<(f64, Walk)>; 2],
    /// Fig. 7: errors of the post-impact velocities from the steady ones.
    pub convergence: Vec<[f64; 3]>,
    /// Fig. 8: sweeps over `mu0` for `T_set` = 0.2, 0.3, 0.4.
    pub active_sweep: Vec<(f64, Vec<SweepPoint>)>,
    /// Figs. 10 and 13: sweeps over `mu0` for `phi` = 0.10, 0.15, 0.20, each `mu0` from (P2b)
    /// (the paper's (P5b) "Repeat from (P2b)", `walker sweep --restart`), 100 s per `mu0`.
    pub passive_sweep: Vec<(f64, Vec<SweepPoint>)>,
    /// Fig. 10 read the other way: each `mu0` from the previous one's last state ((P4b)).
    pub passive_continuation: Vec<(f64, Vec<SweepPoint>)>,
    /// The passive wheel (Table 1) beyond the paper's `mu0`, per `phi`, each `mu0` from (P2b),
    /// 100 s ([`super::passive::LARGE_MU0`]).
    pub passive_large_mu0: Vec<(f64, Vec<SweepPoint>)>,
    /// The passive wheel with other wheel inertias `I1`, each `mu0` from (P2b), 100 s: `(I1,
    /// points)` ([`super::passive::INERTIAS`]).
    pub passive_inertia: Vec<(f64, Vec<SweepPoint>)>,
    /// The Fig. 8 sweep at `T_set = 0.3` with exact Coulomb friction (Eq. 25, stick-slip).
    pub coulomb_sweep: Vec<(f64, Vec<SweepPoint>)>,
    /// The same with Coulomb friction at the impact too (`docs/impacts.md`).
    pub coulomb_impact_sweep: Vec<(f64, Vec<SweepPoint>)>,
    /// Fig. 11: motions at `phi = 0.2`, `mu0` = 0.2 and 0.5.
    pub sticks: Vec<(f64, Walk)>,
    /// Fig. 12: step lengths at `phi = 0.2` for four `mu0`.
    pub step_lengths: Vec<(f64, Walk)>,
    /// Fig. 14: the motion at `phi = 0.10`, `mu0 = 0.19`.
    pub fall: Walk,
}

/// At most `max_steps` steps, no time limit; samples kept if `record`.
fn limits(max_steps: usize, record: bool) -> WalkLimits {
    WalkLimits {
        max_steps,
        duration: f64::INFINITY,
        record,
        periodic: None,
    }
}

/// Fig. 7: the steady state at `T_set = 0.3`, `mu0 = 0.4`, then a start 0.1 rad/s above its
/// angular velocity; per impact `[|qd+ - qd+_eq|, d xd+, d th1d+]` (empty if the steady walk
/// has no step).
fn convergence(cfg: &SimConfig) -> Result<Vec<[f64; 3]>, WriteError> {
    let m = active(0.4, 0.3)?;
    let steady = walk(&m, cfg, &start(&m, 0.8)?, &limits(400, false));
    let mut convergence = Vec::new();
    if let Some(eq) = steady.steps.last() {
        let w0 = eq.qd_plus[2] + 0.1;
        let w = walk(&m, cfg, &start(&m, w0)?, &limits(30, false));
        let mut qds = vec![Vector::from([0.0, 0.0, w0, w0])];
        qds.extend(w.steps.iter().map(|s| s.qd_plus));
        for qd in qds {
            let d: Vec<f64> = qd
                .iter()
                .zip(eq.qd_plus.iter())
                .map(|(a, b)| a - b)
                .collect();
            let norm = d.iter().map(|v| v * v).sum::<f64>().sqrt();
            convergence.push([norm, d[0], d[2]]);
        }
    }
    Ok(convergence)
}

/// A walk of `m` from the paper's start with `omega0`, under `limits`.
fn walk_from(
    m: &walker::model::Model,
    cfg: &SimConfig,
    omega0: f64,
    limits: &WalkLimits,
) -> Result<Walk, WriteError> {
    Ok(walk(m, cfg, &start(m, omega0)?, limits))
}

/// Compute every figure's data.
///
/// # Errors
/// The paper's walkers cannot be set up (a defect of the shipped files).
pub fn collect() -> Result<Data, WriteError> {
    let cfg = SimConfig::default();
    let motion = [
        walk_from(&active(0.0, 0.3)?, &cfg, 0.8, &limits(6, true))?,
        walk_from(&active(0.4, 0.3)?, &cfg, 0.8, &limits(6, true))?,
    ];
    let omegas = |mu0: f64| -> Result<Vec<(f64, Walk)>, WriteError> {
        OMEGAS
            .iter()
            .map(|&w0| {
                Ok((
                    w0,
                    walk_from(&active(mu0, 0.3)?, &cfg, w0, &limits(30, false))?,
                ))
            })
            .collect()
    };
    let omega_series = [omegas(0.0)?, omegas(0.4)?];
    let convergence = convergence(&cfg)?;
    let mu0s = mu0_grid(0.0, 1.0, 0.01);
    let long = WalkLimits {
        max_steps: 1000,
        duration: 100.0,
        record: false,
        periodic: None,
    };
    // Every sweep at once, under one progress bar: the sequential chains (three `T_set` of
    // Fig. 8, its two Coulomb chains, the continued passive chains) each on a thread of their own,
    // the independent passive walks on the rayon pool, so that no core waits for the longest
    // chain of one sweep while another sweep has work.
    let fig8_models = grid(&T_SETS, &mu0s, |ts, mu0| active(mu0, ts))?;
    let coulomb_models = |law: ImpactLaw| {
        grid(&[0.3], &mu0s, move |ts, mu0| {
            let mut s = active_setup(mu0, ts)?;
            s.friction = Friction::Coulomb;
            s.impact = law;
            model(&s)
        })
    };
    let coulomb_frictionless = coulomb_models(ImpactLaw::Frictionless)?;
    let coulomb_with_friction = coulomb_models(ImpactLaw::Coulomb)?;
    let start08 = start(&active(0.0, 0.3)?, 0.8)?;
    let passive_models = super::passive::PassiveModels::new()?;
    let bar = Progress::new(
        "Figs. 8, 10 and 13 sweeps",
        (T_SETS.len() + 2) * mu0s.len() + passive_walks(),
    );
    let tick = || bar.tick();
    let (active_sweep, coulomb_sweep, coulomb_impact_sweep, sweeps) = std::thread::scope(|scope| {
        let fig8 = scope.spawn(|| {
            sweep_chains(
                &T_SETS,
                &fig8_models,
                &cfg,
                &mu0s,
                |_| start08,
                &long,
                false,
                &tick,
            )
        });
        // Fig. 8 at T_set = 0.3 under exact Coulomb friction, with the paper's impact and with
        // friction at the impact.
        let coulomb = scope.spawn(|| {
            let m = &coulomb_frictionless;
            sweep_chains(&[0.3], m, &cfg, &mu0s, |_| start08, &long, false, &tick)
        });
        let coulomb_impact = scope.spawn(|| {
            let m = &coulomb_with_friction;
            sweep_chains(&[0.3], m, &cfg, &mu0s, |_| start08, &long, false, &tick)
        });
        let passive = passive_sweeps(&passive_models, &cfg, &tick);
        let join = |h: std::thread::ScopedJoinHandle<'_, Vec<Vec<SweepPoint>>>| {
            h.join().unwrap_or_else(|e| std::panic::resume_unwind(e))
        };
        let fig8: Vec<(f64, Vec<SweepPoint>)> = T_SETS.iter().copied().zip(join(fig8)).collect();
        let coulomb = vec![0.3].into_iter().zip(join(coulomb)).collect();
        let coulomb_impact = vec![0.3].into_iter().zip(join(coulomb_impact)).collect();
        (fig8, coulomb, coulomb_impact, passive)
    });
    bar.finish();
    let PassiveSweeps {
        restart: passive_sweep,
        continued: passive_continuation,
        large_mu0: passive_large_mu0,
        inertia: passive_inertia,
    } = sweeps;
    let sticks = [0.2, 0.5]
        .iter()
        .map(|&mu0| {
            Ok((
                mu0,
                walk_from(&passive(mu0, 0.2)?, &cfg, 0.5, &limits(6, true))?,
            ))
        })
        .collect::<Result<_, WriteError>>()?;
    let step_lengths = [0.2, 0.3, 0.4, 0.5]
        .iter()
        .map(|&mu0| {
            let walk = walk_from(&passive(mu0, 0.2)?, &cfg, 0.5, &limits(20, false))?;
            Ok((mu0, walk))
        })
        .collect::<Result<_, WriteError>>()?;
    let fall = walk_from(&passive(0.19, 0.10)?, &cfg, 0.5, &limits(5, true))?;
    Ok(Data {
        table1: Table1::load()?,
        motion,
        omega_series,
        convergence,
        active_sweep,
        passive_sweep,
        passive_continuation,
        passive_large_mu0,
        passive_inertia,
        coulomb_sweep,
        coulomb_impact_sweep,
        sticks,
        step_lengths,
        fall,
    })
}
