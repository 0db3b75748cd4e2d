//! The hand-written small dense linear algebra against nalgebra's stack-allocated matrices, to
//! decide which to keep (`cargo bench -p walker --bench linalg`):
//!
//! - `lu9`: factorise a 9x9 matrix (RODAS4's iteration matrix on the walker's state with its
//!   quadrature) and solve one right-hand side, and the same with six right-hand sides (what
//!   one RODAS4 step does): [`walker::ode::Lu`] against `SMatrix<f64, 9, 9>::lu()` and
//!   `solve_mut`;
//! - `matmul8`: the hand-written 8x8 product the Poincare map's Jacobian used (a copy, below)
//!   against the `SMatrix<f64, 8, 8>` product, with and without the conversion from and to
//!   row-major arrays.
//!
//! Measured once (2026-11-24, shared 2-core machine, load about 3): `lu9` factor+solve 337 ns
//! by hand against 414 ns by nalgebra (hand 1.23x faster), factor+6 solves 783 ns against 764 ns
//! (at par, 0.98x); `matmul8` 127 ns by hand against 121 ns by nalgebra (nalgebra 1.05x
//! faster), 287 ns with the conversions. Kept: the LU (`src/ode/linalg.rs`); replaced: the 8x8
//! product (the map now builds its matrices as `SMatrix`; the sums run in the same order, so the
//! Jacobian is bitwise unchanged).

#![allow(missing_docs)]

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use nalgebra::{SMatrix, SVector};
use walker::ode::Lu;

/// The hand-written 8x8 product the Poincare map used before it was replaced by nalgebra's
/// (kept here as the reference of the comparison).
fn matmul(a: &[[f64; 8]; 8], b: &[[f64; 8]; 8]) -> [[f64; 8]; 8] {
    let mut c = [[0.0; 8]; 8];
    for i in 0..8 {
        for j in 0..8 {
            c[i][j] = (0..8).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    c
}

/// A well-conditioned test matrix: `shift I - J` with a dense, non-symmetric `J`.
fn iteration_matrix<const N: usize>() -> ([[f64; N]; N], f64) {
    let jac: [[f64; N]; N] = core::array::from_fn(|i| {
        core::array::from_fn(|j| ((i * 7 + j * 3) % 11) as f64 / 11.0 - 0.5 + (i == j) as u8 as f64)
    });
    (jac, 40.0)
}

fn rhs<const N: usize>() -> [f64; N] {
    core::array::from_fn(|i| 1.0 + 0.1 * i as f64)
}

fn lu9(c: &mut Criterion) {
    let (jac, shift) = iteration_matrix::<9>();
    // nalgebra forms `shift I - J` as RODAS4 would have to, then factorises it.
    let shifted = |shift: f64, jac: &[[f64; 9]; 9]| {
        SMatrix::<f64, 9, 9>::from_fn(|i, j| if i == j { shift } else { 0.0 } - jac[i][j])
    };
    let b = rhs::<9>();
    let mut g = c.benchmark_group("lu9");
    g.bench_function("hand/factor+solve", |bn| {
        let mut lu = Lu::<9>::new();
        bn.iter(|| {
            let _ = lu.factor_shifted(black_box(shift), black_box(&jac));
            let mut x = black_box(b);
            lu.solve(&mut x);
            x
        })
    });
    g.bench_function("nalgebra/factor+solve", |bn| {
        bn.iter(|| {
            let m = shifted(black_box(shift), black_box(&jac));
            let lu = m.lu();
            let mut x = SVector::<f64, 9>::from_column_slice(black_box(&b));
            let ok = lu.solve_mut(&mut x);
            (ok, x)
        })
    });
    g.bench_function("hand/factor+6solves", |bn| {
        let mut lu = Lu::<9>::new();
        bn.iter(|| {
            let _ = lu.factor_shifted(black_box(shift), black_box(&jac));
            let mut xs = [black_box(b); 6];
            for x in &mut xs {
                lu.solve(x);
            }
            xs
        })
    });
    g.bench_function("nalgebra/factor+6solves", |bn| {
        bn.iter(|| {
            let m = shifted(black_box(shift), black_box(&jac));
            let lu = m.lu();
            let mut xs = [SVector::<f64, 9>::from_column_slice(black_box(&b)); 6];
            let mut ok = true;
            for x in &mut xs {
                ok &= lu.solve_mut(x);
            }
            (ok, xs)
        })
    });
    g.finish();
}

fn matmul8(c: &mut Criterion) {
    let (a, _) = iteration_matrix::<8>();
    let b: [[f64; 8]; 8] = core::array::from_fn(|i| core::array::from_fn(|j| a[j][i] * 0.5));
    let (ma, mb) = (
        SMatrix::<f64, 8, 8>::from_fn(|i, j| a[i][j]),
        SMatrix::<f64, 8, 8>::from_fn(|i, j| b[i][j]),
    );
    let mut g = c.benchmark_group("matmul8");
    g.bench_function("hand", |bn| {
        bn.iter(|| matmul(black_box(&a), black_box(&b)))
    });
    g.bench_function("nalgebra", |bn| bn.iter(|| black_box(&ma) * black_box(&mb)));
    g.bench_function("nalgebra/with-conversion", |bn| {
        bn.iter(|| {
            let (a, b) = (black_box(&a), black_box(&b));
            let p = SMatrix::<f64, 8, 8>::from_fn(|i, j| a[i][j])
                * SMatrix::<f64, 8, 8>::from_fn(|i, j| b[i][j]);
            let out: [[f64; 8]; 8] = core::array::from_fn(|i| core::array::from_fn(|j| p[(i, j)]));
            out
        })
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().without_plots();
    targets = lu9, matmul8
}
criterion_main!(benches);
