//! Whole jobs: the paper's Fig. 8 and Fig. 10 sweeps, timed in release with one thread per
//! chain (`walker::sweep::sweep_chains`; a `harness = false` bench:
//! `cargo bench -p walker --bench sweeps`).
//!
//! - Fig. 8 ((P1a)-(P5a), (P4a) continuation): `mu0 = 0, 0.01, ..., 1` (101 values) for
//!   `T_set = 0.2, 0.3, 0.4`, 100 s per `mu0`, each `mu0` starting from the previous steady
//!   post-impact state; the three `T_set` chains run in parallel.
//! - Fig. 10 ((P1b)-(P5b)): `mu0 = 0, 0.01, ..., 0.7` for `phi = 0.10, 0.15, 0.20`, 100 s each,
//!   with continuation; the three `phi` chains run in parallel.
//!
//! Both run with DOP853 (the simulator's default) at the tolerances `TOLS` (`rtol = atol`);
//! wall time is the median of `REPS` runs (min and max printed). Accuracy: the relative error
//! of the last step's descriptors (`T`, `dx`, and `p` on the active walker) of every `mu0`
//! against the same sweep at `rtol = atol = 1e-12` (itself compared with `1e-11` to show the
//! reference's own error): median, 90th and 99th percentiles, maximum, and the number of points
//! above 1e-8.

mod common;

use std::time::Instant;

use common::{median, rel};
use walker::model::Model;
use walker::ode::Method;
use walker::setup::Setup;
use walker::sim::{SimConfig, WalkLimits};
use walker::sweep::{SweepPoint, mu0_grid, sweep_chains};

const REPS: usize = 3;
const TOLS: [f64; 4] = [1e-8, 1e-9, 1e-10, 1e-11];
const REF_TOL: f64 = 1e-12;

#[derive(Clone, Copy)]
enum Fig {
    Fig8,
    Fig10,
}

/// The built-in scene `scene` with `params` set by name.
fn model(scene: &str, params: &[(&str, f64)]) -> Model {
    let mut setup = Setup::built_in(scene).expect("a built-in scene");
    for &(name, value) in params {
        setup.set(name, value).expect("a parameter in its range");
    }
    setup.model().expect("the scene's kernels are compiled in")
}

/// The chains of a figure: `T_set` (Fig. 8) or `phi` (Fig. 10).
fn chains(fig: Fig) -> &'static [f64] {
    match fig {
        Fig::Fig8 => &[0.2, 0.3, 0.4],
        Fig::Fig10 => &[0.10, 0.15, 0.20],
    }
}

fn run(fig: Fig, tol: f64, periodic: bool) -> Vec<Vec<SweepPoint>> {
    run_on(fig, tol, chains(fig), periodic)
}

/// The sweep of `fig` over the chains `on` only; with `periodic`, each `mu0` stops once its gait
/// is periodic to within `tol` (`WalkLimits::periodic`).
fn run_on(fig: Fig, tol: f64, on: &[f64], periodic: bool) -> Vec<Vec<SweepPoint>> {
    let cfg = SimConfig {
        method: Method::Dop853,
        rtol: tol,
        atol: tol,
        ..SimConfig::default()
    };
    let limits = WalkLimits {
        max_steps: 100_000,
        duration: 100.0,
        record: false,
        periodic: periodic.then_some(tol),
    };
    match fig {
        Fig::Fig8 => {
            let grid = mu0_grid(0.0, 1.0, 0.01);
            sweep_chains(
                on,
                |t_set, mu0| model("active-level", &[("mu0", mu0), ("T_set", t_set)]),
                &cfg,
                &grid,
                |m: &Model| {
                    m.start_state_with("omega0", 0.8)
                        .expect("omega0 is a start parameter")
                },
                &limits,
                false,
                &|| {},
            )
        }
        Fig::Fig10 => {
            let grid = mu0_grid(0.0, 0.7, 0.01);
            let make = |phi: f64, mu0: f64| model("passive-slope", &[("mu0", mu0), ("phi", phi)]);
            sweep_chains(
                on,
                make,
                &cfg,
                &grid,
                Model::start_state,
                &limits,
                false,
                &|| {},
            )
        }
    }
}

/// The relative error of the last descriptors (`T`, `dx`, and `p` on the active walker; the
/// largest of them per point) against a reference, over all points with the same outcome and
/// number of steps in both runs.
struct Errors {
    max: f64,
    median: f64,
    /// 90th and 99th percentiles.
    p90: f64,
    p99: f64,
    /// Points with an error above 1e-8 (the target of the Fig. 8 sweep).
    above_1e8: usize,
    /// Points compared.
    n: usize,
    /// Points whose outcome (failure kind) differs.
    differ_kind: usize,
    /// Points with a different number of steps in 100 s: their last steps are not the same
    /// step, so they are not compared (unless one of the two stopped as periodic, when its last
    /// step stands for every later one).
    differ_steps: usize,
}

fn percentile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let k = ((sorted.len() - 1) as f64 * q).round() as usize;
    sorted[k.min(sorted.len() - 1)]
}

fn compare(a: &[Vec<SweepPoint>], b: &[Vec<SweepPoint>]) -> Errors {
    let mut errs = Vec::new();
    let (mut differ_kind, mut differ_steps) = (0, 0);
    for (ca, cb) in a.iter().zip(b) {
        for (pa, pb) in ca.iter().zip(cb) {
            let fa = pa.failure.as_ref().map(|f| f.name());
            let fb = pb.failure.as_ref().map(|f| f.name());
            if fa != fb {
                differ_kind += 1;
                continue;
            }
            if pa.steps != pb.steps && !(pa.periodic || pb.periodic) {
                differ_steps += 1;
                continue;
            }
            if let (Some(la), Some(lb)) = (pa.last, pb.last) {
                let mut e = rel(la.period, lb.period).max(rel(la.dx, lb.dx));
                if let (Some(x), Some(y)) = (la.p, lb.p) {
                    e = e.max(rel(x, y));
                }
                errs.push(e);
            }
        }
    }
    errs.sort_by(f64::total_cmp);
    Errors {
        max: errs.last().copied().unwrap_or(f64::NAN),
        median: percentile(&errs, 0.5),
        p90: percentile(&errs, 0.9),
        p99: percentile(&errs, 0.99),
        above_1e8: errs.iter().filter(|&&e| e > 1e-8).count(),
        n: errs.len(),
        differ_kind,
        differ_steps,
    }
}

fn main() {
    println!(
        "threads: one per chain (continuation), reps {REPS}; {} cores",
        std::thread::available_parallelism().map_or(0, usize::from)
    );
    for (fig, name) in [(Fig::Fig8, "Fig. 8"), (Fig::Fig10, "Fig. 10")] {
        let t0 = Instant::now();
        let reference = run(fig, REF_TOL, false);
        let t_ref = t0.elapsed().as_secs_f64();
        let check = run(fig, REF_TOL * 10.0, false);
        let e = compare(&check, &reference);
        let steps: usize = reference.iter().flatten().map(|p| p.steps).sum();
        let fails = reference
            .iter()
            .flatten()
            .filter(|p| p.failure.is_some())
            .count();
        println!(
            "{name}: reference tol {REF_TOL:e} took {t_ref:.2} s, {steps} steps, {fails} failed points; tol {:e} vs reference: max {:.2e} median {:.2e} p99 {:.2e} over {} points ({} outcome / {} step-count differences)",
            REF_TOL * 10.0,
            e.max,
            e.median,
            e.p99,
            e.n,
            e.differ_kind,
            e.differ_steps
        );
        println!(
            "| {name} | tol | stop | wall median (s) | min | max | rel err median | p90 | p99 | max | points > 1e-8 | points | outcome diffs | step-count diffs |"
        );
        println!("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
        for (tol, periodic) in TOLS.iter().flat_map(|&t| [(t, false), (t, true)]) {
            let mut times = Vec::new();
            let mut last = Vec::new();
            for _ in 0..REPS {
                let t0 = Instant::now();
                last = run(fig, tol, periodic);
                times.push(t0.elapsed().as_secs_f64());
            }
            let stop = if periodic { "periodic" } else { "100 s" };
            let tmin = times.iter().copied().fold(f64::INFINITY, f64::min);
            let tmax = times.iter().copied().fold(0.0, f64::max);
            let tm = median(&mut times);
            let e = compare(&last, &reference);
            println!(
                "| {name} | {tol:e} | {stop} | {tm:.3} | {tmin:.3} | {tmax:.3} | {:.2e} | {:.2e} | {:.2e} | {:.2e} | {} | {} | {} | {} |",
                e.median, e.p90, e.p99, e.max, e.above_1e8, e.n, e.differ_kind, e.differ_steps
            );
        }
        // The CPU work: each chain alone, one after the other (one run each).
        let serial: Vec<String> = chains(fig)
            .iter()
            .map(|&c| {
                let t0 = Instant::now();
                run_on(fig, 1e-9, &[c], false);
                format!("{c}: {:.2} s", t0.elapsed().as_secs_f64())
            })
            .collect();
        println!("{name} at 1e-9, each chain alone: {}", serial.join(", "));
    }
}
