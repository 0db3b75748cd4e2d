//! The walker's geometry and energies (Section 2.1, Fig. 1), and the equations of motion
//! `M(q) qddot + h(q, qdot)` derived from them by Euler-Lagrange.

use super::terms::{Q_SYMS, QD_SYMS, QDD_SYMS, cos, frac, int, sin, sym, time_derivative};
use crate::error::Result;
use crate::matrix::Matrix;
use crate::ratfunc::RatFunc;
use crate::symbol::Sym;

/// Positions and energies of the walker.
#[derive(Clone, Debug)]
pub struct Geometry {
    /// Hip position `(x_h, z_h)`.
    pub hip: [RatFunc; 2],
    /// Fore-leg end `(x_f, z_f)` (the spoke at `th1 - alpha`).
    pub fore_foot: [RatFunc; 2],
    /// Kinetic energy `T`.
    pub kinetic: RatFunc,
    /// Potential energy `V`.
    pub potential: RatFunc,
}

/// The walker's geometry and energies (Section 2.1, Fig. 1).
pub fn geometry() -> Result<Geometry> {
    let (x, z, l) = (sym(Sym::X), sym(Sym::Z), sym(Sym::L));
    let mt = sym(Sym::M1) + &sym(Sym::M2);
    let hip = [
        &x + &(&l * &sin(&[(Sym::Th1, 1)])?),
        &z + &(&l * &cos(&[(Sym::Th1, 1)])?),
    ];
    let fore_foot = [
        &hip[0] - &(&l * &sin(&[(Sym::Th1, 1), (Sym::Alpha, -1)])?),
        &hip[1] - &(&l * &cos(&[(Sym::Th1, 1), (Sym::Alpha, -1)])?),
    ];
    let vh = [time_derivative(&hip[0]), time_derivative(&hip[1])];
    let half = frac(1, 2);
    let kinetic = &half
        * &(&(&mt * &(&(&vh[0] * &vh[0]) + &(&vh[1] * &vh[1])))
            + &(&(&sym(Sym::I1) * &sym(Sym::Th1d)) * &sym(Sym::Th1d))
            + &(&(&sym(Sym::I2) * &sym(Sym::Th2d)) * &sym(Sym::Th2d)));
    let potential = &(&mt * &sym(Sym::G)) * &hip[1];
    Ok(Geometry {
        hip,
        fore_foot,
        kinetic,
        potential,
    })
}

/// The equations of motion in the form `M(q) qddot + h(q, qdot)` (Eqs. 2, 19, 20).
#[derive(Clone, Debug)]
pub struct Dynamics {
    /// The geometry it was derived from.
    pub geometry: Geometry,
    /// Inertia matrix `M(q)` (Eq. 2).
    pub mass: Matrix,
    /// Its inverse.
    pub mass_inv: Matrix,
    /// Coriolis, centrifugal and gravity terms `h(q, qdot)` (Eq. 20), a column.
    pub bias: Matrix,
    /// Input map `S` (Eq. 20), a column.
    pub input_map: Matrix,
}

/// Euler-Lagrange: `d/dt dL/dqdot - dL/dq = M qddot + h` with `L = T - V`.
pub fn dynamics() -> Result<Dynamics> {
    let geometry = geometry()?;
    let lagrangian = &geometry.kinetic - &geometry.potential;
    let mut mass = Matrix::zeros(4, 4);
    let mut bias = Vec::with_capacity(4);
    for i in 0..4 {
        let p = lagrangian.diff(QD_SYMS[i]);
        let el = &time_derivative(&p) - &lagrangian.diff(Q_SYMS[i]);
        let mut rest = el.clone();
        for (j, qdd) in QDD_SYMS.iter().enumerate() {
            let mij = el.diff(*qdd);
            rest = &rest - &(&mij * &sym(*qdd));
            mass.set(i, j, mij);
        }
        bias.push(rest);
    }
    let mass_inv = mass.inverse("M")?;
    let input_map = Matrix::column(vec![int(0), int(0), int(1), int(-1)]);
    Ok(Dynamics {
        geometry,
        mass,
        mass_inv,
        bias: Matrix::column(bias),
        input_map,
    })
}
