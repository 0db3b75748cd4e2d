//! The paper's matrices written out: the input vector `S`, the inertia matrix `M`, the bias
//! `h`, the stance and friction Jacobians `J`, `J_mu` and the impact constraint rows.

use crate::phys::Phys;
use nalgebra::{Matrix4, RowVector4, Vector4};

/// The input vector `S = [0, 0, 1, -1]` (Eq. 20).
#[must_use]
pub fn s_vec() -> Vector4<f64> {
    Vector4::new(0.0, 0.0, 1.0, -1.0)
}

/// Inertia matrix `M(q)` of Eq. 2.
#[must_use]
pub fn mass_matrix(p: &Phys, th1: f64) -> Matrix4<f64> {
    let mt = p.mt();
    let (s, c) = th1.sin_cos();
    Matrix4::new(
        mt,
        0.0,
        mt * p.l * c,
        0.0,
        0.0,
        mt,
        -mt * p.l * s,
        0.0,
        mt * p.l * c,
        -mt * p.l * s,
        mt * p.l * p.l + p.i1,
        0.0,
        0.0,
        0.0,
        0.0,
        p.i2,
    )
}

/// `h(q, qd)` of Eq. 20 and its absolute-value evaluation (every term replaced by its
/// magnitude), the error scale of a direct evaluation.
#[must_use]
pub fn bias(p: &Phys, th1: f64, th1d: f64) -> (Vector4<f64>, Vector4<f64>) {
    let mt = p.mt();
    let (s, c) = th1.sin_cos();
    let w2 = th1d * th1d;
    let h = Vector4::new(
        -mt * p.l * w2 * s,
        mt * (p.g - p.l * w2 * c),
        -mt * p.g * p.l * s,
        0.0,
    );
    let habs = Vector4::new(
        mt * p.l * w2 * s.abs(),
        mt * (p.g + p.l * w2 * c.abs()),
        mt * p.g * p.l * s.abs(),
        0.0,
    );
    (h, habs)
}

/// Stance constraint `J = [tan phi, 1, 0, 0]` (Eqs. 21, 36).
#[must_use]
pub fn j_stance(phi: f64) -> RowVector4<f64> {
    RowVector4::new(phi.tan(), 1.0, 0.0, 0.0)
}

/// Friction Jacobian `J_mu = [mu, -mu tan phi, 0, 0]` (Eqs. 24, 38).
#[must_use]
pub fn j_mu(phi: f64, mu: f64) -> RowVector4<f64> {
    RowVector4::new(mu, -mu * phi.tan(), 0.0, 0.0)
}

/// Fore-foot impact row: normal velocity of the fore foot on the floor (Eq. 3 on level ground,
/// Eq. 42 on the slope): `[tan phi, 1, l (sin(phi - th1) - sin(phi - th1 + alpha)) / cos phi, 0]`.
#[must_use]
pub fn j_fore(p: &Phys, th1: f64) -> RowVector4<f64> {
    let a = p.l * ((p.phi - th1).sin() - (p.phi - th1 + p.alpha).sin()) / p.phi.cos();
    RowVector4::new(p.phi.tan(), 1.0, a, 0.0)
}

/// Rear-foot impact row (Eq. 4, and the slope's rear foot of Eq. 46): the stance constraint.
#[must_use]
pub fn j_rear(p: &Phys) -> RowVector4<f64> {
    j_stance(p.phi)
}

/// Torso lock row `th1d - th2d = 0` (Eq. 5).
#[must_use]
pub fn j_lock() -> RowVector4<f64> {
    RowVector4::new(0.0, 0.0, 1.0, -1.0)
}
