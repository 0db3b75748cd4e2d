//! Bifurcation diagrams of Figs. 8 and 10 by continuation (`walker continue`), beside the
//! simulated figures: the speed of every period-one gait against `mu0` for the three `T_set`
//! of Fig. 8 and the three `phi` of Fig. 10, and against `phi` for the passive wheel at
//! `mu0 = 0.5`; stable parts solid, unstable dashed, parts that are not physical pale, special
//! points tagged, the 100 s walks of the sweeps as crosses. Written as new files
//! (`fig8_bifurcation`, `fig10_bifurcation`, `fig10_bifurcation_phi`: PNG, SVG and CSV); no
//! other output of `walker reproduce` depends on them.

use std::path::Path;

use plotters::chart::SeriesLabelPosition;
use walker::continuation::{Branch, ContinuationOptions, WalkerProblem, continuation};
use walker::setup::Setup;
use walker::sim::SimConfig;
use walker::sweep::SweepPoint;

use super::data::{Data, PHIS, T_SETS};
use super::error::WriteError;
use super::models::{active_setup, passive_setup};
use crate::continue_cmd::{diagram, output};

/// Largest continuation step of the diagrams: a twentieth of the range, so that the drawn
/// polyline follows the curve (the library's default, 0.2, is for speed).
const MAX_STEP: f64 = 0.05;

/// `mu0` of the diagram over `phi` (Fig. 11's sliding case on `phi = 0.2` walks there too).
const MU0_OVER_PHI: f64 = 0.5;

/// The branch of `setup` in `param` over `[from, to]`, or `None` where none was found.
fn branch(setup: Result<Setup, WriteError>, param: &str, from: f64, to: f64) -> Option<Branch> {
    let w = WalkerProblem::new(setup.ok()?, param, SimConfig::default()).ok()?;
    let opts = ContinuationOptions {
        max_step: MAX_STEP,
        ..ContinuationOptions::default()
    };
    continuation(&w, from, to, &opts).ok()
}

/// The steady speeds of a sweep's periodic, successful walks.
fn simulated(sweeps: &[(f64, Vec<SweepPoint>)]) -> Vec<(f64, f64)> {
    sweeps
        .iter()
        .flat_map(|(_, pts)| pts.iter())
        .filter(|p| p.failure.is_none())
        .filter_map(|p| {
            let (last, prev) = (p.last?, p.previous?);
            let repeats = ((last.speed - prev.speed) / last.speed).abs() < 1e-6;
            repeats.then_some((p.value, last.speed))
        })
        .collect()
}

/// Draw `branches` as `stem.png`, `stem.svg` and write `stem.csv`.
#[allow(clippy::too_many_arguments, reason = "one per part of the figure")]
fn write(
    out: &Path,
    stem: &str,
    legend: SeriesLabelPosition,
    title: &str,
    x_label: &str,
    branches: &[(String, Branch)],
    sim: Vec<(f64, f64)>,
) -> Result<(), WriteError> {
    let d = diagram::Diagram {
        title: title.to_owned(),
        x_label: x_label.to_owned(),
        branches: branches.iter().map(|(n, b)| (n.clone(), b)).collect(),
        simulated: ("100 s walks (periodic)".to_owned(), sim),
        legend,
    };
    for ext in ["png", "svg"] {
        let path = out.join(format!("{stem}.{ext}"));
        diagram::save(&d, &path).map_err(|message| WriteError::Figure {
            path: out.join(stem),
            message,
        })?;
    }
    let all: Vec<Branch> = branches.iter().map(|(_, b)| b.clone()).collect();
    let path = out.join(format!("{stem}.csv"));
    std::fs::write(&path, output::csv(&all)).map_err(WriteError::file(&path))
}

/// Compute the branches (one thread per branch) and write the three diagrams into `out`.
///
/// # Errors
/// A file could not be written.
pub fn write_bifurcation(out: &Path, d: &Data) -> Result<(), WriteError> {
    let active = |t: f64| active_setup(0.4, t);
    let passive = |phi: f64, mu0: f64| passive_setup(mu0, phi);
    let (fig8, fig10, over_phi) = std::thread::scope(|scope| {
        let fig8: Vec<_> = T_SETS
            .map(|t| {
                scope.spawn(move || (format!("T_set = {t}"), branch(active(t), "mu0", 0.0, 1.0)))
            })
            .into_iter()
            .collect();
        let fig10: Vec<_> = PHIS
            .map(|phi| {
                scope.spawn(move || {
                    (
                        format!("phi = {phi}"),
                        branch(passive(phi, 0.0), "mu0", 0.0, 0.7),
                    )
                })
            })
            .into_iter()
            .collect();
        let over_phi = scope.spawn(|| branch(passive(0.2, MU0_OVER_PHI), "phi", 0.05, 0.3));
        let join = |hs: Vec<std::thread::ScopedJoinHandle<'_, (String, Option<Branch>)>>| {
            hs.into_iter()
                .filter_map(|h| h.join().ok())
                .filter_map(|(n, b)| b.map(|b| (n, b)))
                .collect::<Vec<_>>()
        };
        (join(fig8), join(fig10), over_phi.join().ok().flatten())
    });
    write(
        out,
        "fig8_bifurcation",
        SeriesLabelPosition::MiddleRight,
        "Fig. 8 by continuation: V against mu0 (dashed: unstable, pale: not physical)",
        "mu0",
        &fig8,
        simulated(&d.active_sweep),
    )?;
    write(
        out,
        "fig10_bifurcation",
        SeriesLabelPosition::LowerRight,
        "Fig. 10 by continuation: V against mu0 (dashed: unstable, pale: not physical)",
        "mu0",
        &fig10,
        simulated(&d.passive_sweep),
    )?;
    let over_phi: Vec<_> = over_phi
        .map(|b| (format!("mu0 = {MU0_OVER_PHI}"), b))
        .into_iter()
        .collect();
    write(
        out,
        "fig10_bifurcation_phi",
        SeriesLabelPosition::LowerRight,
        "The passive wheel by continuation: V against phi (dashed: unstable)",
        "phi (rad)",
        &over_phi,
        Vec::new(),
    )
}
