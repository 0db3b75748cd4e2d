//! The figures of `walker reproduce`, one function per figure of the paper, each returning its
//! panels as `(file stem, figure)`; [`write_figures`] saves them all as PNG and SVG.

use std::path::Path;

use walker::sim::{Sample, StepResult, Walk};
use walker::sweep::SweepPoint;

use super::data::Data;
use super::error::WriteError;
use crate::plot::{Figure, Series, save};

/// One panel of a figure: the file stem (`fig8a`) and what to draw.
pub type Panel = (&'static str, Figure);

/// A figure with lines (and `markers` at the points if asked) on ordinary axes.
#[must_use]
pub fn fig(title: &str, x: &str, y: &str, series: Vec<Series>, markers: bool) -> Figure {
    Figure {
        title: title.to_owned(),
        x_label: x.to_owned(),
        y_label: y.to_owned(),
        series,
        markers,
        equal_axes: false,
        legend: None,
        y_range: None,
    }
}

/// `x`, `th1` and `th2` of a motion against time.
fn motion_fig(title: &str, s: &[Sample]) -> Figure {
    let pick = |i: usize| s.iter().map(|p| (p.time, p.state[i])).collect();
    fig(
        title,
        "time [s]",
        "x [m], th1, th2 [rad]",
        vec![
            Series::new("x", pick(0)),
            Series::new("th1", pick(2)),
            Series::new("th2", pick(3)),
        ],
        false,
    )
}

/// `key` of each step against the step number, one series per walk (`name = value`).
fn per_step(walks: &[(f64, Walk)], name: &str, key: fn(&StepResult) -> f64) -> Vec<Series> {
    walks
        .iter()
        .map(|(v, w)| {
            Series::new(
                format!("{name} = {v}"),
                w.steps
                    .iter()
                    .enumerate()
                    .map(|(k, s)| (k as f64, key(s)))
                    .collect(),
            )
        })
        .collect()
}

/// `key` of the last step against `mu0` (valid points from `mu0_min` on), one series per
/// sweep chain (`name = value`).
fn per_mu0(
    chains: &[(f64, Vec<SweepPoint>)],
    name: &str,
    key: fn(&StepResult) -> Option<f64>,
    mu0_min: f64,
) -> Vec<Series> {
    chains
        .iter()
        .map(|(v, pts)| {
            Series::new(
                format!("{name} = {v}"),
                pts.iter()
                    .filter(|p| p.failure.is_none() && p.value >= mu0_min)
                    .filter_map(|p| p.last.as_ref().and_then(key).map(|y| (p.value, y)))
                    .collect(),
            )
        })
        .collect()
}

/// `key` of the last step against `mu0` for the passive sweeps (points from `mu0_min` on), per
/// chain `phi = value` the periodic gaits and, as a series of its own labelled `not periodic
/// after 100 s`, the walks that reached 100 s without settling (transients). With `magnify`,
/// the axis is that of the periodic gaits and each chain's transients are marked by a row of
/// points above them (one row per chain, 4 % of the range apart), their values off scale.
fn per_mu0_marked(
    chains: &[(f64, Vec<SweepPoint>)],
    key: fn(&StepResult) -> f64,
    mu0_min: f64,
    magnify: bool,
) -> Vec<Series> {
    let shown = |p: &&SweepPoint| p.failure.is_none() && p.value >= mu0_min;
    let (bottom, top) = chains
        .iter()
        .flat_map(|(_, pts)| pts.iter().filter(shown))
        .filter(|p| p.periodic)
        .filter_map(|p| p.last.as_ref().map(key))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| {
            (a.min(y), b.max(y))
        });
    let mut series = Vec::new();
    let mut rows = 0.0;
    for (v, pts) in chains {
        let points = |periodic: bool| -> Vec<(f64, f64)> {
            pts.iter()
                .filter(shown)
                .filter(|p| p.periodic == periodic)
                .filter_map(|p| p.last.as_ref().map(|r| (p.value, key(r))))
                .collect()
        };
        series.push(Series::new(format!("phi = {v}"), points(true)));
        let mut unsettled = points(false);
        if unsettled.is_empty() {
            continue;
        }
        let mut label = format!("phi = {v}: not periodic after 100 s");
        if magnify {
            rows += 1.0;
            let row = top + rows * 0.04 * (top - bottom);
            unsettled.iter_mut().for_each(|p| p.1 = row);
            label.push_str(" (row: V off scale)");
        }
        series.push(Series::new(label, unsettled));
    }
    series
}

/// Stick diagram: the stance spoke (foot to hip) at every few samples, and the hip path.
fn stick_fig(title: &str, s: &[Sample], l: f64) -> Figure {
    let hip = |p: &Sample| {
        (
            p.state[0] + l * p.state[2].sin(),
            p.state[1] + l * p.state[2].cos(),
        )
    };
    let mut series = vec![Series::new("hip", s.iter().map(hip).collect())];
    for p in s.iter().step_by(6) {
        series.push(Series::new("", vec![(p.state[0], p.state[1]), hip(p)]));
    }
    Figure {
        equal_axes: true,
        ..fig(title, "x [m]", "z [m]", series, false)
    }
}

/// The period (a) and speed (b) of each step from three `omega0` (Figs. 4 and 6).
fn steps_by_omega0(
    stems: [&'static str; 2],
    titles: [&str; 2],
    walks: &[(f64, Walk)],
) -> Vec<Panel> {
    vec![
        (
            stems[0],
            fig(
                titles[0],
                "step",
                "T [s]",
                per_step(walks, "omega0", |s| s.period),
                true,
            ),
        ),
        (
            stems[1],
            fig(
                titles[1],
                "step",
                "V [m/s]",
                per_step(walks, "omega0", |s| s.speed),
                true,
            ),
        ),
    ]
}

/// Fig. 3: the motion at `mu0 = 0`.
fn fig3(d: &Data) -> Vec<Panel> {
    let title = "Fig. 3: T_set = 0.3, mu0 = 0, omega0 = 0.8";
    vec![("fig3", motion_fig(title, &d.motion[0].samples))]
}

/// Fig. 4: the steps at `mu0 = 0`.
fn fig4(d: &Data) -> Vec<Panel> {
    steps_by_omega0(
        ["fig4a", "fig4b"],
        ["Fig. 4(a): mu0 = 0", "Fig. 4(b): mu0 = 0"],
        &d.omega_series[0],
    )
}

/// Fig. 5: the motion at `mu0 = 0.4`.
fn fig5(d: &Data) -> Vec<Panel> {
    let title = "Fig. 5: T_set = 0.3, mu0 = 0.4, omega0 = 0.8";
    vec![("fig5", motion_fig(title, &d.motion[1].samples))]
}

/// Fig. 6: the steps at `mu0 = 0.4`.
fn fig6(d: &Data) -> Vec<Panel> {
    steps_by_omega0(
        ["fig6a", "fig6b"],
        ["Fig. 6(a): mu0 = 0.4", "Fig. 6(b): mu0 = 0.4"],
        &d.omega_series[1],
    )
}

/// Fig. 7: the errors of the post-impact velocities from the steady ones.
fn fig7(d: &Data) -> Vec<Panel> {
    let series = ["|qd+ - qd+_eq|", "d xd+", "d th1d+"]
        .iter()
        .enumerate()
        .map(|(i, label)| {
            let points = d
                .convergence
                .iter()
                .enumerate()
                .map(|(k, r)| (k as f64, r[i]))
                .collect();
            Series::new(*label, points)
        })
        .collect();
    let title = "Fig. 7: errors after impact (T_set = 0.3, mu0 = 0.4)";
    vec![("fig7", fig(title, "impact", "error", series, true))]
}

/// Fig. 8: period, step length (with its limit `2 l sin(alpha/2)`), speed and specific
/// resistance against `mu0`.
fn fig8(d: &Data) -> Vec<Panel> {
    let sweep = |key| per_mu0(&d.active_sweep, "T_set", key, 0.0);
    let mut dx = sweep(|s| Some(s.dx));
    let lim = 2.0 * d.table1.l * (d.table1.alpha / 2.0).sin();
    dx.push(Series::new(
        "2 l sin(alpha/2)",
        vec![(0.0, lim), (1.0, lim)],
    ));
    vec![
        (
            "fig8a",
            fig("Fig. 8(a)", "mu0", "T [s]", sweep(|s| Some(s.period)), true),
        ),
        ("fig8b", fig("Fig. 8(b)", "mu0", "dx [m]", dx, true)),
        (
            "fig8c",
            fig(
                "Fig. 8(c)",
                "mu0",
                "V [m/s]",
                sweep(|s| Some(s.speed)),
                true,
            ),
        ),
        (
            "fig8d",
            fig("Fig. 8(d)", "mu0", "SR", sweep(|s| s.sr), true),
        ),
    ]
}

/// Fig. 8(c) at `T_set = 0.3` with the tanh law, with exact Coulomb friction, and with exact
/// Coulomb friction in stance and at the impact.
fn fig8_coulomb(d: &Data) -> Vec<Panel> {
    let mut s = per_mu0(&d.active_sweep[1..2], "tanh, T_set", |s| Some(s.speed), 0.0);
    s.extend(per_mu0(
        &d.coulomb_sweep,
        "Coulomb, T_set",
        |s| Some(s.speed),
        0.0,
    ));
    s.extend(per_mu0(
        &d.coulomb_impact_sweep,
        "Coulomb with impact friction, T_set",
        |s| Some(s.speed),
        0.0,
    ));
    let title = "Fig. 8(c) at T_set = 0.3: tanh law (c = 100), exact Coulomb friction, and friction at the impact";
    vec![("fig8c_coulomb", fig(title, "mu0", "V [m/s]", s, true))]
}

/// Fig. 10: period and speed against `mu0` from (P2b), and the speed continued ((P4b)); walks
/// of 100 s that did not settle to a periodic gait are series of their own.
fn fig10(d: &Data) -> Vec<Panel> {
    let speed = |chains| per_mu0_marked(chains, |s| s.speed, 0.0, false);
    let period = per_mu0_marked(&d.passive_sweep, |s| s.period, 0.0, false);
    let continued = "Fig. 10(b), each mu0 continued from the previous one ((P4b)), 100 s";
    vec![
        (
            "fig10a",
            fig("Fig. 10(a), 100 s per mu0", "mu0", "T [s]", period, true),
        ),
        (
            "fig10b",
            fig(
                "Fig. 10(b), 100 s per mu0",
                "mu0",
                "V [m/s]",
                speed(&d.passive_sweep),
                true,
            ),
        ),
        (
            "fig10b_continued",
            fig(
                continued,
                "mu0",
                "V [m/s]",
                speed(&d.passive_continuation),
                true,
            ),
        ),
    ]
}

/// Fig. 11: stick diagrams at `phi = 0.2`, `mu0` = 0.2 and 0.5.
fn fig11(d: &Data) -> Vec<Panel> {
    let l = d.table1.l;
    vec![
        (
            "fig11a",
            stick_fig("Fig. 11: phi = 0.2, mu0 = 0.2", &d.sticks[0].1.samples, l),
        ),
        (
            "fig11b",
            stick_fig("Fig. 11: phi = 0.2, mu0 = 0.5", &d.sticks[1].1.samples, l),
        ),
    ]
}

/// Fig. 12: the step lengths at `phi = 0.2`.
fn fig12(d: &Data) -> Vec<Panel> {
    let s = per_step(&d.step_lengths, "mu0", |s| s.dx);
    vec![(
        "fig12",
        fig("Fig. 12: phi = 0.2", "step", "dx [m]", s, true),
    )]
}

/// Fig. 13: Fig. 10(b) from `mu0 = 0.2` on, magnified to the periodic gaits.
fn fig13(d: &Data) -> Vec<Panel> {
    let s = per_mu0_marked(&d.passive_sweep, |s| s.speed, 0.2, true);
    let title = "Fig. 13: magnified Fig. 10(b)";
    vec![("fig13", fig(title, "mu0", "V [m/s]", s, true))]
}

/// Fig. 14: the stick diagram of the fall at `phi = 0.10`, `mu0 = 0.19`.
fn fig14(d: &Data) -> Vec<Panel> {
    let title = "Fig. 14: phi = 0.10, mu0 = 0.19";
    let f = stick_fig(title, &d.fall.samples, d.table1.l);
    vec![("fig14", f)]
}

/// Every figure's panels, in the paper's order.
#[must_use]
pub fn panels(d: &Data) -> Vec<Panel> {
    [
        fig3,
        fig4,
        fig5,
        fig6,
        fig7,
        fig8,
        fig8_coulomb,
        fig10,
        fig11,
        fig12,
        fig13,
        fig14,
    ]
    .iter()
    .flat_map(|f| f(d))
    .collect()
}

/// Write every figure as `<stem>.png` and `<stem>.svg` into `out`.
///
/// # Errors
/// A figure could not be drawn or written.
pub fn write_figures(out: &Path, d: &Data) -> Result<(), WriteError> {
    for (name, f) in &panels(d) {
        save_figure(f, &out.join(name))?;
    }
    Ok(())
}

/// Write `f` as `<stem>.png` and `<stem>.svg`.
///
/// # Errors
/// The figure could not be drawn or written.
pub fn save_figure(f: &Figure, stem: &Path) -> Result<(), WriteError> {
    save(f, stem).map_err(|message| WriteError::Figure {
        path: stem.to_owned(),
        message,
    })
}
