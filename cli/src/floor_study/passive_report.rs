//! The passive part's files: `floor_study_passive.csv`, the figure `floor_study_passive` and
//! its section of `summary.txt`.

use std::fmt::Write as _;
use std::path::Path;

use super::data::Size;
use super::passive::{Draw, MESH_CHECK, MESH_POINTS, MESH_SAMPLES, Outcome, Walker, passive_size};
use plotters::chart::SeriesLabelPosition;

use crate::plot::{Figure, Marker, Series, save_grid};
use crate::reproduce::WriteError;
use crate::reproduce::csv::fmt;

/// One row per case: the Monte Carlo statistics, the mesh at each size, the friction the gait
/// needs (friction cases) and the failures by kind.
#[must_use]
pub fn csv(outcomes: &[Outcome], size: Size) -> String {
    let size = passive_size(size);
    let mut s = String::from(
        "walker,floor,nominal_or_lo,spread_or_hi,walks,max_steps,failures,restricted_mean_steps,\
         mfpt_constant_rate,mfpt_lo,mfpt_hi",
    );
    for n in MESH_POINTS {
        let _ = write!(s, ",mesh_{n}");
    }
    let _ = write!(s, ",mesh_{}_samples_{}", MESH_CHECK.0, MESH_CHECK.1);
    s.push_str(",mesh_eigen,mesh_error,needed_mu0,failures_by_kind\n");
    for o in outcomes {
        let sv = &o.survival;
        let e = &sv.mfpt.exponential;
        let (kind, a, b) = match o.case.draw {
            Draw::Slope { nominal, spread } => ("slope", nominal, spread),
            Draw::Friction { lo, hi } => ("friction", lo, hi),
        };
        let _ = write!(
            s,
            "{},{kind},{},{},{},{},{},{},{},{},{}",
            o.case.walker.model(),
            fmt(Some(a)),
            fmt(Some(b)),
            sv.walks,
            size.max_steps,
            sv.failures,
            fmt(Some(sv.mfpt.restricted_mean)),
            fmt(e.estimate),
            fmt(Some(e.lo)),
            fmt(e.hi),
        );
        for t in o.refinements() {
            let _ = write!(s, ",{}", fmt(t));
        }
        let (n, m) = MESH_CHECK;
        let _ = write!(
            s,
            ",{}",
            fmt(o.mesh_at(n, m).and_then(|p| p.from_fixed_point))
        );
        let _ = writeln!(
            s,
            ",{},{},{},{}",
            fmt(o
                .mesh_at(MESH_POINTS[MESH_POINTS.len() - 1], MESH_SAMPLES)
                .and_then(|m| m.eigen)),
            fmt(o.mesh_estimate().map(|e| e.1)),
            fmt(o.needed_mu0()),
            sv.failures_text(":", " ")
        );
    }
    s
}

/// The figure: the MFPT against the slopes' spread (Monte Carlo with its interval, the mesh),
/// and the survival curves of the widest slopes and of the friction ranges.
///
/// # Errors
/// The figure could not be written.
pub fn figure(out: &Path, outcomes: &[Outcome], size: Size) -> Result<(), WriteError> {
    let log = |x: f64| x.max(1e-3).log10();
    let mut series = Vec::new();
    for (c, walker) in [Walker::Wheel, Walker::Compass].into_iter().enumerate() {
        let cases: Vec<(f64, &Outcome)> = outcomes
            .iter()
            .filter_map(|o| match o.case.draw {
                Draw::Slope { spread, .. } if o.case.walker == walker => Some((spread, o)),
                _ => None,
            })
            .collect();
        let mc = |g: &dyn Fn(&Outcome) -> Option<f64>| {
            cases
                .iter()
                .filter_map(|(s, o)| g(o).map(|t| (*s, log(t))))
                .collect::<Vec<_>>()
        };
        series.push(
            Series::new(
                format!("{}, Monte Carlo", walker.label()),
                mc(&|o| o.survival.mfpt.exponential.estimate),
            )
            .color(2 * c),
        );
        series.push(
            Series::new(
                format!("{}, 95% interval, low end", walker.label()),
                mc(&|o| Some(o.survival.mfpt.exponential.lo)),
            )
            .color(2 * c)
            .markers(Marker::Ring),
        );
        series.push(
            Series::new(
                format!("{}, 95% interval, high end", walker.label()),
                mc(&|o| o.survival.mfpt.exponential.hi),
            )
            .color(2 * c)
            .markers(Marker::Ring),
        );
        let mesh = mc(&|o| o.mesh_estimate().map(|e| e.0));
        if !mesh.is_empty() {
            series.push(
                Series::new(
                    format!(
                        "{}, mesh (N = {})",
                        walker.label(),
                        MESH_POINTS[MESH_POINTS.len() - 1]
                    ),
                    mesh,
                )
                .color(2 * c + 1),
            );
        }
    }
    let spread = Figure {
        title: "Mean first-passage time on random slopes".to_owned(),
        x_label: "spread of the slope around the nominal (rad)".to_owned(),
        y_label: "log10 MFPT (steps before a failure)".to_owned(),
        series,
        markers: true,
        equal_axes: false,
        // The times fall from the upper left: the upper right is free.
        legend: Some(SeriesLabelPosition::UpperRight),
        y_range: None,
    };
    let curves: Vec<Series> = outcomes
        .iter()
        .filter(|o| match o.case.draw {
            Draw::Slope { spread, .. } => {
                let widest = outcomes
                    .iter()
                    .filter(|p| p.case.walker == o.case.walker)
                    .filter_map(|p| match p.case.draw {
                        Draw::Slope { spread, .. } => Some(spread),
                        Draw::Friction { .. } => None,
                    })
                    .fold(0.0, f64::max);
                spread == widest
            }
            Draw::Friction { .. } => true,
        })
        .enumerate()
        .map(|(i, o)| {
            let pts = o
                .survival
                .curve
                .iter()
                .map(|p| (p.step as f64, p.alive))
                .collect();
            Series::new(o.case.name(), pts).color(i)
        })
        .collect();
    let survival = Figure {
        title: "Walks alive after k steps (Kaplan-Meier)".to_owned(),
        x_label: "steps k".to_owned(),
        y_label: "fraction of walks alive".to_owned(),
        series: curves,
        markers: false,
        equal_axes: false,
        legend: None,
        y_range: Some((0.0, 1.05)),
    };
    let size = passive_size(size);
    let title = format!(
        "Passive walkers on random slopes and friction: {} walks of at most {} steps per case",
        size.walks, size.max_steps
    );
    let stem = out.join("floor_study_passive");
    save_grid(&title, &[spread, survival], 2, (1400, 520), &stem).map_err(|message| {
        WriteError::Figure {
            path: stem.clone(),
            message,
        }
    })
}

/// The passive part's section of the summary (its claims are listed with the study's).
#[must_use]
pub fn summary(outcomes: &[Outcome], size: Size) -> String {
    let size = passive_size(size);
    let mut s = format!(
        "\nPassive walkers (exact Coulomb friction in stance and at the strike): {} seeded walks \
         of at most {} steps per case; the MFPT (steps before a failure) by the constant failure \
         rate with its 95% interval, and by the mesh (from the gait, N = {:?} points, the \
         estimate the finest, its error the last change plus that of {} to {} slope \
         samples):\n",
        size.walks, size.max_steps, MESH_POINTS, MESH_SAMPLES, MESH_CHECK.1
    );
    for o in outcomes {
        let e = &o.survival.mfpt.exponential;
        let kinds = o.survival.failures_text(" ", ", ");
        let _ = writeln!(
            s,
            "  {:<36} MC {:>9} [{:.1}, {}]{}{}; failures: {}",
            o.case.name(),
            e.estimate.map_or("-".to_owned(), |t| format!("{t:.1}")),
            e.lo,
            e.hi.map_or("unbounded".to_owned(), |h| format!("{h:.1}")),
            o.mesh_estimate()
                .map(|(t, err)| format!("; mesh {t:.1} +- {err:.1}"))
                .unwrap_or_default(),
            o.needed_mu0()
                .map(|m| format!("; walks every uniform floor from mu0 = {m:.3}"))
                .unwrap_or_default(),
            if kinds.is_empty() {
                "none".to_owned()
            } else {
                kinds
            }
        );
    }
    s
}
