//! The closed loops by the generic path (Eq. 31 sliding, and its stick counterpart): the
//! [`Contact`] the foot makes and three KKT solves.

use crate::linear::solve;
use crate::matrices::{bias, s_vec};
use crate::phys::Phys;
use crate::stance::stance_kkt;
use crate::stick::{resolve_on_floor, stick_kkt};
use nalgebra::{DMatrix, DVector, Vector4};

/// Which contact the foot makes: sliding with friction coefficient `mu` (one constraint row,
/// Eqs. 19, 21-24, 36-38) or stuck (two rows, see [`stick_kkt`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Contact {
    /// Sliding, `mu` the friction coefficient with its direction (Eq. 24).
    Slide(f64),
    /// Stuck (the stick phase of Coulomb friction; not in the paper).
    Stick,
}

impl Contact {
    /// The KKT matrix of the contact.
    #[must_use]
    pub fn kkt(self, p: &Phys, th1: f64) -> DMatrix<f64> {
        match self {
            Contact::Slide(mu) => stance_kkt(p, th1, mu),
            Contact::Stick => stick_kkt(p, th1),
        }
    }
}

/// A closed loop (Eq. 31 and its stick counterpart) by the generic path.
#[derive(Debug, Clone)]
pub struct ClosedLoop {
    /// `A`, `B` with `yddot = A u - B` (Eq. 30).
    pub a: f64,
    /// See `a`.
    pub b: f64,
    /// `u = (v + B) / A` (Eq. 31).
    pub u: f64,
    /// Accelerations at that `u`.
    pub qdd: Vector4<f64>,
    /// The multipliers at that `u`: for sliding the one reaction `lambda` (vertical, Eqs.
    /// 22-23, as [`stance_kkt`] scales its row); for sticking `[lambda_t, lambda_n]` (the
    /// Cartesian force resolved by [`resolve_on_floor`]).
    pub lambda: Vec<f64>,
    /// Error scale of `u`: `(|v| + s_B + |u| s_A) / |A|` with `s_A`, `s_B` the error scales of
    /// `A`, `B` (`||S|| Solved::scale` of their systems): first-order propagation through
    /// `u = (v + B) / A`, the `|v|` for the rounding of `v + B`.
    pub scale_u: f64,
    /// Error scale of `qdd` and the multipliers: [`Solved::scale`](crate::Solved::scale) of the system at `u`, plus
    /// `||x_S|| scale_u`, `x_S` the solution for `[S; 0]` (how an error of `u` moves them).
    pub scale: f64,
    /// `cond_2` of the KKT matrix.
    pub cond: f64,
}

/// Solves the closed loop with auxiliary input `v` for a contact: `A`, `B` by two KKT solves,
/// `u = (v + B) / A`, then the KKT system at that `u`.
///
/// # Errors
/// The KKT matrix is exactly singular.
pub fn closed_loop(
    p: &Phys,
    th1: f64,
    th1d: f64,
    v: f64,
    contact: Contact,
) -> Result<ClosedLoop, String> {
    let k = contact.kkt(p, th1);
    let n = k.nrows();
    let (h, habs) = bias(p, th1, th1d);
    let s = s_vec();
    let mut rs = DVector::zeros(n);
    let mut rh = DVector::zeros(n);
    let mut rh_abs = DVector::zeros(n);
    for i in 0..4 {
        rs[i] = s[i];
        rh[i] = h[i];
        rh_abs[i] = habs[i];
    }
    let xs = solve(&k, &rs)?;
    let xh = solve(&k, &rh)?;
    let ydd = |x: &DVector<f64>| x[2] - x[3];
    let (a, b) = (ydd(&xs.x), ydd(&xh.x));
    let n_s = s.norm();
    let (sa, sb) = (n_s * xs.scale(&rs.abs()), n_s * xh.scale(&rh_abs));
    let u = (v + b) / a;
    let scale_u = (v.abs() + sb + u.abs() * sa) / a.abs();
    let mut r = DVector::zeros(n);
    let mut r_abs = DVector::zeros(n);
    for i in 0..4 {
        r[i] = s[i] * u - h[i];
        r_abs[i] = (s[i] * u).abs() + habs[i];
    }
    let sol = solve(&k, &r)?;
    let lambda = match contact {
        Contact::Slide(_) => vec![sol.x[4]],
        Contact::Stick => resolve_on_floor(p.phi, sol.x[4], sol.x[5]).to_vec(),
    };
    Ok(ClosedLoop {
        a,
        b,
        u,
        qdd: Vector4::new(sol.x[0], sol.x[1], sol.x[2], sol.x[3]),
        lambda,
        scale_u,
        scale: sol.scale(&r_abs) + xs.x.norm() * scale_u,
        cond: sol.cond,
    })
}
