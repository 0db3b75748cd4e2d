//! Shared by the kernel benches: the deterministic input set and the *lean* generic path.
//!
//! The lean generic path is what a generic simulator would do per right-hand-side call:
//! assemble `M`, `h`, `J`, `J_mu` (the matrices of `walker_tests`) and solve the KKT system by
//! LU with partial pivoting on nalgebra's fixed-size matrices (no heap, no conditioning
//! estimate). `walker_tests::stance` etc. also estimate the conditioning by SVD for the test
//! bounds; that is not part of a simulation and is timed separately as "test-suite generic".

#![allow(dead_code, reason = "each bench binary uses a subset")]

use nalgebra::{SMatrix, SVector, Vector4};
use walker_tests::{Phys, bias, j_fore, j_lock, j_mu, j_stance, mass_matrix, s_vec};

/// Deterministic generator (SplitMix64).
pub struct Rng(u64);

impl Rng {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }
    /// Uniform in `[0, 1)`.
    pub fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in `[a, b)`.
    pub fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.unit()
    }
}

/// One stance / impact input point of the walker in the paper's operating range.
#[derive(Clone, Copy, Debug)]
pub struct Input {
    /// Stance-leg angle.
    pub th1: f64,
    /// Horizontal foot velocity (the friction law's argument).
    pub xd: f64,
    /// Vertical foot velocity (impacts on the slope).
    pub zd: f64,
    /// Stance-leg angular velocity.
    pub th1d: f64,
    /// Torso angular velocity.
    pub th2d: f64,
    /// Control input.
    pub u: f64,
    /// Auxiliary input `v` of Eq. 32.
    pub v: f64,
}

/// Number of input points of every bench.
pub const N_POINTS: usize = 1024;

/// The fixed input set (seeded): `th1` within the stance range widened by 0.1 rad, `xd` within
/// the `tanh` law's transition (`|c xd| < 3` for `c = 100`).
pub fn inputs() -> Vec<Input> {
    let mut r = Rng::new(0x5EED_2024);
    let a2 = std::f64::consts::PI / 12.0;
    (0..N_POINTS)
        .map(|_| Input {
            th1: r.range(-a2 - 0.1, a2 + 0.1),
            xd: r.range(-0.03, 0.03),
            zd: r.range(-0.1, 0.1),
            th1d: r.range(-1.5, 1.5),
            th2d: r.range(-1.5, 1.5),
            u: r.range(-5.0, 5.0),
            v: r.range(-20.0, 20.0),
        })
        .collect()
}

/// Table 1 with the paper's friction law at `mu0 = 0.4`, `c = 100`.
pub const MU0: f64 = 0.4;
/// Sharpness of the friction law.
pub const C: f64 = 100.0;

/// `mu = -mu0 tanh(c xd [/ cos phi])` (Eqs. 26, 37), as the kernels compute it.
pub fn mu_of(mu0: f64, c: f64, phi: f64, xd: f64) -> f64 {
    walker_tests::mu_law(mu0, c, phi, xd)
}

fn kkt5(p: &Phys, th1: f64, mu: f64) -> SMatrix<f64, 5, 5> {
    let m = mass_matrix(p, th1);
    let j = j_stance(p.phi);
    let jh = j + j_mu(p.phi, mu);
    let mut k = SMatrix::<f64, 5, 5>::zeros();
    k.fixed_view_mut::<4, 4>(0, 0).copy_from(&m);
    for i in 0..4 {
        k[(i, 4)] = -jh[i];
        k[(4, i)] = j[i];
    }
    k
}

/// Generic stance of the active walker, one LU of the KKT matrix for three right-hand sides:
/// `[S; 0]` and `[h; 0]` give `A = S^T x_S`, `B = S^T x_h` (Eqs. 30-31), the control
/// `u = (v + B) / A` (Eq. 31), and `[qdd; lambda] = x_S u - x_h` (Eq. 19 is linear in `u`).
/// Returns `(qdd, lambda, [A, B], u)`.
pub fn generic_closed_loop(
    p: &Phys,
    th1: f64,
    th1d: f64,
    mu: f64,
    v: f64,
) -> ([f64; 4], f64, [f64; 2], f64) {
    let k = kkt5(p, th1, mu);
    let (h, _) = bias(p, th1, th1d);
    let s = s_vec();
    let mut rhs = SMatrix::<f64, 5, 2>::zeros();
    for i in 0..4 {
        rhs[(i, 0)] = s[i];
        rhs[(i, 1)] = h[i];
    }
    let x = k.lu().solve(&rhs).unwrap_or_else(SMatrix::zeros);
    let a = x[(2, 0)] - x[(3, 0)];
    let b = x[(2, 1)] - x[(3, 1)];
    let u = (v + b) / a;
    let y = x.column(0) * u - x.column(1);
    ([y[0], y[1], y[2], y[3]], y[4], [a, b], u)
}

/// Generic stance accelerations and reaction for a given `u`: one KKT solve.
pub fn generic_accel(p: &Phys, th1: f64, th1d: f64, u: f64, mu: f64) -> ([f64; 4], f64) {
    let k = kkt5(p, th1, mu);
    let (h, _) = bias(p, th1, th1d);
    let r = s_vec() * u - h;
    let b = SVector::<f64, 5>::new(r[0], r[1], r[2], r[3], 0.0);
    let x = k.lu().solve(&b).unwrap_or_else(SVector::zeros);
    ([x[0], x[1], x[2], x[3]], x[4])
}

/// Generic `A, B` (Eqs. 30-31) by one KKT LU with two right-hand sides.
pub fn generic_control(p: &Phys, th1: f64, th1d: f64, mu: f64) -> [f64; 2] {
    let (_, _, ab, _) = generic_closed_loop(p, th1, th1d, mu, 0.0);
    ab
}

/// Generic `Y` (Eq. 28) with `M^-1` by fixed-size inversion.
pub fn generic_projection(p: &Phys, th1: f64, mu: f64) -> [f64; 16] {
    let m = mass_matrix(p, th1);
    let minv = m.try_inverse().unwrap_or_else(nalgebra::Matrix4::zeros);
    let j = j_stance(p.phi);
    let jh = j + j_mu(p.phi, mu);
    let d = (j * minv * jh.transpose())[0];
    let y = nalgebra::Matrix4::identity() - jh.transpose() * (j * minv) / d;
    let mut out = [0.0; 16];
    for r in 0..4 {
        for c in 0..4 {
            out[4 * r + c] = y[(r, c)];
        }
    }
    out
}

/// Generic impact with `R` constraint rows: one `(4 + R)`-square KKT solve (Eq. 1).
/// Writes `[lambda_I (R), qd+ (4)]` into `out`.
pub fn generic_impact<const R: usize, const NR: usize>(
    p: &Phys,
    rows: [nalgebra::RowVector4<f64>; R],
    th1: f64,
    qd: Vector4<f64>,
    out: &mut [f64],
) where
    nalgebra::Const<NR>: nalgebra::DimMin<nalgebra::Const<NR>, Output = nalgebra::Const<NR>>,
{
    let m = mass_matrix(p, th1);
    let mut k = SMatrix::<f64, NR, NR>::zeros();
    k.fixed_view_mut::<4, 4>(0, 0).copy_from(&m);
    for (r, row) in rows.iter().enumerate() {
        for i in 0..4 {
            k[(i, 4 + r)] = -row[i];
            k[(4 + r, i)] = row[i];
        }
    }
    let mq = m * qd;
    let mut b = SVector::<f64, NR>::zeros();
    for i in 0..4 {
        b[i] = mq[i];
    }
    let x = k.lu().solve(&b).unwrap_or_else(SVector::zeros);
    for r in 0..R {
        out[r] = x[4 + r];
    }
    for i in 0..4 {
        out[R + i] = x[i];
    }
}

/// Generic `impact2_level` (fore foot, torso lock).
pub fn generic_impact2_level(p: &Phys, th1: f64, qd: Vector4<f64>) -> [f64; 6] {
    let mut o = [0.0; 6];
    generic_impact::<2, 6>(p, [j_fore(p, th1), j_lock()], th1, qd, &mut o);
    o
}

/// Generic `impact3_level` (fore foot, rear foot, torso lock).
pub fn generic_impact3_level(p: &Phys, th1: f64, qd: Vector4<f64>) -> [f64; 7] {
    let mut o = [0.0; 7];
    generic_impact::<3, 7>(
        p,
        [j_fore(p, th1), j_stance(p.phi), j_lock()],
        th1,
        qd,
        &mut o,
    );
    o
}

/// Generic `impact_slope` (fore foot along the slope normal).
pub fn generic_impact_slope(p: &Phys, th1: f64, qd: Vector4<f64>) -> [f64; 5] {
    let mut o = [0.0; 5];
    generic_impact::<1, 5>(p, [j_fore(p, th1)], th1, qd, &mut o);
    o
}

/// Generic slope stance (`u = 0`): `(qdd, lambda)` from one KKT solve.
pub fn generic_accel_slope(p: &Phys, th1: f64, th1d: f64, mu: f64) -> ([f64; 4], f64) {
    generic_accel(p, th1, th1d, 0.0, mu)
}
