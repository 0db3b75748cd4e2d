//! Positions, energies and momenta of the walker: the fore foot, `T` and `V`, the hip, the
//! angular momentum about a point.

use crate::matrices::mass_matrix;
use crate::phys::Phys;
use nalgebra::Vector4;

/// Fore-foot position and velocity `[x_f, z_f, xd_f, zd_f]` (docs/kernels.md) and their
/// absolute-value evaluation (the rounding of `th1 - alpha` enters through `|th1| + |alpha|`).
#[must_use]
pub fn fore_foot(
    p: &Phys,
    x: f64,
    z: f64,
    th1: f64,
    xd: f64,
    zd: f64,
    th1d: f64,
) -> ([f64; 4], [f64; 4]) {
    let (s, c) = th1.sin_cos();
    let (sa, ca) = (th1 - p.alpha).sin_cos();
    let l = p.l;
    let v = [
        x + l * s - l * sa,
        z + l * c - l * ca,
        xd + l * c * th1d - l * ca * th1d,
        zd - l * s * th1d + l * sa * th1d,
    ];
    let arg = 1.0 + th1.abs() + p.alpha.abs();
    let a = [
        x.abs() + l * (1.0 + arg),
        z.abs() + l * (1.0 + arg),
        xd.abs() + l * th1d.abs() * (1.0 + arg),
        zd.abs() + l * th1d.abs() * (1.0 + arg),
    ];
    (v, a)
}

/// Kinetic and potential energy `[T, V]` (docs/kernels.md) as `T = 1/2 qd^T M qd`,
/// `V = m_t g (z + l cos th1)`, with their absolute-value evaluations.
#[must_use]
pub fn energy(p: &Phys, z: f64, th1: f64, qd: Vector4<f64>) -> ([f64; 2], [f64; 2]) {
    let m = mass_matrix(p, th1);
    let t = 0.5 * (qd.transpose() * m * qd)[0];
    let t_abs = 0.5 * (qd.abs().transpose() * m.abs() * qd.abs())[0];
    let mt = p.mt();
    let c = th1.cos();
    let v = mt * p.g * (z + p.l * c);
    let v_abs = mt * p.g * (z.abs() + p.l * c.abs());
    ([t, v], [t_abs, v_abs])
}

/// Horizontal position of the hip and the centre of mass of the whole walker.
#[must_use]
pub fn hip(p: &Phys, x: f64, z: f64, th1: f64) -> (f64, f64) {
    (x + p.l * th1.sin(), z + p.l * th1.cos())
}

/// Angular momentum of the walker about the point `(px, pz)` (sense of positive `th1`):
/// `m_t ((z_h - pz) xd_h - (x_h - px) zd_h) + I1 th1d + I2 th2d`.
#[must_use]
pub fn angular_momentum(p: &Phys, q: Vector4<f64>, qd: Vector4<f64>, px: f64, pz: f64) -> f64 {
    let (xh, zh) = hip(p, q[0], q[1], q[2]);
    let (s, c) = q[2].sin_cos();
    let xdh = qd[0] + p.l * c * qd[2];
    let zdh = qd[1] - p.l * s * qd[2];
    p.mt() * ((zh - pz) * xdh - (xh - px) * zdh) + p.i1 * qd[2] + p.i2 * qd[3]
}
