//! Fig. 8 and Fig. 10 from continuation, timed side by side with the sweeps that walk each
//! `mu0` for 100 s and with the sweeps that stop a walk once its gait is periodic, in one run:
//! `cargo run --release -p walker --example continuation_timing -- [REPEATS]`.
//!
//! Fig. 8: the branches of `T_set = 0.2, 0.3, 0.4` over `mu0` in [0, 1] (one thread each);
//! the sweeps walk `mu0 = 0, 0.01, ..., 1` ((P4a): each `mu0` from the previous steady state).
//! Fig. 10: `phi = 0.10, 0.15, 0.20` over `mu0` in [0, 0.7] and `mu0 = 0, 0.01, ..., 0.7`, each
//! `mu0` from (P2b) as `walker reproduce` walks it.
//! Every job uses the simulator's default settings (DOP853, `rtol = 1e-10`, `atol = 1e-12`);
//! the sweeps' periodic stop is at `1e-9` (`walker sweep --until-periodic 1e-9`). Printed: the
//! median wall time of each job over REPEATS runs (default 5) and the ratios, then the largest
//! relative difference of `V` and `T` between the continuation (points placed at every 0.05 of
//! `mu0`) and the 100 s sweep where the sweep's walk is periodic and the branch stable and
//! physical.
//!
//! `-- fig8 [REPEATS]` times only Fig. 8's continuation (every run, then the median);
//! `-- profile` runs each branch of both figures alone and prints where its time goes: the
//! points, and the calls and wall time of the map, of its image alone, its Jacobian, its parameter derivative and the
//! warm-up walk. `-- dump DIR` writes the branches that `walker reproduce` draws (largest
//! step 0.05), Fig. 8's branches at the default settings and both figures' branches with points
//! placed at every 0.01 of `mu0` as CSV files into `DIR`, one line
//! a point, with every digit, to compare two versions of the library numerically.

use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Instant;

use nalgebra::DMatrix;

use walker::continuation::{
    Branch, ContinuationOptions, GaitProblem, LabelKind, MapValue, ProblemError, Stability,
    WalkerProblem, continuation,
};
use walker::model::Model;
use walker::setup::Setup;
use walker::sim::{SimConfig, WalkLimits};
use walker::sweep::{SweepPoint, mu0_grid, sweep_chains};

/// Which figure.
#[derive(Clone, Copy)]
enum Fig {
    Fig8,
    Fig10,
}

impl Fig {
    fn chains(self) -> [f64; 3] {
        match self {
            Fig::Fig8 => [0.2, 0.3, 0.4],
            Fig::Fig10 => [0.10, 0.15, 0.20],
        }
    }
    fn mu0_max(self) -> f64 {
        match self {
            Fig::Fig8 => 1.0,
            Fig::Fig10 => 0.7,
        }
    }
    fn setup(self, chain: f64) -> Setup {
        let (scene, param) = match self {
            Fig::Fig8 => ("active-level", "T_set"),
            Fig::Fig10 => ("passive-slope", "phi"),
        };
        Setup::built_in(scene)
            .and_then(|s| s.with(param, chain))
            .expect("a built-in scene and a chain value in its range")
    }
}

fn branches(fig: Fig, user: &[f64]) -> Vec<Option<Branch>> {
    let opts = ContinuationOptions {
        user_points: user.to_vec(),
        ..ContinuationOptions::default()
    };
    std::thread::scope(|scope| {
        let handles: Vec<_> = fig
            .chains()
            .map(|c| {
                let opts = &opts;
                scope.spawn(move || {
                    let w = WalkerProblem::new(fig.setup(c), "mu0", SimConfig::default()).ok()?;
                    continuation(&w, 0.0, fig.mu0_max(), opts).ok()
                })
            })
            .into_iter()
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().ok().flatten())
            .collect()
    })
}

fn sweep(fig: Fig, periodic: bool) -> Vec<Vec<SweepPoint>> {
    let limits = WalkLimits {
        max_steps: 100_000,
        duration: 100.0,
        record: false,
        periodic: periodic.then_some(1e-9),
    };
    let grid = mu0_grid(0.0, fig.mu0_max(), 0.01);
    let make = |c: f64, mu0: f64| {
        fig.setup(c)
            .with("mu0", mu0)
            .and_then(|s| Ok(s.model()?))
            .expect("the sweep's models are compiled in")
    };
    sweep_chains(
        &fig.chains(),
        make,
        &SimConfig::default(),
        &grid,
        |m: &Model| {
            if matches!(fig, Fig::Fig8) {
                m.start_state_with("omega0", 0.8)
                    .expect("omega0 is a start parameter")
            } else {
                m.start_state()
            }
        },
        &limits,
        // Fig. 10 starts every `mu0` from (P2b), as `walker reproduce` does: continued from
        // the previous `mu0`, the wheel on `phi = 0.2` keeps the ever faster slide of the
        // `mu0` below 0.41, where no periodic gait exists, up to `mu0 = 0.67`.
        matches!(fig, Fig::Fig10),
        &|| {},
    )
}

fn median_time(repeats: usize, mut job: impl FnMut()) -> f64 {
    let mut t: Vec<f64> = (0..repeats)
        .map(|_| {
            let start = Instant::now();
            job();
            start.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[t.len() / 2]
}

/// Calls and nanoseconds of one kind of evaluation.
#[derive(Default)]
struct Tally {
    calls: AtomicU64,
    nanos: AtomicU64,
}

/// The CPU time this thread has run (ns), from Linux's `/proc/thread-self/schedstat` (0
/// elsewhere; updated at the scheduler's ticks, a few ms): unlike wall time it does not count
/// the time other jobs on a loaded machine hold the core.
fn thread_cpu_ns() -> u64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse().ok())
        .unwrap_or(0)
}

impl Tally {
    fn time<T>(&self, f: impl FnOnce() -> T) -> T {
        let start = Instant::now();
        let out = f();
        let ns = u64::try_from(start.elapsed().as_nanos()).unwrap_or(u64::MAX);
        self.calls.fetch_add(1, Ordering::Relaxed);
        self.nanos.fetch_add(ns, Ordering::Relaxed);
        out
    }

    fn show(&self, name: &str) -> String {
        let calls = self.calls.load(Ordering::Relaxed);
        let ms = self.nanos.load(Ordering::Relaxed) as f64 * 1e-6;
        format!("{name} {calls} ({ms:.1} ms)")
    }
}

/// A walker that counts and times what continuation asks of it.
struct Counted {
    inner: WalkerProblem,
    map: Tally,
    image: Tally,
    jacobian: Tally,
    derivative: Tally,
    guess: Tally,
}

impl GaitProblem for Counted {
    fn dim(&self) -> usize {
        self.inner.dim()
    }
    fn parameter_name(&self) -> &str {
        self.inner.parameter_name()
    }
    fn map(&self, r: &[f64], p: f64) -> Result<MapValue, ProblemError> {
        self.map.time(|| self.inner.map(r, p))
    }
    fn image(&self, r: &[f64], p: f64) -> Result<Vec<f64>, ProblemError> {
        self.image.time(|| self.inner.image(r, p))
    }
    fn jacobian(&self, r: &[f64], p: f64) -> Result<DMatrix<f64>, ProblemError> {
        self.jacobian.time(|| self.inner.jacobian(r, p))
    }
    fn parameter_derivative(
        &self,
        r: &[f64],
        p: f64,
        image: &[f64],
        direction: f64,
    ) -> Result<Vec<f64>, ProblemError> {
        self.derivative
            .time(|| self.inner.parameter_derivative(r, p, image, direction))
    }
    fn has_family_at(&self, p: f64) -> bool {
        self.inner.has_family_at(p)
    }
    fn guess(&self, p: f64) -> Option<Vec<f64>> {
        self.guess.time(|| self.inner.guess(p))
    }
}

/// Each branch of both figures alone (one thread), with where its time goes.
fn profile() {
    for fig in [Fig::Fig8, Fig::Fig10] {
        for c in fig.chains() {
            let Ok(inner) = WalkerProblem::new(fig.setup(c), "mu0", SimConfig::default()) else {
                continue;
            };
            let w = Counted {
                inner,
                map: Tally::default(),
                image: Tally::default(),
                jacobian: Tally::default(),
                derivative: Tally::default(),
                guess: Tally::default(),
            };
            let (start, cpu) = (Instant::now(), thread_cpu_ns());
            let b = continuation(&w, 0.0, fig.mu0_max(), &ContinuationOptions::default());
            let wall = start.elapsed().as_secs_f64() * 1e3;
            let cpu = thread_cpu_ns().saturating_sub(cpu) as f64 * 1e-6;
            let (points, labels) = b.as_ref().map_or((0, 0), |b| {
                (
                    b.points.len(),
                    b.points.iter().filter(|p| p.label.is_some()).count(),
                )
            });
            println!(
                "{} {c}: {wall:.1} ms wall, {cpu:.1} ms CPU, {points} points ({labels} labelled); {}, {}, {}, {}, {}",
                if matches!(fig, Fig::Fig8) {
                    "Fig. 8 T_set"
                } else {
                    "Fig. 10 phi"
                },
                w.map.show("map"),
                w.image.show("image"),
                w.jacobian.show("jacobian"),
                w.derivative.show("dP/dp"),
                w.guess.show("warm-up"),
            );
        }
    }
}

/// Fig. 8's continuation alone, `repeats` times.
fn fig8_only(repeats: usize) {
    let mut times = Vec::new();
    let mut points = 0;
    for _ in 0..repeats {
        let start = Instant::now();
        points = branches(Fig::Fig8, &[])
            .iter()
            .flatten()
            .map(|b| b.points.len())
            .sum();
        times.push(start.elapsed().as_secs_f64());
    }
    let shown: Vec<String> = times.iter().map(|t| format!("{t:.3}")).collect();
    times.sort_by(f64::total_cmp);
    println!(
        "Fig. 8 continuation: median {:.3} s over {repeats} runs ({points} points); runs {}",
        times[times.len() / 2],
        shown.join(" ")
    );
}

/// One branch as CSV lines: parameter, state, `T`, `dx`, `V`, multipliers (real, imaginary),
/// smallest normal force, stability, physical, label.
fn dump_branch(b: &Branch) -> String {
    let mut out =
        String::from("p,r0,r1,T,dx,V,m0re,m0im,m1re,m1im,lambda_min,stability,physical,label\n");
    for pt in &b.points {
        let m = |i: usize, im: bool| {
            pt.multipliers
                .get(i)
                .map_or(f64::NAN, |m| if im { m.im } else { m.re })
        };
        out += &format!(
            "{:.17e},{:.17e},{:.17e},{:.17e},{:.17e},{:.17e},{:.17e},{:.17e},{:.17e},{:.17e},{:.17e},{:?},{},{}\n",
            pt.parameter,
            pt.state[0],
            pt.state[1],
            pt.cycle.period,
            pt.cycle.dx,
            pt.cycle.speed,
            m(0, false),
            m(0, true),
            m(1, false),
            m(1, true),
            pt.tests.min_normal_force.unwrap_or(f64::NAN),
            pt.stability,
            pt.physical,
            pt.label.map_or("", |l| l.tag),
        );
    }
    out
}

/// The branches of `walker reproduce`'s diagrams and Fig. 8's at the default settings, as CSV
/// files in `dir`.
fn dump(dir: &str) {
    let reproduce = ContinuationOptions {
        max_step: 0.05,
        ..ContinuationOptions::default()
    };
    let mut jobs: Vec<(String, Setup, &str, f64, f64, ContinuationOptions)> = Vec::new();
    // Points placed at every 0.01 of mu0 compare two versions at the same parameters.
    let placed = |fig: Fig| ContinuationOptions {
        user_points: mu0_grid(0.0, fig.mu0_max(), 0.01),
        ..ContinuationOptions::default()
    };
    for (fig, name, opts) in [
        (Fig::Fig8, "fig8_t", &reproduce),
        (Fig::Fig10, "fig10_phi", &reproduce),
        (Fig::Fig8, "fig8_default_t", &ContinuationOptions::default()),
        (Fig::Fig8, "fig8_placed_t", &placed(Fig::Fig8)),
        (Fig::Fig10, "fig10_placed_phi", &placed(Fig::Fig10)),
    ] {
        for c in fig.chains() {
            let s = fig.setup(c).with("mu0", 0.0).expect("mu0 = 0 is in range");
            jobs.push((
                format!("{name}{c}"),
                s,
                "mu0",
                0.0,
                fig.mu0_max(),
                opts.clone(),
            ));
        }
    }
    let s = Setup::passive_slope()
        .and_then(|s| s.with("phi", 0.2)?.with("mu0", 0.5))
        .expect("the built-in scene passive-slope");
    jobs.push((
        "fig10_over_phi".into(),
        s,
        "phi",
        0.05,
        0.3,
        reproduce.clone(),
    ));
    for (name, setup, param, from, to, opts) in jobs {
        let text = WalkerProblem::new(setup, param, SimConfig::default())
            .map_err(|e| e.to_string())
            .and_then(|w| continuation(&w, from, to, &opts).map_err(|e| e.to_string()))
            .map_or_else(|e| format!("error: {e}\n"), |b| dump_branch(&b));
        let path = format!("{dir}/{name}.csv");
        if let Err(e) = std::fs::write(&path, text) {
            eprintln!("{path}: {e}");
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let count =
        |i: usize| -> usize { args.get(i).and_then(|a| a.parse().ok()).unwrap_or(5).max(1) };
    match args.first().map(String::as_str) {
        Some("profile") => return profile(),
        Some("fig8") => return fig8_only(count(1)),
        Some("dump") => return dump(args.get(1).map_or(".", String::as_str)),
        _ => {}
    }
    let repeats = count(0);
    for fig in [Fig::Fig8, Fig::Fig10] {
        let name = if matches!(fig, Fig::Fig8) {
            "Fig. 8"
        } else {
            "Fig. 10"
        };
        let mut points = 0;
        let cont = median_time(repeats, || {
            points = branches(fig, &[])
                .iter()
                .flatten()
                .map(|b| b.points.len())
                .sum();
        });
        let sweep_periodic = median_time(repeats, || {
            std::hint::black_box(sweep(fig, true));
        });
        let long = sweep(fig, false);
        let sweep_100 = median_time(repeats.min(3), || {
            std::hint::black_box(sweep(fig, false));
        });
        println!(
            "{name}: continuation {cont:.3} s ({points} points), sweep with periodic stop {sweep_periodic:.3} s, sweep of 100 s walks {sweep_100:.3} s; ratios {:.1}x and {:.1}x",
            sweep_periodic / cont,
            sweep_100 / cont
        );
        // Agreement with the 100 s sweep at every 0.05 of mu0.
        let user: Vec<f64> = mu0_grid(0.0, fig.mu0_max(), 0.05);
        let mut worst = (0.0_f64, 0.0_f64, 0usize);
        for (b, chain) in branches(fig, &user).iter().zip(&long) {
            let Some(b) = b else { continue };
            for p in b.labelled(LabelKind::UserPoint) {
                let Some(s) = chain.iter().find(|s| (s.value - p.parameter).abs() < 1e-9) else {
                    continue;
                };
                let Some(last) = s.last.filter(|_| s.failure.is_none()) else {
                    continue;
                };
                // The walk's last two steps repeat (a walk that runs away to ever faster
                // sliding changes its step length and speed from step to step).
                let periodic = s.previous.is_some_and(|prev| {
                    ((prev.dx - last.dx) / last.dx).abs() < 1e-10
                        && ((prev.speed - last.speed) / last.speed).abs() < 1e-10
                });
                if p.stability == Stability::Stable && p.physical && periodic {
                    worst.0 = worst
                        .0
                        .max(((p.cycle.speed - last.speed) / last.speed).abs());
                    worst.1 = worst
                        .1
                        .max(((p.cycle.period - last.period) / last.period).abs());
                    worst.2 += 1;
                }
            }
        }
        println!(
            "{name}: largest relative difference to the 100 s sweep over {} stable, physical, periodic points: V {:.1e}, T {:.1e}",
            worst.2, worst.0, worst.1
        );
    }
}
