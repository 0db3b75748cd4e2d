//! Criterion benchmarks of walker-gen's tape interpreter (`walker_gen::tape`, what runs a model
//! file read at run time) against the same kernels compiled (this crate's generated model
//! kernels: exact Coulomb friction, default options), side by side on the same 1024 seeded
//! points and the model's default parameters: paper-active `closed_loop`, compass-gait `accel`
//! and `impact`. Each measurement evaluates all 1024 points; throughput is per element. Before
//! timing, each pair is checked to give the same bits on every point.
//!
//! `cargo bench -p walker-tests --bench tape` (about 2 s per bench, sample size 20).

mod common;

use std::hint::black_box;
use std::path::Path;
use std::time::Duration;

use common::{N_POINTS, Rng};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use walker_gen::tape::{KernelIndex, Prepared, Scratch, TapeModule};
use walker_gen::{Config, Friction};
use walker_tests::models::{compass_gait as cg, load, paper_active as pa};

/// A model's tape, prepared at the model's defaults.
struct Tape {
    tape: TapeModule,
    prepared: Prepared,
}

impl Tape {
    /// The tape of `models/<name>.toml` with the compiled kernels' configuration.
    fn new(name: &str) -> Tape {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../models/{name}.toml"));
        let mut config = Config::new();
        config
            .model_file(&path)
            .friction(Friction::Coulomb)
            .checked(false);
        let module = config.module().expect("a shipped model derives");
        let tape = TapeModule::new(&module, &config.options()).expect("a shipped model tapes");
        let prepared = tape.prepare_with(default_of(name));
        Tape { tape, prepared }
    }

    fn kernel(&self, name: &str) -> KernelIndex {
        self.tape.kernel_index(name).expect("a kernel of the model")
    }
}

/// The default of each parameter of `models/<name>.toml`, by name.
fn default_of(name: &str) -> impl Fn(&str) -> f64 {
    let model = load(name);
    move |p: &str| {
        model
            .parameters
            .iter()
            .find(|q| q.name.name == p)
            .map_or(f64::NAN, |q| q.default)
    }
}

/// `N_POINTS` argument vectors drawn by `draw`.
fn points<const N: usize>(seed: u64, draw: impl Fn(&mut Rng) -> [f64; N]) -> Vec<[f64; N]> {
    let mut r = Rng::new(seed);
    (0..N_POINTS).map(|_| draw(&mut r)).collect()
}

/// Asserts that the tape gives the compiled outputs, bit for bit, at every point.
fn check<const N: usize, const M: usize>(
    t: &Tape,
    k: KernelIndex,
    xs: &[[f64; N]],
    compiled: impl Fn(&[f64; N]) -> [f64; M],
) {
    let mut scratch = Scratch::new();
    let mut out = [0.0; M];
    for x in xs {
        t.tape
            .eval(k, &t.prepared, x, &mut out, &mut scratch)
            .expect("right lengths");
        let want = compiled(x);
        assert!(
            out.iter()
                .zip(&want)
                .all(|(a, b)| a.to_bits() == b.to_bits()),
            "tape {out:?} != compiled {want:?} at {x:?}"
        );
    }
}

/// One group: the compiled kernel and its tape on the same points.
fn pair<const N: usize, const M: usize>(
    c: &mut Criterion,
    group: &str,
    t: &Tape,
    kernel: &str,
    xs: &[[f64; N]],
    compiled: impl Fn(&[f64; N]) -> [f64; M],
) {
    let k = t.kernel(kernel);
    check(t, k, xs, &compiled);
    let mut g = c.benchmark_group(group);
    g.throughput(Throughput::Elements(xs.len() as u64));
    g.bench_function("compiled", |b| {
        b.iter(|| {
            for x in black_box(xs) {
                black_box(compiled(x));
            }
        });
    });
    let mut scratch = t.tape.scratch();
    let mut out = [0.0; M];
    g.bench_function("tape", |b| {
        b.iter(|| {
            for x in black_box(xs) {
                // Lengths are right (checked above); the Result is only the length checks.
                let _ = t.tape.eval(k, &t.prepared, x, &mut out, &mut scratch);
                black_box(&out);
            }
        });
    });
    g.finish();
}

fn bench(c: &mut Criterion) {
    let active = Tape::new("paper-active");
    let pa_p = pa::prepare(&pa::Params::from_fn(default_of("paper-active")));
    // th1 in the stance range widened by 0.1 rad, th1d, the sliding direction, v.
    let xs = points(0x5EED_2024, |r| {
        [
            r.range(-0.36, 0.36),
            r.range(-1.5, 1.5),
            if r.unit() < 0.5 { -1.0 } else { 1.0 },
            r.range(-20.0, 20.0),
        ]
    });
    pair(
        c,
        "paper_active_closed_loop",
        &active,
        "closed_loop",
        &xs,
        |x| pa::closed_loop(&pa_p, x[0], x[1], x[2], x[3]),
    );

    let gait = Tape::new("compass-gait");
    let cg_p = cg::prepare(&cg::Params::from_fn(default_of("compass-gait")));
    // Stance and swing angles within 0.5 rad, their rates, the sliding direction.
    let xs = points(0x5EED_2025, |r| {
        [
            r.range(-0.5, 0.5),
            r.range(-0.5, 0.5),
            r.range(-2.0, 2.0),
            r.range(-2.0, 2.0),
            if r.unit() < 0.5 { -1.0 } else { 1.0 },
        ]
    });
    pair(c, "compass_gait_accel", &gait, "accel", &xs, |x| {
        cg::accel(&cg_p, x[0], x[1], x[2], x[3], x[4])
    });
    // Angles, the foot's velocity (x, z) and the angle rates just before a strike.
    let xs = points(0x5EED_2026, |r| {
        [
            r.range(-0.5, 0.5),
            r.range(-0.5, 0.5),
            r.range(-0.5, 0.5),
            r.range(-0.5, 0.5),
            r.range(-2.0, 2.0),
            r.range(-2.0, 2.0),
        ]
    });
    pair(c, "compass_gait_impact", &gait, "impact", &xs, |x| {
        cg::impact(&cg_p, x[0], x[1], x[2], x[3], x[4], x[5])
    });
}

/// As `kernels.rs`: short runs, no plots.
fn config() -> Criterion {
    Criterion::default()
        .without_plots()
        .sample_size(20)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench
}
criterion_main!(benches);
