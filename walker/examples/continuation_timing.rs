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

use std::time::Instant;

use walker::continuation::{
    Branch, ContinuationOptions, LabelKind, PaperWalker, Stability, continuation,
};
use walker::setup::Setup;
use walker::sim::{SimConfig, WalkLimits};
use walker::sweep::{SweepPoint, mu0_grid, sweep_chains};
use walker_scene::Param;

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
        match self {
            Fig::Fig8 => {
                let mut s = Setup::active_level();
                s.runtime.t_set = chain;
                s
            }
            Fig::Fig10 => {
                let mut s = Setup::passive_slope();
                s.runtime.phi = chain;
                s
            }
        }
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
                    let w =
                        PaperWalker::new(fig.setup(c), Param::Mu0, SimConfig::default()).ok()?;
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
        let mut s = fig.setup(c);
        s.runtime.mu0 = mu0;
        s.model()
    };
    sweep_chains(
        &fig.chains(),
        make,
        &SimConfig::default(),
        &grid,
        |c| {
            let m = make(c, 0.0);
            m.initial_state(if matches!(fig, Fig::Fig8) {
                0.8
            } else {
                m.default_omega0()
            })
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

fn main() {
    let repeats: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(5)
        .max(1);
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
                let Some(s) = chain.iter().find(|s| (s.mu0 - p.parameter).abs() < 1e-9) else {
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
