//! The stick phase by the generic path (not in the paper): the stance foot held, the ground
//! force resolved along the floor.

use crate::linear::solve;
use crate::matrices::{bias, mass_matrix, s_vec};
use crate::phys::Phys;
use nalgebra::{DMatrix, DVector, Vector4};

/// The stick KKT matrix `[[M, -J_p^T], [J_p, 0]]`, `J_p = d(x, z)/dq = [[1, 0, 0, 0],
/// [0, 1, 0, 0]]`: the foot's position held, whatever the floor (not in the paper).
#[must_use]
pub fn stick_kkt(p: &Phys, th1: f64) -> DMatrix<f64> {
    let m = mass_matrix(p, th1);
    let mut k = DMatrix::zeros(6, 6);
    k.view_mut((0, 0), (4, 4)).copy_from(&m);
    for c in 0..2 {
        k[(c, 4 + c)] = -1.0;
        k[(4 + c, c)] = 1.0;
    }
    k
}

/// The stick phase by the generic path.
#[derive(Debug, Clone)]
pub struct Stick {
    /// Accelerations (the first two are zero up to rounding).
    pub qdd: Vector4<f64>,
    /// `[lambda_t, lambda_n]`: the ground force along the floor's unit tangent
    /// `(cos phi, -sin phi)` and its unit normal `(sin phi, cos phi)`.
    pub lambda: [f64; 2],
    /// Error scale ([`Solved::scale`](crate::Solved::scale) of the KKT system; the rotation of the force into
    /// tangent and normal is orthogonal and adds a few roundings only).
    pub scale: f64,
    /// `cond_2` of the KKT matrix.
    pub cond: f64,
}

/// The ground force `F = (F_x, F_z)` on the foot resolved along the floor's unit tangent and
/// normal: `[F . (cos phi, -sin phi), F . (sin phi, cos phi)]`.
#[must_use]
pub fn resolve_on_floor(phi: f64, fx: f64, fz: f64) -> [f64; 2] {
    let (s, c) = phi.sin_cos();
    [fx * c - fz * s, fx * s + fz * c]
}

/// Solves the stick phase at `th1`, `th1d` with torque `u` (`u = 0` for the passive wheel).
///
/// # Errors
/// The KKT matrix is exactly singular.
pub fn stick(p: &Phys, th1: f64, th1d: f64, u: f64) -> Result<Stick, String> {
    let (h, habs) = bias(p, th1, th1d);
    let su = s_vec() * u;
    let mut b = DVector::zeros(6);
    let mut b_abs = DVector::zeros(6);
    for i in 0..4 {
        b[i] = su[i] - h[i];
        b_abs[i] = su[i].abs() + habs[i];
    }
    let sol = solve(&stick_kkt(p, th1), &b)?;
    Ok(Stick {
        qdd: Vector4::new(sol.x[0], sol.x[1], sol.x[2], sol.x[3]),
        lambda: resolve_on_floor(p.phi, sol.x[4], sol.x[5]),
        scale: sol.scale(&b_abs),
        cond: sol.cond,
    })
}
