//! `walker reproduce`: the data of the paper's Figs. 3-8 and 10-14 as CSV files and a summary
//! of the paper's claims with the values found.

use std::fmt::Write as _;
use std::fs;
use std::io;
use std::path::Path;

use crate::plot::{Figure, Series, save};
use crate::progress::Progress;
use walker::model::{Model, Physical, Runtime};
use walker::sim::{Sample, SimConfig, StepResult, Walk, WalkLimits, walk};
use walker::sweep::{SweepPoint, mu0_grid, sweep_chains};

fn runtime(mu0: f64, t_set: f64) -> Runtime {
    Runtime {
        mu0,
        t_set,
        ..Runtime::default()
    }
}

fn active(mu0: f64, t_set: f64) -> Model {
    Model::active_level(runtime(mu0, t_set))
}

fn passive(mu0: f64, phi: f64) -> Model {
    Model::passive_slope(Runtime {
        mu0,
        phi,
        ..Runtime::default()
    })
}

/// [`sweep_chains`] with a progress bar named `label` on a terminal: `(chain value, points)` for
/// each of `chains`.
#[allow(clippy::too_many_arguments)]
fn sweep_with_bar(
    label: &str,
    chains: &[f64],
    make: impl Fn(f64, f64) -> Model + Sync,
    cfg: &SimConfig,
    grid: &[f64],
    initial: impl Fn(f64) -> [f64; 8] + Sync,
    limits: &WalkLimits,
    restart: bool,
) -> Vec<(f64, Vec<SweepPoint>)> {
    let bar = Progress::new(label, chains.len() * grid.len());
    let points = sweep_chains(chains, make, cfg, grid, initial, limits, restart, &|| {
        bar.tick()
    });
    bar.finish();
    chains.iter().copied().zip(points).collect()
}

fn limits(max_steps: usize, record: bool) -> WalkLimits {
    WalkLimits {
        max_steps,
        duration: f64::INFINITY,
        record,
        periodic: None,
    }
}

fn fmt(v: Option<f64>) -> String {
    v.filter(|x| x.is_finite())
        .map_or_else(String::new, |x| format!("{x:.12e}"))
}

fn samples_csv(path: &Path, s: &[Sample]) -> io::Result<()> {
    let mut out = String::from("time,step,x,z,th1,th2,xd,zd,th1d,th2d,lambda,u\n");
    for p in s {
        let _ = write!(out, "{:.9e},{}", p.time, p.step);
        for v in p.state {
            let _ = write!(out, ",{v:.9e}");
        }
        let _ = writeln!(out, ",{:.9e},{:.9e}", p.lambda, p.u);
    }
    fs::write(path, out)
}

fn steps_header() -> &'static str {
    "T,dx,V,p,SR,x_plus,z_plus,th1_plus,th2_plus,xd_plus,zd_plus,th1d_plus,th2d_plus"
}

fn step_row(s: &StepResult) -> String {
    let mut r = format!(
        "{},{},{},{},{}",
        fmt(Some(s.period)),
        fmt(Some(s.dx)),
        fmt(Some(s.speed)),
        fmt(s.p),
        fmt(s.sr)
    );
    for v in s.q_plus.iter().chain(&s.qd_plus) {
        let _ = write!(r, ",{}", fmt(Some(*v)));
    }
    r
}

fn series_csv(path: &Path, label: &str, walks: &[(f64, Walk)]) -> io::Result<()> {
    let mut out = format!("{label},step,{}\n", steps_header());
    for (v, w) in walks {
        for (k, s) in w.steps.iter().enumerate() {
            let _ = writeln!(out, "{v},{k},{}", step_row(s));
        }
    }
    fs::write(path, out)
}

fn sweep_csv(path: &Path, label: &str, chains: &[(f64, Vec<SweepPoint>)]) -> io::Result<()> {
    let mut out = format!("{label},mu0,steps,status,{}\n", steps_header());
    for (v, pts) in chains {
        for p in pts {
            let status = p.failure.as_ref().map_or("ok", |f| f.name());
            let row = p.last.as_ref().map_or_else(|| ",".repeat(12), step_row);
            let _ = writeln!(out, "{v},{:.4},{},{status},{row}", p.mu0, p.steps);
        }
    }
    fs::write(path, out)
}

/// The collected data of every figure.
pub struct Data {
    /// Fig. 3 (`mu0 = 0`) and Fig. 5 (`mu0 = 0.4`) motions, `T_set = 0.3`, `omega0 = 0.8`.
    pub motion: [Walk; 2],
    /// Figs. 4 and 6: steps for three `omega0` at `mu0 = 0` and `mu0 = 0.4`.
    pub omega_series: [Vec<(f64, Walk)>; 2],
    /// Fig. 7: errors of the post-impact velocities from the steady ones.
    pub convergence: Vec<[f64; 3]>,
    /// Fig. 8: sweeps over `mu0` for `T_set` = 0.2, 0.3, 0.4.
    pub active_sweep: Vec<(f64, Vec<SweepPoint>)>,
    /// Figs. 10 and 13: sweeps over `mu0` for `phi` = 0.10, 0.15, 0.20, each `mu0` from (P2b)
    /// (the paper's (P5b) "Repeat from (P2b)", `walker sweep --restart`).
    pub passive_sweep: Vec<(f64, Vec<SweepPoint>)>,
    /// Fig. 10 read the other way: each `mu0` from the previous steady state ((P4b)).
    pub passive_continuation: Vec<(f64, Vec<SweepPoint>)>,
    /// The Fig. 8 sweep at `T_set = 0.3` with exact Coulomb friction (Eq. 25, stick-slip).
    pub coulomb_sweep: Vec<(f64, Vec<SweepPoint>)>,
    /// Fig. 11: motions at `phi = 0.2`, `mu0` = 0.2 and 0.5.
    pub sticks: Vec<(f64, Walk)>,
    /// Fig. 12: step lengths at `phi = 0.2` for four `mu0`.
    pub step_lengths: Vec<(f64, Walk)>,
    /// Fig. 14: the motion at `phi = 0.10`, `mu0 = 0.19`.
    pub fall: Walk,
}

/// Omega0 values of Figs. 4 and 6.
pub const OMEGAS: [f64; 3] = [0.6, 0.7, 0.8];
/// `T_set` values of Fig. 8.
pub const T_SETS: [f64; 3] = [0.2, 0.3, 0.4];
/// Slope angles of Fig. 10.
pub const PHIS: [f64; 3] = [0.10, 0.15, 0.20];

/// Compute every figure's data.
pub fn collect() -> Data {
    let cfg = SimConfig::default();
    let motion = [0.0, 0.4].map(|mu0| {
        let m = active(mu0, 0.3);
        walk(&m, &cfg, m.initial_state(0.8), &limits(6, true))
    });
    let omega_series = [0.0, 0.4].map(|mu0| {
        OMEGAS
            .iter()
            .map(|&w0| {
                let m = active(mu0, 0.3);
                (w0, walk(&m, &cfg, m.initial_state(w0), &limits(30, false)))
            })
            .collect()
    });
    // Fig. 7: the steady state, then a start 0.1 rad/s above its angular velocity.
    let m = active(0.4, 0.3);
    let steady = walk(&m, &cfg, m.initial_state(0.8), &limits(400, false));
    let mut convergence = Vec::new();
    if let Some(eq) = steady.steps.last() {
        let w0 = eq.qd_plus[2] + 0.1;
        let w = walk(&m, &cfg, m.initial_state(w0), &limits(30, false));
        let mut qds = vec![[0.0, 0.0, w0, w0]];
        qds.extend(w.steps.iter().map(|s| s.qd_plus));
        for qd in qds {
            let d: Vec<f64> = qd.iter().zip(&eq.qd_plus).map(|(a, b)| a - b).collect();
            let norm = d.iter().map(|v| v * v).sum::<f64>().sqrt();
            convergence.push([norm, d[0], d[2]]);
        }
    }
    let grid = mu0_grid(0.0, 1.0, 0.01);
    let long = WalkLimits {
        max_steps: 1000,
        duration: 100.0,
        record: false,
        periodic: None,
    };
    let active_sweep = sweep_with_bar(
        "Fig. 8 sweep",
        &T_SETS,
        |ts, mu0| active(mu0, ts),
        &cfg,
        &grid,
        |ts| active(0.0, ts).initial_state(0.8),
        &long,
        false,
    );
    let pgrid = mu0_grid(0.0, 0.7, 0.01);
    let passive_chains = |label, restart| {
        sweep_with_bar(
            label,
            &PHIS,
            |phi, mu0| passive(mu0, phi),
            &cfg,
            &pgrid,
            |phi| passive(0.0, phi).initial_state(0.5),
            &limits(20, false),
            restart,
        )
    };
    let passive_sweep = passive_chains("Fig. 10 sweep", true);
    let passive_continuation = passive_chains("Fig. 10 sweep, continued", false);
    let coulomb_sweep = sweep_with_bar(
        "Fig. 8 sweep, Coulomb",
        &[0.3],
        |ts, mu0| Model::coulomb_level(Physical::TABLE1, runtime(mu0, ts)),
        &cfg,
        &grid,
        |ts| active(0.0, ts).initial_state(0.8),
        &long,
        false,
    );
    let sticks = [0.2, 0.5]
        .iter()
        .map(|&mu0| {
            let m = passive(mu0, 0.2);
            (mu0, walk(&m, &cfg, m.initial_state(0.5), &limits(6, true)))
        })
        .collect();
    let step_lengths = [0.2, 0.3, 0.4, 0.5]
        .iter()
        .map(|&mu0| {
            let m = passive(mu0, 0.2);
            (
                mu0,
                walk(&m, &cfg, m.initial_state(0.5), &limits(20, false)),
            )
        })
        .collect();
    let m = passive(0.19, 0.10);
    let fall = walk(&m, &cfg, m.initial_state(0.5), &limits(5, true));
    Data {
        motion,
        omega_series,
        convergence,
        active_sweep,
        passive_sweep,
        passive_continuation,
        coulomb_sweep,
        sticks,
        step_lengths,
        fall,
    }
}

fn write_csvs(out: &Path, d: &Data) -> io::Result<()> {
    samples_csv(&out.join("fig3_motion_mu0_0.csv"), &d.motion[0].samples)?;
    samples_csv(&out.join("fig5_motion_mu0_0.4.csv"), &d.motion[1].samples)?;
    series_csv(
        &out.join("fig4_steps_mu0_0.csv"),
        "omega0",
        &d.omega_series[0],
    )?;
    series_csv(
        &out.join("fig6_steps_mu0_0.4.csv"),
        "omega0",
        &d.omega_series[1],
    )?;
    let mut c = String::from("impact,norm_dqd,d_xd,d_th1d\n");
    for (k, r) in d.convergence.iter().enumerate() {
        let _ = writeln!(c, "{k},{:.12e},{:.12e},{:.12e}", r[0], r[1], r[2]);
    }
    fs::write(out.join("fig7_convergence.csv"), c)?;
    sweep_csv(&out.join("fig8_sweep.csv"), "T_set", &d.active_sweep)?;
    sweep_csv(&out.join("fig10_sweep.csv"), "phi", &d.passive_sweep)?;
    sweep_csv(
        &out.join("fig10_sweep_continued.csv"),
        "phi",
        &d.passive_continuation,
    )?;
    sweep_csv(
        &out.join("fig8_sweep_coulomb.csv"),
        "T_set",
        &d.coulomb_sweep,
    )?;
    for (mu0, w) in &d.sticks {
        samples_csv(&out.join(format!("fig11_stick_mu0_{mu0}.csv")), &w.samples)?;
    }
    series_csv(&out.join("fig12_step_length.csv"), "mu0", &d.step_lengths)?;
    samples_csv(&out.join("fig14_fall.csv"), &d.fall.samples)?;
    Ok(())
}

fn argbest(pts: &[SweepPoint], key: impl Fn(&StepResult) -> Option<f64>, max: bool) -> String {
    let mut best: Option<(f64, f64)> = None;
    for p in pts.iter().filter(|p| p.failure.is_none() && p.mu0 > 0.0) {
        if let Some(v) = p.last.as_ref().and_then(&key) {
            let better = best.is_none_or(|(_, b)| if max { v > b } else { v < b });
            if better {
                best = Some((p.mu0, v));
            }
        }
    }
    best.map_or_else(
        || "none".to_owned(),
        |(m, v)| format!("mu0 = {m:.2} ({v:.6})"),
    )
}

/// The failures of a sweep as `mu0:name` pairs, or `none`.
fn failures(pts: &[SweepPoint]) -> String {
    let fails: Vec<String> = pts
        .iter()
        .filter_map(|p| {
            p.failure
                .as_ref()
                .map(|f| format!("{:.2}:{}", p.mu0, f.name()))
        })
        .collect();
    if fails.is_empty() {
        "none".to_owned()
    } else {
        fails.join(" ")
    }
}

/// The summary table of the paper's claims and the values found.
pub fn summary(d: &Data) -> String {
    let mut s = String::from("Claims of the paper and values found\n");
    let steady_v = |w: &Walk| w.steps.last().map_or(f64::NAN, |s| s.speed);
    let v0: Vec<String> = d.omega_series[0]
        .iter()
        .map(|(w0, w)| format!("omega0={w0}: V={:.6}", steady_v(w)))
        .collect();
    let v4: Vec<String> = d.omega_series[1]
        .iter()
        .map(|(w0, w)| format!("omega0={w0}: V={:.6}", steady_v(w)))
        .collect();
    let _ = writeln!(
        s,
        "- mu0 = 0: limit cycles not unique (Fig. 4): {}",
        v0.join(", ")
    );
    let _ = writeln!(
        s,
        "- mu0 = 0.4: unique limit cycle (Fig. 6), after 30 steps: {}",
        v4.join(", ")
    );
    for (ts, pts) in &d.active_sweep {
        let _ = writeln!(s, "- T_set = {ts}: failures at mu0 {}", failures(pts));
        let _ = writeln!(
            s,
            "  max V at {}; min SR at {}",
            argbest(pts, |r| Some(r.speed), true),
            argbest(pts, |r| r.sr, false)
        );
        if let Some(last) = pts.last().and_then(|p| p.last.as_ref()) {
            let _ = writeln!(
                s,
                "  dx at mu0 = {:.2}: {:.6} (limit 2 l sin(alpha/2) = {:.6})",
                pts.last().map_or(f64::NAN, |p| p.mu0),
                last.dx,
                2.0 * (std::f64::consts::PI / 12.0).sin()
            );
        }
    }
    for (phi, pts) in &d.passive_sweep {
        let _ = writeln!(s, "- phi = {phi}: failures at mu0 {}", failures(pts));
    }
    for (phi, pts) in &d.passive_continuation {
        let _ = writeln!(
            s,
            "- phi = {phi}, each mu0 continued from the previous one ((P4b)): failures at mu0 {}",
            failures(pts)
        );
    }
    if let (Some((_, tanh)), Some((_, exact))) = (
        d.active_sweep.iter().find(|(ts, _)| *ts == 0.3),
        d.coulomb_sweep.first(),
    ) {
        let dv = tanh
            .iter()
            .zip(exact)
            .filter(|(a, b)| a.mu0 > 0.0 && a.failure.is_none() && b.failure.is_none())
            .filter_map(|(a, b)| Some((a.last?.speed, b.last?.speed)))
            .map(|(a, b)| ((a - b) / b).abs())
            .fold(0.0, f64::max);
        let fails = exact.iter().filter(|p| p.failure.is_some()).count();
        let _ = writeln!(
            s,
            "- exact Coulomb friction (Eq. 25, stick-slip), T_set = 0.3: max V at {}; min SR at {}; \
             V differs from the tanh law (c = 100) by at most {:.2} % for mu0 in (0, 1]; {fails} failed points",
            argbest(exact, |r| Some(r.speed), true),
            argbest(exact, |r| r.sr, false),
            100.0 * dv
        );
    }
    let _ = writeln!(
        s,
        "- phi = 0.10, mu0 = 0.19 (Fig. 14): {}",
        d.fall.failure.as_ref().map_or_else(
            || "walks".to_owned(),
            |f| format!("{} at step {}", f.name(), f.step)
        )
    );
    s
}

fn fig(title: &str, x: &str, y: &str, series: Vec<Series>, markers: bool) -> Figure {
    Figure {
        title: title.to_owned(),
        x_label: x.to_owned(),
        y_label: y.to_owned(),
        series,
        markers,
        equal_axes: false,
    }
}

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
                    .filter(|p| p.failure.is_none() && p.mu0 >= mu0_min)
                    .filter_map(|p| p.last.as_ref().and_then(key).map(|y| (p.mu0, y)))
                    .collect(),
            )
        })
        .collect()
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

fn write_figures(out: &Path, d: &Data) -> Result<(), String> {
    let t = |s: &StepResult| s.period;
    let v = |s: &StepResult| s.speed;
    let figs: Vec<(&str, Figure)> = vec![
        (
            "fig3",
            motion_fig(
                "Fig. 3: T_set = 0.3, mu0 = 0, omega0 = 0.8",
                &d.motion[0].samples,
            ),
        ),
        (
            "fig5",
            motion_fig(
                "Fig. 5: T_set = 0.3, mu0 = 0.4, omega0 = 0.8",
                &d.motion[1].samples,
            ),
        ),
        (
            "fig4a",
            fig(
                "Fig. 4(a): mu0 = 0",
                "step",
                "T [s]",
                per_step(&d.omega_series[0], "omega0", t),
                true,
            ),
        ),
        (
            "fig4b",
            fig(
                "Fig. 4(b): mu0 = 0",
                "step",
                "V [m/s]",
                per_step(&d.omega_series[0], "omega0", v),
                true,
            ),
        ),
        (
            "fig6a",
            fig(
                "Fig. 6(a): mu0 = 0.4",
                "step",
                "T [s]",
                per_step(&d.omega_series[1], "omega0", t),
                true,
            ),
        ),
        (
            "fig6b",
            fig(
                "Fig. 6(b): mu0 = 0.4",
                "step",
                "V [m/s]",
                per_step(&d.omega_series[1], "omega0", v),
                true,
            ),
        ),
        (
            "fig7",
            fig(
                "Fig. 7: errors after impact (T_set = 0.3, mu0 = 0.4)",
                "impact",
                "error",
                (0..3)
                    .map(|i| {
                        Series::new(
                            ["|qd+ - qd+_eq|", "d xd+", "d th1d+"][i],
                            d.convergence
                                .iter()
                                .enumerate()
                                .map(|(k, r)| (k as f64, r[i]))
                                .collect(),
                        )
                    })
                    .collect(),
                true,
            ),
        ),
        (
            "fig8a",
            fig(
                "Fig. 8(a)",
                "mu0",
                "T [s]",
                per_mu0(&d.active_sweep, "T_set", |s| Some(s.period), 0.0),
                true,
            ),
        ),
        (
            "fig8b",
            fig(
                "Fig. 8(b)",
                "mu0",
                "dx [m]",
                {
                    let mut s = per_mu0(&d.active_sweep, "T_set", |s| Some(s.dx), 0.0);
                    let lim = 2.0 * Physical::TABLE1.l * (Physical::TABLE1.alpha / 2.0).sin();
                    s.push(Series::new(
                        "2 l sin(alpha/2)",
                        vec![(0.0, lim), (1.0, lim)],
                    ));
                    s
                },
                true,
            ),
        ),
        (
            "fig8c",
            fig(
                "Fig. 8(c)",
                "mu0",
                "V [m/s]",
                per_mu0(&d.active_sweep, "T_set", |s| Some(s.speed), 0.0),
                true,
            ),
        ),
        (
            "fig8d",
            fig(
                "Fig. 8(d)",
                "mu0",
                "SR",
                per_mu0(&d.active_sweep, "T_set", |s| s.sr, 0.0),
                true,
            ),
        ),
        (
            "fig10a",
            fig(
                "Fig. 10(a)",
                "mu0",
                "T [s]",
                per_mu0(&d.passive_sweep, "phi", |s| Some(s.period), 0.0),
                true,
            ),
        ),
        (
            "fig10b",
            fig(
                "Fig. 10(b)",
                "mu0",
                "V [m/s]",
                per_mu0(&d.passive_sweep, "phi", |s| Some(s.speed), 0.0),
                true,
            ),
        ),
        (
            "fig10b_continued",
            fig(
                "Fig. 10(b), each mu0 continued from the previous one ((P4b))",
                "mu0",
                "V [m/s]",
                per_mu0(&d.passive_continuation, "phi", |s| Some(s.speed), 0.0),
                true,
            ),
        ),
        (
            "fig8c_coulomb",
            fig(
                "Fig. 8(c) at T_set = 0.3: tanh law (c = 100) and exact Coulomb friction",
                "mu0",
                "V [m/s]",
                {
                    let mut s =
                        per_mu0(&d.active_sweep[1..2], "tanh, T_set", |s| Some(s.speed), 0.0);
                    s.extend(per_mu0(
                        &d.coulomb_sweep,
                        "Coulomb, T_set",
                        |s| Some(s.speed),
                        0.0,
                    ));
                    s
                },
                true,
            ),
        ),
        (
            "fig13",
            fig(
                "Fig. 13: magnified Fig. 10(b)",
                "mu0",
                "V [m/s]",
                per_mu0(&d.passive_sweep, "phi", |s| Some(s.speed), 0.2),
                true,
            ),
        ),
        (
            "fig11a",
            stick_fig(
                "Fig. 11: phi = 0.2, mu0 = 0.2",
                &d.sticks[0].1.samples,
                Physical::TABLE1.l,
            ),
        ),
        (
            "fig11b",
            stick_fig(
                "Fig. 11: phi = 0.2, mu0 = 0.5",
                &d.sticks[1].1.samples,
                Physical::TABLE1.l,
            ),
        ),
        (
            "fig12",
            fig(
                "Fig. 12: phi = 0.2",
                "step",
                "dx [m]",
                per_step(&d.step_lengths, "mu0", |s| s.dx),
                true,
            ),
        ),
        (
            "fig14",
            stick_fig(
                "Fig. 14: phi = 0.10, mu0 = 0.19",
                &d.fall.samples,
                Physical::TABLE1.l,
            ),
        ),
    ];
    for (name, f) in &figs {
        save(f, &out.join(name))?;
    }
    Ok(())
}

/// Run everything and write the CSV files, the figures (PNG and SVG) and `summary.txt` into
/// `out`; returns the summary.
pub fn run(out: &Path) -> io::Result<String> {
    fs::create_dir_all(out)?;
    let d = collect();
    write_csvs(out, &d)?;
    write_figures(out, &d).map_err(io::Error::other)?;
    let mut s = summary(&d);
    s.push_str(&stability(out)?);
    fs::write(out.join("summary.txt"), &s)?;
    Ok(s)
}

/// Where the gaits are stable: fixed points of the Poincare map and their largest Floquet
/// multiplier along `mu0` for the paper's three `T_set` and three `phi` (continuation from
/// cycle to cycle, [`walker::poincare::continuation`]), written to `stability.csv`; returns the
/// summary lines.
fn stability(out: &Path) -> io::Result<String> {
    use crate::report::{continuation_csv, stability_summary};
    use rayon::prelude::*;
    use walker::poincare::{Status, continuation};
    let cfg = SimConfig::default();
    let active_grid = mu0_grid(0.05, 1.0, 0.05);
    let passive_grid = mu0_grid(0.05, 0.7, 0.05);
    let jobs: Vec<(bool, f64)> = [0.2, 0.3, 0.4]
        .map(|t| (true, t))
        .into_iter()
        .chain([0.10, 0.15, 0.20].map(|p| (false, p)))
        .collect();
    let results: Vec<(bool, Vec<_>)> = jobs
        .par_iter()
        .map(|&(is_active, chain)| {
            let pts = if is_active {
                continuation(
                    |t_set, mu0| active(mu0, t_set),
                    &[chain],
                    &active_grid,
                    &cfg,
                )
            } else {
                continuation(|phi, mu0| passive(mu0, phi), &[chain], &passive_grid, &cfg)
            };
            (is_active, pts)
        })
        .collect();
    // The largest multiplier's modulus along mu0, one curve per chain (valid gaits only: an
    // `invalid-gait` cycle, one that lifts off, is not drawn).
    let curves = |active_chains: bool, name: &str| -> Vec<Series> {
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
    };
    for (stem, active_chains, name) in [
        ("stability_active", true, "T_set"),
        ("stability_passive", false, "phi"),
    ] {
        let f = fig(
            &format!("Largest Floquet multiplier against mu0 ({name})"),
            "mu0",
            "max |multiplier| (stable below 1)",
            curves(active_chains, name),
            true,
        );
        save(&f, &out.join(stem)).map_err(io::Error::other)?;
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
    fs::write(out.join("stability.csv"), csv)?;
    Ok(text)
}
