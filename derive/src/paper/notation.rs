//! The paper's notation as expressions of its symbol table ([`Symbols::paper`]): the coordinate
//! symbols `q`, `qdot`, `qddot`, constants, `sin(alpha/2)`, `tan(phi)`, the total time
//! derivative along the motion, and the total mass `m_t` and inertia `I_t`.
//!
//! [`Symbols::paper`]: crate::symbol::Symbols::paper

use crate::error::Result;
use crate::poly::Q;
use crate::ratfunc::RatFunc;
use crate::symbol::{BaseAngle, Sym};

/// The generalized coordinates `q = [x, z, th1, th2]` (Section 2.2).
pub const Q_SYMS: [Sym; 4] = [Sym::X, Sym::Z, Sym::Th1, Sym::Th2];
/// The generalized velocities.
pub const QD_SYMS: [Sym; 4] = [Sym::Xd, Sym::Zd, Sym::Th1d, Sym::Th2d];
/// The generalized accelerations.
pub const QDD_SYMS: [Sym; 4] = [Sym::Xdd, Sym::Zdd, Sym::Th1dd, Sym::Th2dd];

/// A symbol as a rational function.
pub fn sym(s: Sym) -> RatFunc {
    RatFunc::sym(s)
}

/// An integer.
pub fn int(n: i64) -> RatFunc {
    RatFunc::int(n)
}

/// A rational constant `n / d`.
pub fn frac(n: i64, d: i64) -> RatFunc {
    RatFunc::constant(Q::new(n.into(), d.into()))
}

/// `sin(alpha / 2)`.
pub fn sin_half_alpha() -> RatFunc {
    RatFunc::sin_of(BaseAngle::HalfAlpha)
}

/// `tan(phi)`.
pub fn tan_phi() -> Result<RatFunc> {
    RatFunc::sin_of(BaseAngle::Phi).div(&RatFunc::cos_of(BaseAngle::Phi))
}

/// Total time derivative along the motion: `sum dF/dq qdot + dF/dqdot qddot`.
pub fn time_derivative(f: &RatFunc) -> RatFunc {
    let mut acc = RatFunc::zero();
    for (q, qd) in Q_SYMS.iter().zip(QD_SYMS.iter()) {
        acc = acc + &(f.diff(*q) * sym(*qd));
    }
    for (qd, qdd) in QD_SYMS.iter().zip(QDD_SYMS.iter()) {
        acc = acc + &(f.diff(*qd) * sym(*qdd));
    }
    acc
}

/// `m_t = m1 + m2`.
pub fn total_mass() -> RatFunc {
    sym(Sym::M1) + &sym(Sym::M2)
}

/// `I_t = I1 + I2`.
pub fn total_inertia() -> RatFunc {
    sym(Sym::I1) + &sym(Sym::I2)
}
