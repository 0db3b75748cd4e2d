//! The sliding stance by the generic path: the stance KKT system, its solution, Eq. 22's
//! reaction, the projection `Y` and the control terms `A`, `B`.

use crate::linear::solve;
use crate::matrices::{bias, j_mu, j_stance, mass_matrix, s_vec};
use crate::phys::Phys;
use nalgebra::{DMatrix, DVector, Matrix4, Vector4};

/// The stance KKT matrix `[[M, -Jhat^T], [J, 0]]` with `Jhat = J + J_mu`.
#[must_use]
pub fn stance_kkt(p: &Phys, th1: f64, mu: f64) -> DMatrix<f64> {
    let m = mass_matrix(p, th1);
    let j = j_stance(p.phi);
    let jh = j + j_mu(p.phi, mu);
    let mut k = DMatrix::zeros(5, 5);
    k.view_mut((0, 0), (4, 4)).copy_from(&m);
    for i in 0..4 {
        k[(i, 4)] = -jh[i];
        k[(4, i)] = j[i];
    }
    k
}

/// Stance dynamics by the generic path.
#[derive(Debug, Clone)]
pub struct Stance {
    /// Accelerations `qdd` (Eq. 27), from the KKT solve.
    pub qdd: Vector4<f64>,
    /// Vertical reaction `lambda` from the same KKT solve.
    pub lambda_kkt: f64,
    /// `lambda` by Eq. 22 (`M^-1` applied by LU).
    pub lambda_eq22: f64,
    /// Error scale of `qdd` and `lambda` ([`Solved::scale`](crate::Solved::scale) of the KKT system).
    pub scale: f64,
    /// `cond_2` of the KKT matrix.
    pub cond: f64,
}

/// Solves the stance dynamics (Eq. 19 with Eq. 21/36) at `q = (., ., th1, .)`, `th1d`, `u`,
/// `mu`.
///
/// # Errors
/// The KKT matrix or `M` is exactly singular.
pub fn stance(p: &Phys, th1: f64, th1d: f64, u: f64, mu: f64) -> Result<Stance, String> {
    let (h, habs) = bias(p, th1, th1d);
    let su = s_vec() * u;
    let r = su - h;
    let k = stance_kkt(p, th1, mu);
    let mut b = DVector::zeros(5);
    let mut b_abs = DVector::zeros(5);
    for i in 0..4 {
        b[i] = r[i];
        b_abs[i] = su[i].abs() + habs[i];
    }
    let sol = solve(&k, &b)?;
    // Eq. 22: lambda = -J M^-1 (S u - h) / (J M^-1 Jhat^T).
    let m = mass_matrix(p, th1);
    let lu = m.lu();
    let j = j_stance(p.phi);
    let jh = j + j_mu(p.phi, mu);
    let minv_r = lu.solve(&r).ok_or("singular M")?;
    let minv_jh = lu.solve(&jh.transpose()).ok_or("singular M")?;
    let lambda_eq22 = -(j * minv_r)[0] / (j * minv_jh)[0];
    Ok(Stance {
        qdd: Vector4::new(sol.x[0], sol.x[1], sol.x[2], sol.x[3]),
        lambda_kkt: sol.x[4],
        lambda_eq22,
        scale: sol.scale(&b_abs),
        cond: sol.cond,
    })
}

/// `Y` of Eq. 28 (with `M.try_inverse()`) and its error scale `cond(K) max(1, ||Y||_2)`, `K`
/// the stance KKT matrix: `Y` is a rational function of `M`, `J`, `Jhat` whose only
/// denominator is the Schur complement `J M^-1 Jhat^T` of `K`, so its relative sensitivity to
/// relative perturbations of the data is bounded by `cond(K)` (up to a modest factor).
///
/// # Errors
/// `M` or the Schur complement is singular.
pub fn projection(p: &Phys, th1: f64, mu: f64) -> Result<(Matrix4<f64>, f64), String> {
    let m = mass_matrix(p, th1);
    let minv = m.try_inverse().ok_or("singular M")?;
    let j = j_stance(p.phi);
    let jh = j + j_mu(p.phi, mu);
    let d = (j * minv * jh.transpose())[0];
    if d == 0.0 {
        return Err("singular Schur complement".into());
    }
    let y = Matrix4::identity() - jh.transpose() * (j * minv) / d;
    let cond = solve(&stance_kkt(p, th1, mu), &DVector::zeros(5))?.cond;
    Ok((y, cond * y.norm().max(1.0)))
}

/// `A` and `B` of Eqs. 30-31 (`A = S^T M^-1 Y S`, `B = S^T M^-1 Y h`, from Eq. 28's `Y`), with
/// their error scales. `A` (`B`) is `S^T` times the KKT solution for the right-hand side `[S; 0]`
/// (`[h; 0]`), so the scales are `||S|| * Solved::scale` of those systems.
///
/// # Errors
/// `M` or the KKT matrix is singular.
pub fn control(p: &Phys, th1: f64, th1d: f64, mu: f64) -> Result<[f64; 4], String> {
    let m = mass_matrix(p, th1);
    let minv = m.try_inverse().ok_or("singular M")?;
    let (y, _) = projection(p, th1, mu)?;
    let (h, habs) = bias(p, th1, th1d);
    let s = s_vec();
    let a = (s.transpose() * minv * y * s)[0];
    let bb = (s.transpose() * minv * y * h)[0];
    let k = stance_kkt(p, th1, mu);
    let mut rs = DVector::zeros(5);
    let mut rh = DVector::zeros(5);
    let mut rh_abs = DVector::zeros(5);
    for i in 0..4 {
        rs[i] = s[i];
        rh[i] = h[i];
        rh_abs[i] = habs[i];
    }
    let sa = solve(&k, &rs)?;
    let sb = solve(&k, &rh)?;
    let rs_abs = rs.abs();
    let n_s = s.norm();
    Ok([a, bb, n_s * sa.scale(&rs_abs), n_s * sb.scale(&rh_abs)])
}
