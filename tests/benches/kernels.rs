//! Criterion benchmarks of the generated kernels (`active_level` / `passive_slope` with Table 1
//! compiled in, `general_level` / `general_slope` with every parameter at run time) against the
//! lean generic nalgebra path (fixed-size KKT + LU, `common`) on the same 1024 seeded inputs.
//! Each measurement evaluates all 1024 points; throughput is reported per element. Beside the
//! scene kernels (what the hand-derived simulator called), the closed loop and the slope's
//! `accel` the simulator calls now: those of `models/paper-active.toml` and
//! `models/paper-passive.toml` with Table 1 fixed (`walker::compiled`, the `model_*` benches).
//!
//! `cargo bench -p walker-tests --bench kernels` (about 1.5 s per bench, sample size 20).

mod common;

use std::hint::black_box;
use std::time::Duration;

use common::{C, Input, MU0, inputs};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use nalgebra::Vector4;
use walker::compiled::{paper_active_0 as ma, paper_passive_0 as mp};
use walker_tests::scenes::{
    active_level as al, general_level as gl, general_slope as gs, passive_slope as ps,
};
use walker_tests::{Phys, mu_law};

fn gl_prep(p: &Phys) -> gl::Prepared {
    p.level_kernels((MU0, C), (0.3, 0.0, 0.0))
}

fn gs_prep(p: &Phys) -> gs::Prepared {
    p.slope_kernels((MU0, C))
}

fn qd(x: &Input) -> Vector4<f64> {
    Vector4::new(x.xd, x.zd, x.th1d, x.th2d)
}

fn bench(c: &mut Criterion) {
    let xs = inputs();
    let p0 = Phys::table1(0.0);
    let p2 = Phys::table1(0.2);
    let ka = al::prepare(&al::Params {
        mu0: MU0,
        c: C,
        t_set: 0.3,
        k_p: 0.0,
        k_d: 0.0,
    });
    let kl = gl_prep(&p0);
    let kp = ps::prepare(&ps::Params {
        phi: 0.2,
        mu0: MU0,
        c: C,
    });
    let ks = gs_prep(&p2);
    let kma = ma::prepare(&ma::Params {
        mu0: MU0,
        c: C,
        t_set: 0.3,
        k_p: 0.0,
        k_d: 0.0,
    });
    let kmp = mp::prepare(&mp::Params {
        phi: 0.2,
        mu0: MU0,
        c: C,
    });

    let mut g = c.benchmark_group("rhs_control_accel");
    g.throughput(Throughput::Elements(xs.len() as u64));
    g.bench_function("active_level", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                let [a, bb] = al::control_level(&ka, x.th1, x.th1d, x.xd);
                let u = (x.v + bb) / a;
                black_box(al::accel_level(&ka, x.th1, x.th1d, u, x.xd));
            }
        });
    });
    g.bench_function("active_level_closed_loop", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(al::closed_loop_level(&ka, x.th1, x.th1d, x.xd, x.v));
            }
        });
    });
    g.bench_function("model_closed_loop", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(ma::closed_loop(&kma, x.th1, x.th1d, x.xd, x.v));
            }
        });
    });
    g.bench_function("general_level", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                let [a, bb] = gl::control_level(&kl, x.th1, x.th1d, x.xd);
                let u = (x.v + bb) / a;
                black_box(gl::accel_level(&kl, x.th1, x.th1d, u, x.xd));
            }
        });
    });
    g.bench_function("generic_lu", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                let mu = mu_law(MU0, C, 0.0, x.xd);
                black_box(common::generic_closed_loop(&p0, x.th1, x.th1d, mu, x.v));
            }
        });
    });
    g.finish();

    let mut g = c.benchmark_group("lambda_level");
    g.throughput(Throughput::Elements(xs.len() as u64));
    g.bench_function("active_level", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(al::lambda_level(&ka, x.th1, x.th1d, x.u, x.xd));
            }
        });
    });
    g.bench_function("general_level", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(gl::lambda_level(&kl, x.th1, x.th1d, x.u, x.xd));
            }
        });
    });
    g.bench_function("generic_lu", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                let mu = mu_law(MU0, C, 0.0, x.xd);
                black_box(common::generic_accel(&p0, x.th1, x.th1d, x.u, mu).1);
            }
        });
    });
    g.finish();

    let mut g = c.benchmark_group("projection_level");
    g.throughput(Throughput::Elements(xs.len() as u64));
    g.bench_function("active_level", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(al::projection_level(&ka, x.th1, x.xd));
            }
        });
    });
    g.bench_function("general_level", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(gl::projection_level(&kl, x.th1, x.xd));
            }
        });
    });
    g.bench_function("generic_inverse", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                let mu = mu_law(MU0, C, 0.0, x.xd);
                black_box(common::generic_projection(&p0, x.th1, mu));
            }
        });
    });
    g.finish();

    let mut g = c.benchmark_group("impact2_level");
    g.throughput(Throughput::Elements(xs.len() as u64));
    g.bench_function("active_level", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(al::impact2_level(&ka, x.th1, x.xd, x.zd, x.th1d, x.th2d));
            }
        });
    });
    g.bench_function("general_level", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(gl::impact2_level(&kl, x.th1, x.xd, x.zd, x.th1d, x.th2d));
            }
        });
    });
    g.bench_function("generic_lu", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(common::generic_impact2_level(&p0, x.th1, qd(x)));
            }
        });
    });
    g.finish();

    let mut g = c.benchmark_group("impact3_level");
    g.throughput(Throughput::Elements(xs.len() as u64));
    g.bench_function("active_level", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(al::impact3_level(&ka, x.th1, x.xd, x.zd, x.th1d, x.th2d));
            }
        });
    });
    g.bench_function("general_level", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(gl::impact3_level(&kl, x.th1, x.xd, x.zd, x.th1d, x.th2d));
            }
        });
    });
    g.bench_function("generic_lu", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(common::generic_impact3_level(&p0, x.th1, qd(x)));
            }
        });
    });
    g.finish();

    let mut g = c.benchmark_group("impact_slope");
    g.throughput(Throughput::Elements(xs.len() as u64));
    g.bench_function("passive_slope", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(ps::impact_slope(&kp, x.th1, x.xd, x.zd, x.th1d, x.th2d));
            }
        });
    });
    g.bench_function("general_slope", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(gs::impact_slope(&ks, x.th1, x.xd, x.zd, x.th1d, x.th2d));
            }
        });
    });
    g.bench_function("generic_lu", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(common::generic_impact_slope(&p2, x.th1, qd(x)));
            }
        });
    });
    g.finish();

    let mut g = c.benchmark_group("accel_slope");
    g.throughput(Throughput::Elements(xs.len() as u64));
    g.bench_function("passive_slope", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(ps::accel_slope(&kp, x.th1, x.th1d, x.xd));
            }
        });
    });
    g.bench_function("model_accel", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(mp::accel(&kmp, x.th1, x.th1d, x.xd));
            }
        });
    });
    g.bench_function("general_slope", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                black_box(gs::accel_slope(&ks, x.th1, x.th1d, x.xd));
            }
        });
    });
    g.bench_function("generic_lu", |b| {
        b.iter(|| {
            for x in black_box(&xs) {
                let mu = mu_law(MU0, C, 0.2, x.xd);
                black_box(common::generic_accel_slope(&p2, x.th1, x.th1d, mu));
            }
        });
    });
    g.finish();
}

/// 20 samples of 1.5 s per bench; no plots (Criterion's plotting needs a system font, which a
/// fresh machine need not have: it panicked with `FontUnavailable` here).
fn config() -> Criterion {
    Criterion::default()
        .without_plots()
        .sample_size(20)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_millis(1500))
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench
}
criterion_main!(benches);
