//! The ingredients of the impact with Coulomb friction at the fore foot (not in the paper) by
//! the generic path: the contact rows written out from the feet's positions, the torso lock
//! (level ground) and `M_L^-1` applied by KKT solves, never by the closed forms.

use crate::impact::impact;
use crate::linear::solve;
use crate::matrices::{j_lock, mass_matrix};
use crate::phys::Phys;
use nalgebra::{DMatrix, DVector, Matrix3, Matrix4x2, RowVector4, Vector3, Vector4};

/// The generic values of `impact_coulomb_level` / `impact_coulomb_slope` with error scales.
#[derive(Debug, Clone)]
pub struct CoulombIngredients {
    /// `qdl`: velocities after the torso lock (`qd-` without it).
    pub qdl: Vector4<f64>,
    /// `[v_t, v_n, v_r]` at `qdl`.
    pub v: Vector3<f64>,
    /// The Delassus matrix `W = J M_L^-1 J^T` over `(t, n, r)`.
    pub w: Matrix3<f64>,
    /// `R = M_L^-1 [J_t; J_n]^T`.
    pub r: Matrix4x2<f64>,
    /// Error scale of `qdl` ([`crate::Impact::scale`] of the lock, `||qd-||` without it: exact).
    pub scale_qdl: f64,
    /// Error scale of `v`: `||J|| (scale_qdl + ||qdl||)` (the product's rounding is within the
    /// second term).
    pub scale_v: f64,
    /// Error scale of `R` (the columns `M_L^-1 J^T` from KKT solves, the largest
    /// [`crate::Solved::scale`] with `b_abs = |J^T col|`).
    pub scale_r: f64,
    /// Error scale of `W = J X`: `||J|| (scale_r' + ||X||)`, `scale_r'` over all three columns.
    pub scale_w: f64,
}

/// The contact rows `(t, n, r)`: the fore foot's velocity along the floor's unit tangent
/// `(cos phi, -sin phi)` and unit normal `(sin phi, cos phi)`, and the rear (stance) foot's
/// along the normal, each the foot's Cartesian Jacobian `d(x_p, z_p)/dq` projected.
#[must_use]
pub fn contact_rows(p: &Phys, th1: f64) -> [RowVector4<f64>; 3] {
    // Fore foot (x + l sin th1 - l sin(th1 - alpha), z + l cos th1 - l cos(th1 - alpha)).
    let dx = RowVector4::new(1.0, 0.0, p.l * (th1.cos() - (th1 - p.alpha).cos()), 0.0);
    let dz = RowVector4::new(0.0, 1.0, p.l * ((th1 - p.alpha).sin() - th1.sin()), 0.0);
    let (sp, cp) = p.phi.sin_cos();
    [
        dx * cp - dz * sp,
        dx * sp + dz * cp,
        RowVector4::new(sp, cp, 0.0, 0.0),
    ]
}

/// The generic ingredients at `th1`, `qd-`, with the torso locked when `lock` (level ground).
///
/// # Errors
/// A KKT system is exactly singular.
pub fn coulomb_ingredients(
    p: &Phys,
    th1: f64,
    qd: Vector4<f64>,
    lock: bool,
) -> Result<CoulombIngredients, String> {
    let m = mass_matrix(p, th1);
    let rows = contact_rows(p, th1);
    let (qdl, scale_qdl) = if lock {
        let imp = impact(p, &[j_lock()], th1, qd)?;
        (imp.qd_plus, imp.scale)
    } else {
        (qd, 0.0)
    };
    // M_L^-1 b by [[M, -j^T], [j, 0]] [x; l] = [b; 0] (lock) or M x = b.
    let n = if lock { 5 } else { 4 };
    let mut k = DMatrix::zeros(n, n);
    k.view_mut((0, 0), (4, 4)).copy_from(&m);
    if lock {
        let jl = j_lock();
        for i in 0..4 {
            k[(i, 4)] = -jl[i];
            k[(4, i)] = jl[i];
        }
    }
    let mut x = nalgebra::Matrix4x3::zeros();
    let mut scale_x: f64 = 0.0;
    for (c, row) in rows.iter().enumerate() {
        let mut b = DVector::zeros(n);
        let mut b_abs = DVector::zeros(n);
        for i in 0..4 {
            b[i] = row[i];
            b_abs[i] = row[i].abs();
        }
        let sol = solve(&k, &b)?;
        for i in 0..4 {
            x[(i, c)] = sol.x[i];
        }
        scale_x = scale_x.max(sol.scale(&b_abs));
    }
    let j = nalgebra::Matrix3x4::from_rows(&rows);
    let j_norm = j.norm();
    let w = j * x;
    let r = x.fixed_columns::<2>(0).into_owned();
    Ok(CoulombIngredients {
        qdl,
        v: j * qdl,
        w,
        r,
        scale_qdl,
        scale_v: j_norm * (scale_qdl + qdl.norm()),
        scale_r: scale_x,
        scale_w: j_norm * (scale_x + x.norm()),
    })
}

/// The 21 outputs in the kernels' order (`qdl0..3, v_t, v_n, v_r, W_tt, W_tn, W_tr, W_nn,
/// W_nr, W_rr, R00, R01, .., R31`) and their error scales.
#[must_use]
pub fn coulomb_outputs(c: &CoulombIngredients) -> (Vec<f64>, Vec<f64>) {
    let mut v: Vec<f64> = c.qdl.iter().copied().collect();
    let mut s = vec![c.scale_qdl.max(c.qdl.norm() * f64::EPSILON); 4];
    v.extend(c.v.iter());
    s.extend([c.scale_v; 3]);
    for (i, jj) in [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)] {
        v.push(c.w[(i, jj)]);
        s.push(c.scale_w);
    }
    for i in 0..4 {
        for jj in 0..2 {
            v.push(c.r[(i, jj)]);
            s.push(c.scale_r);
        }
    }
    (v, s)
}
