//! Impacts by the generic path: Eq. 1 with its constraint rows as one linear system, and the
//! rows of each impact kernel.

use crate::linear::solve;
use crate::matrices::{j_fore, j_lock, j_rear, mass_matrix};
use crate::phys::Phys;
use nalgebra::{DMatrix, DVector, RowVector4, Vector4};

/// An impact by the generic path.
#[derive(Debug, Clone)]
pub struct Impact {
    /// Impulses, one per constraint row.
    pub lambda: Vec<f64>,
    /// Post-impact velocities (old coordinates).
    pub qd_plus: Vector4<f64>,
    /// Error scale ([`Solved::scale`](crate::Solved::scale) with `b_abs = [|M| |qd-|; 0]`).
    pub scale: f64,
    /// `cond_2` of the impact KKT matrix.
    pub cond: f64,
}

/// Solves Eq. 1 with the constraint rows `rows` as one linear system
/// `[[M, -J_I^T], [J_I, 0]] [qd+; lambda_I] = [M qd-; 0]`.
///
/// # Errors
/// The system is exactly singular.
pub fn impact(
    p: &Phys,
    rows: &[RowVector4<f64>],
    th1: f64,
    qd: Vector4<f64>,
) -> Result<Impact, String> {
    let m = mass_matrix(p, th1);
    let n = 4 + rows.len();
    let mut k = DMatrix::zeros(n, n);
    k.view_mut((0, 0), (4, 4)).copy_from(&m);
    for (r, row) in rows.iter().enumerate() {
        for i in 0..4 {
            k[(i, 4 + r)] = -row[i];
            k[(4 + r, i)] = row[i];
        }
    }
    let mq = m * qd;
    let mq_abs = m.abs() * qd.abs();
    let mut b = DVector::zeros(n);
    let mut b_abs = DVector::zeros(n);
    for i in 0..4 {
        b[i] = mq[i];
        b_abs[i] = mq_abs[i];
    }
    let sol = solve(&k, &b)?;
    Ok(Impact {
        lambda: (0..rows.len()).map(|r| sol.x[4 + r]).collect(),
        qd_plus: Vector4::new(sol.x[0], sol.x[1], sol.x[2], sol.x[3]),
        scale: sol.scale(&b_abs),
        cond: sol.cond,
    })
}

/// The constraint rows of the four impact kernels (docs/kernels.md), by kernel name.
#[must_use]
pub fn impact_rows(kernel: &str, p: &Phys, th1: f64) -> Vec<RowVector4<f64>> {
    match kernel {
        "impact3_level" => vec![j_fore(p, th1), j_rear(p), j_lock()],
        "impact2_level" => vec![j_fore(p, th1), j_lock()],
        "impact_slope" => vec![j_fore(p, th1)],
        "impact2_slope" => vec![j_fore(p, th1), j_rear(p)],
        _ => Vec::new(),
    }
}
