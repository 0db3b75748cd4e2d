//! The gallery's figures, per model: the sweeps in the manner of the paper's Figs. 8 and 10
//! (`<model>_sweep`: the steady `T`, `V` and `dx` against `mu0`, one column per pair of laws,
//! one colour per slope), the speed on the model's own slope under the four laws for the README
//! (`<model>`), and the friction the held gait needs along its step (`<model>_friction`).
//!
//! A gait is a line through its points, a filled disc where the foot is held, a ring where it
//! slips. A walk without a gait is a marker in a row below the gaits (one row per slope or law,
//! in its colour), shaped by what became of it: the shapes are the legend's, in black.

use std::path::Path;

use plotters::chart::SeriesLabelPosition;
use walker::sim::StepResult;
use walker::sweep::SweepPoint;

use super::data::ModelRun;
use super::designed::Designed;
use super::entries::Start;
use super::held::Held;
use super::laws::LAWS;
use super::outcome::Outcome;
use crate::plot::{BLACK, Figure, Marker, Series, save_grid};
use crate::reproduce::WriteError;
use crate::reproduce::figures::{fig, save_figure};

/// A descriptor of the steady step: its axis label and its value.
type Descriptor = (&'static str, fn(&StepResult) -> f64);

/// The descriptors of the sweep figure's rows.
const DESCRIPTORS: [Descriptor; 3] = [
    ("T [s]", |s| s.period),
    ("V [m/s]", |s| s.speed),
    ("dx [m]", |s| s.dx),
];

/// The rows below the gaits are this far apart, as a share of the gaits' range.
const ROW: f64 = 0.08;

/// Room above the gaits for a panel's legend, as a share of their range.
const LEGEND_ROOM: f64 = 0.9;

/// The y axis of panels whose gaits span `(bottom, top)` with `rows` rows below them and
/// `room` (a share of the span) above.
fn y_axis((bottom, top): (f64, f64), rows: usize, room: f64) -> (f64, f64) {
    let span = (top - bottom).max(1e-9 * top.abs().max(1.0));
    (
        bottom - (rows as f64 + 0.7) * ROW * span,
        top + (0.05 + room) * span,
    )
}

/// The marker shapes of the outcomes of one model's figures: fixed for the walks that did not
/// fail, the failures in the order of [`failure_names`] from a pool.
struct Shapes {
    failures: Vec<String>,
    pool: Vec<Marker>,
}

/// Shapes for the failures, in turn.
const FAILURE_SHAPES: [Marker; 3] = [Marker::Cross, Marker::Square, Marker::Diamond];

/// The fixed shapes of the walks that did not fail and did not hold their foot, lent to the
/// failures of a model whose figures have none of those walks (so that every failure has a
/// shape of its own).
const SPARE_SHAPES: [(Outcome, Marker); 3] = [
    (Outcome::NotPeriodic, Marker::Triangle),
    (Outcome::SlidesAway, Marker::Plus),
    (Outcome::Slipping, Marker::Ring),
];

impl Shapes {
    /// The shapes of a model whose figures show the outcomes `present`.
    fn new(run: &ModelRun, present: &[Outcome]) -> Shapes {
        let failures = failure_names(run, present);
        let mut pool = FAILURE_SHAPES.to_vec();
        if failures.len() > pool.len() {
            pool.extend(
                SPARE_SHAPES
                    .iter()
                    .filter(|(o, _)| !present.contains(o))
                    .map(|(_, m)| *m),
            );
        }
        Shapes { failures, pool }
    }

    fn of(&self, o: &Outcome) -> Marker {
        match o {
            Outcome::Held => Marker::Circle,
            Outcome::Slipping => Marker::Ring,
            Outcome::NotPeriodic => Marker::Triangle,
            Outcome::SlidesAway => Marker::Plus,
            Outcome::Failed(name) => {
                let k = self.failures.iter().position(|f| f == name).unwrap_or(0);
                self.pool[k % self.pool.len()]
            }
        }
    }

    /// Legend entries (no points, black) for every outcome in `present`.
    fn legend(&self, present: &[Outcome]) -> Vec<Series> {
        present
            .iter()
            .map(|o| {
                let label = match o {
                    Outcome::NotPeriodic => "not periodic (row)".to_owned(),
                    Outcome::SlidesAway => "slides away (row)".to_owned(),
                    Outcome::Failed(n) => format!("{n} (row)"),
                    o => o.label(),
                };
                Series::new(label, Vec::new())
                    .color(BLACK)
                    .markers(self.of(o))
            })
            .collect()
    }
}

/// Every outcome of `run`'s sweeps, in [`Outcome`]'s order (the model's falls first among the
/// failures).
fn outcomes(run: &ModelRun) -> Vec<Outcome> {
    let mut all: Vec<Outcome> = run
        .sweeps
        .iter()
        .flat_map(|s| {
            s.chains
                .iter()
                .enumerate()
                .flat_map(move |(i, pts)| pts.iter().map(move |p| run.outcome(i, p)))
        })
        .collect();
    all.sort();
    all.dedup();
    all
}

/// The failure names of `run`, the model's falls first.
fn failure_names(run: &ModelRun, present: &[Outcome]) -> Vec<String> {
    let spec = run
        .entry
        .setup()
        .map(|s| {
            s.walker
                .spec()
                .falls()
                .map(str::to_owned)
                .collect::<Vec<_>>()
        })
        .unwrap_or_default();
    let mut names: Vec<String> = present
        .iter()
        .filter_map(|o| match o {
            Outcome::Failed(n) => Some(n.clone()),
            _ => None,
        })
        .collect();
    names.sort_by_key(|n| (!spec.contains(n), n.clone()));
    names
}

/// One curve of a panel: its points on slope `slope` and its palette colour.
struct Curve<'a> {
    slope: usize,
    color: usize,
    label: String,
    points: &'a [SweepPoint],
}

/// A panel's gaits span at least this share of their value: a gait that does not change with
/// `mu0` (a held gait: its stuck stance and sticking impact do not see it) is a level line in
/// the middle of that range, not a panel of rounding.
const MIN_SPAN: f64 = 0.01;

/// The range of `key` over the gaits of `curves` (at least [`MIN_SPAN`] of its value wide),
/// `(0, 1)` without any.
fn gait_range(run: &ModelRun, curves: &[Curve<'_>], key: fn(&StepResult) -> f64) -> (f64, f64) {
    let (lo, hi) = curves
        .iter()
        .flat_map(|c| {
            c.points
                .iter()
                .filter(|p| run.outcome(c.slope, p).is_gait())
                .filter_map(|p| p.last.as_ref().map(key))
        })
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| {
            (a.min(y), b.max(y))
        });
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let (mid, half) = (0.5 * (lo + hi), 0.5 * MIN_SPAN * hi.abs().max(lo.abs()));
    if hi - lo < 2.0 * half {
        (mid - half, mid + half)
    } else {
        (lo, hi)
    }
}

/// The series of one panel: each curve's gaits as a line with held and slipping markers, and
/// its other walks in a row below the range `(bottom, top)`.
fn panel_series(
    run: &ModelRun,
    curves: &[Curve<'_>],
    key: fn(&StepResult) -> f64,
    (bottom, top): (f64, f64),
    shapes: &Shapes,
    labels: bool,
) -> Vec<Series> {
    let span = (top - bottom).max(1e-9 * top.abs().max(1.0));
    let mut out = Vec::new();
    for (k, c) in curves.iter().enumerate() {
        let of = |o: &dyn Fn(&Outcome) -> bool| -> Vec<(f64, f64)> {
            c.points
                .iter()
                .filter(|p| o(&run.outcome(c.slope, p)))
                .filter_map(|p| p.last.as_ref().map(|s| (p.value, key(s))))
                .collect()
        };
        let label = if labels {
            c.label.clone()
        } else {
            String::new()
        };
        out.push(Series::new(label, of(&Outcome::is_gait)).color(c.color));
        out.push(
            Series::new("", of(&|o| *o == Outcome::Held))
                .color(c.color)
                .markers(Marker::Circle),
        );
        out.push(
            Series::new("", of(&|o| *o == Outcome::Slipping))
                .color(c.color)
                .markers(Marker::Ring),
        );
        let row = bottom - (k as f64 + 1.0) * ROW * span;
        let mut rest: Vec<(Outcome, f64)> = c
            .points
            .iter()
            .map(|p| (run.outcome(c.slope, p), p.value))
            .filter(|(o, _)| !o.is_gait())
            .collect();
        rest.sort_by(|a, b| a.0.cmp(&b.0));
        for group in rest.chunk_by(|a, b| a.0 == b.0) {
            let pts = group.iter().map(|(_, x)| (*x, row)).collect();
            out.push(
                Series::new("", pts)
                    .color(c.color)
                    .markers(shapes.of(&group[0].0)),
            );
        }
    }
    out
}

/// The sweep figure: rows `T`, `V`, `dx`; one column per pair of laws; one curve per slope.
fn sweep_figure(run: &ModelRun, shapes: &Shapes, present: &[Outcome]) -> Vec<Figure> {
    let mut panels = Vec::new();
    for (r, (name, key)) in DESCRIPTORS.iter().enumerate() {
        let all: Vec<Curve<'_>> = run
            .sweeps
            .iter()
            .flat_map(|s| {
                s.chains.iter().enumerate().map(|(i, pts)| Curve {
                    slope: i,
                    color: i,
                    label: run.slope_label(i),
                    points: pts,
                })
            })
            .collect();
        let range = gait_range(run, &all, *key);
        for (k, s) in run.sweeps.iter().enumerate() {
            let curves: Vec<Curve<'_>> = s
                .chains
                .iter()
                .enumerate()
                .map(|(i, pts)| Curve {
                    slope: i,
                    color: i,
                    label: run.slope_label(i),
                    points: pts,
                })
                .collect();
            let first = r == 0 && k == 0;
            let mut series = panel_series(run, &curves, *key, range, shapes, first);
            if first {
                series.extend(shapes.legend(present));
            }
            let mut f = fig(&s.laws.label(), "mu0", name, series, false);
            f.legend = Some(SeriesLabelPosition::UpperRight);
            let room = if r == 0 { LEGEND_ROOM } else { 0.0 };
            f.y_range = Some(y_axis(range, curves.len(), room));
            panels.push(f);
        }
    }
    panels
}

/// Where the walks of `run` start, for a title (`its held gait`).
fn from(run: &ModelRun) -> &'static str {
    match run.entry.start {
        Start::Held => "its held gait",
        Start::Own => "its own start",
    }
}

/// The README's figure: `V` against `mu0` on the model's own slope, one curve per pair of laws.
fn overview(run: &ModelRun, shapes: &Shapes, present: &[Outcome]) -> Figure {
    let i = run.nominal;
    let curves: Vec<Curve<'_>> = run
        .sweeps
        .iter()
        .enumerate()
        .map(|(k, s)| Curve {
            slope: i,
            color: k,
            label: s.laws.label(),
            points: &s.chains[i],
        })
        .collect();
    let key = |s: &StepResult| s.speed;
    let range = gait_range(run, &curves, key);
    let mut series = panel_series(run, &curves, key, range, shapes, true);
    series.extend(shapes.legend(present));
    let floor = if run.slopes[i].phi.is_nan() {
        "a level floor".to_owned()
    } else {
        run.slope_label(i)
    };
    let title = format!(
        "The {} on {floor}: speed against mu0, from {}",
        run.entry.title,
        from(run)
    );
    let mut f = fig(&title, "mu0", "V [m/s]", series, false);
    f.legend = Some(SeriesLabelPosition::UpperLeft);
    f.y_range = Some(y_axis(range, curves.len(), 1.6));
    f
}

/// Held gaits' friction figure: each gait `(label, held, colour)`, the ratio
/// `lambda_t / lambda_n` along its step as a line and its heel strike's `Lambda_t / Lambda_n` as
/// a diamond at `t = T`.
fn friction_figure<'h>(
    title: &str,
    gaits: impl IntoIterator<Item = (String, &'h Held, usize)>,
) -> Figure {
    let mut series = Vec::new();
    for (label, h, i) in gaits {
        series.push(Series::new(label, h.profile.clone()).color(i));
        series.push(
            Series::new("", vec![(1.0, h.impulse[0] / h.impulse[1])])
                .color(i)
                .markers(Marker::Diamond),
        );
    }
    series.push(
        Series::new("Lambda_t / Lambda_n at the heel strike", Vec::new())
            .color(BLACK)
            .markers(Marker::Diamond),
    );
    let mut f = fig(
        title,
        "t / T",
        "lambda_t / lambda_n (+: pushes the foot forward)",
        series,
        false,
    );
    f.legend = Some(SeriesLabelPosition::UpperLeft);
    f
}

/// The friction the held gait needs: `lambda_t / lambda_n` along the step on each slope, and
/// the heel strike's `Lambda_t / Lambda_n` at `t = T`.
fn friction(run: &ModelRun) -> Figure {
    let title = format!(
        "The {}'s held gait: friction it needs along a step",
        run.entry.title
    );
    friction_figure(
        &title,
        run.slopes
            .iter()
            .enumerate()
            .filter_map(|(i, s)| s.held.as_ref().ok().map(|h| (run.slope_label(i), h, i))),
    )
}

/// The designed gait beside the hand-made one (`<model>_designed`): the friction each needs
/// along its step on the model's own slope, and each heel strike's impulse ratio at `t = T`.
fn designed(run: &ModelRun, d: &Designed) -> Option<Figure> {
    let hand = run.slopes.get(run.nominal)?.held.as_ref().ok()?;
    let title = format!(
        "The {}: the friction a designed gait needs beside the hand-made one's",
        run.entry.title
    );
    let designed = format!(
        "designed gait ({}), needs {:.4}",
        d.parameters(),
        d.held.needs()
    );
    Some(friction_figure(
        &title,
        [
            (
                format!("hand-made gait, needs {:.4}", hand.needs()),
                hand,
                0,
            ),
            (designed, &d.held, 1),
        ],
    ))
}

/// Write the three figures of `run` into `out` (PNG and SVG), and the designed gait's where
/// the run has one.
///
/// # Errors
/// A figure could not be drawn or written.
pub fn write_figures(out: &Path, run: &ModelRun) -> Result<(), WriteError> {
    let present = outcomes(run);
    let shapes = Shapes::new(run, &present);
    let m = run.entry.model;
    let stem = out.join(format!("{m}_sweep"));
    let title = format!(
        "The {}: steady T, V, dx against mu0, each mu0 from {} ({})",
        run.entry.title,
        from(run),
        run.entry.path()
    );
    save_grid(
        &title,
        &sweep_figure(run, &shapes, &present),
        LAWS.len(),
        (1800, 1150),
        &stem,
    )
    .map_err(|message| WriteError::Figure {
        path: stem.clone(),
        message,
    })?;
    save_figure(&overview(run, &shapes, &present), &out.join(m))?;
    save_figure(&friction(run), &out.join(format!("{m}_friction")))?;
    if let Some(f) = run
        .designed
        .as_ref()
        .and_then(|d| d.as_ref().ok())
        .and_then(|d| designed(run, d))
    {
        save_figure(&f, &out.join(format!("{m}_designed")))?;
    }
    Ok(())
}
