//! Where the gaits are stable: fixed points of the Poincare map and their largest Floquet
//! multiplier along `mu0` for the paper's three `T_set` and three `phi` (continuation from
//! cycle to cycle, [`walker::poincare::continuation`]): `stability.csv`, two figures and the
//! summary lines.

use std::fmt::Write as _;
use std::fs;
use std::path::Path;

use rayon::prelude::*;
use walker::poincare::{ContinuationPoint, Status, continuation};
use walker::sim::SimConfig;
use walker::sweep::mu0_grid;

use super::error::WriteError;
use super::figures::{fig, save_figure};
use super::models::{active, passive};
use crate::plot::Series;
use crate::report::{continuation_csv, stability_summary};

/// The continuation along `mu0` of one chain: `(active walker, points)`, each chain's `T_set`
/// (active) or `phi` (passive) in parallel.
fn continue_chains() -> Vec<(bool, Vec<ContinuationPoint>)> {
    let cfg = SimConfig::default();
    let active_grid = mu0_grid(0.05, 1.0, 0.05);
    let passive_grid = mu0_grid(0.05, 0.7, 0.05);
    let jobs: Vec<(bool, f64)> = [0.2, 0.3, 0.4]
        .map(|t| (true, t))
        .into_iter()
        .chain([0.10, 0.15, 0.20].map(|p| (false, p)))
        .collect();
    jobs.par_iter()
        .map(|&(is_active, chain)| {
            let pts = if is_active {
                continuation(
                    |t_set, mu0| active(mu0, t_set).ok(),
                    &[chain],
                    &active_grid,
                    &cfg,
                )
            } else {
                continuation(
                    |phi, mu0| passive(mu0, phi).ok(),
                    &[chain],
                    &passive_grid,
                    &cfg,
                )
            };
            (is_active, pts)
        })
        .collect()
}

/// The largest multiplier's modulus along `mu0`, one curve per chain of the active
/// (`active_chains`) or passive walker (valid gaits only: an `invalid-gait` cycle, one that
/// lifts off, is not drawn).
fn curves(
    results: &[(bool, Vec<ContinuationPoint>)],
    active_chains: bool,
    name: &str,
) -> Vec<Series> {
    results
        .iter()
        .filter(|(a, _)| *a == active_chains)
        .filter_map(|(_, pts)| {
            let chain = pts.first()?.chain;
            let points = pts
                .iter()
                .filter_map(|p| p.cycle.as_ref().map(|c| (p.mu0, c)))
                .filter(|(_, c)| matches!(c.status, Status::Converged | Status::Family))
                .map(|(mu0, c)| (mu0, c.max_modulus()))
                .filter(|(_, m)| m.is_finite())
                .collect();
            Some(Series::new(format!("{name} = {chain}"), points))
        })
        .collect()
}

/// Compute the stability along `mu0`, write `stability.csv` and the figures
/// `stability_active` and `stability_passive` into `out`; returns the summary lines.
///
/// # Errors
/// A file could not be written.
pub fn stability(out: &Path) -> Result<String, WriteError> {
    let results = continue_chains();
    for (stem, active_chains, name) in [
        ("stability_active", true, "T_set"),
        ("stability_passive", false, "phi"),
    ] {
        let f = fig(
            &format!("Largest Floquet multiplier against mu0 ({name})"),
            "mu0",
            "max |multiplier| (stable below 1)",
            curves(&results, active_chains, name),
            true,
        );
        save_figure(&f, &out.join(stem))?;
    }
    let mut csv = String::new();
    let mut text =
        String::from("- Stability from the Floquet multipliers (largest modulus < 1):\n");
    for (is_active, pts) in &results {
        let body = continuation_csv(pts);
        let body = if csv.is_empty() {
            body.as_str()
        } else {
            body.split_once('\n').map_or("", |(_, b)| b)
        };
        csv.push_str(body);
        for line in stability_summary(pts, if *is_active { "T_set" } else { "phi" }).lines() {
            let _ = writeln!(text, "  {line}");
        }
    }
    let path = out.join("stability.csv");
    fs::write(&path, csv).map_err(WriteError::file(path))?;
    Ok(text)
}
