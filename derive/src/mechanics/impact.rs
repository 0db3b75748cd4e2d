//! Impact maps (Eqs. 1, 6-10; Eqs. 39-42 on the slope) and the substitutions that bring them
//! to the paper's closed forms: the impact posture and the paper's pre-impact state; and the
//! ingredients of the impact with Coulomb friction at the striking foot (not in the paper).

use super::dynamics::Dynamics;
use super::floor::{floor_gap, floor_tangent};
use super::terms::{Q_SYMS, QD_SYMS, frac, int, sym, tan_phi};
use crate::error::Result;
use crate::matrix::Matrix;
use crate::ratfunc::RatFunc;
use crate::symbol::{Atom, BaseAngle, Sym};
use crate::trig::sin_cos_combination;
use walker_scene::Floor;

/// Velocity constraints that can be active at an impact (Eqs. 3-5, 39-42).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImpactConstraint {
    /// The fore-leg end stops moving into the floor (Eq. 3; Eqs. 39-42 on the slope).
    ForeFoot,
    /// The rear foot stays on the floor (Eq. 4).
    RearFoot,
    /// The torso is locked to the wheel (Eq. 5).
    TorsoLock,
}

/// An impact map (Eqs. 1, 6-10).
#[derive(Clone, Debug)]
pub struct Impact {
    /// `J_I` (one row per constraint).
    pub jacobian: Matrix,
    /// `X_I = J_I M^-1 J_I^T`.
    pub x_i: Matrix,
    /// `lambda_I = -X_I^-1 J_I qdot-` (a column); the rows of `J_I` are unit normals, so the
    /// foot impulses are normal impulses (on the slope the paper's vertical impulse is this
    /// times `cos phi`).
    pub impulse: Matrix,
    /// `qdot+ = qdot- + M^-1 J_I^T lambda_I` (a column).
    pub velocity: Matrix,
}

/// Derives the impact map for a set of constraints (evaluated at the general `th1`; the paper
/// evaluates at `th1 = alpha/2`, or `alpha/2 + phi` on the slope).
pub fn impact(
    dynamics: &Dynamics,
    floor: Floor,
    constraints: &[ImpactConstraint],
) -> Result<Impact> {
    let g = &dynamics.geometry;
    let mut rows = Vec::new();
    for c in constraints {
        let f = match c {
            ImpactConstraint::ForeFoot => floor_gap(floor, &g.fore_foot[0], &g.fore_foot[1]),
            ImpactConstraint::RearFoot => floor_gap(floor, &sym(Sym::X), &sym(Sym::Z)),
            ImpactConstraint::TorsoLock => &sym(Sym::Th1) - &sym(Sym::Th2),
        };
        rows.push(f);
    }
    let jacobian = Matrix::jacobian(&rows, &Q_SYMS);
    let x_i = jacobian
        .mul(&dynamics.mass_inv)?
        .mul(&jacobian.transpose())?;
    let x_inv = x_i.inverse("X_I")?;
    let qd = Matrix::column(QD_SYMS.iter().map(|s| sym(*s)).collect());
    let impulse = x_inv.mul(&jacobian.mul(&qd)?)?.scale(&int(-1));
    let velocity = qd.add(
        &dynamics
            .mass_inv
            .mul(&jacobian.transpose())?
            .mul(&impulse)?,
    )?;
    Ok(Impact {
        jacobian,
        x_i,
        impulse,
        velocity,
    })
}

/// Substitutes the impact posture `th1 = alpha/2 + k phi` (`k = 0` level, `k = 1` slope).
pub fn at_impact_posture(f: &RatFunc, floor: Floor) -> Result<RatFunc> {
    // th1 = alpha/2 (+ phi): sin and cos of that combination of base angles.
    let combo: Vec<(BaseAngle, i64)> = match floor {
        Floor::Level => vec![(BaseAngle::HalfAlpha, 1)],
        Floor::Slope => vec![(BaseAngle::HalfAlpha, 1), (BaseAngle::Phi, 1)],
    };
    let (s, c) = sin_cos_combination(&combo);
    let f = f.substitute(Atom::Sin(BaseAngle::Th1), &s.into())?;
    let f = f.substitute(Atom::Cos(BaseAngle::Th1), &c.into())?;
    let th1 = match floor {
        Floor::Level => &sym(Sym::Alpha) * &frac(1, 2),
        Floor::Slope => &(&sym(Sym::Alpha) * &frac(1, 2)) + &sym(Sym::Phi),
    };
    f.substitute(Atom::Sym(Sym::Th1), &th1)
}

/// The pre-impact state the paper's closed forms assume: the torso locked (`th2d = th1d`) and
/// the stance foot not moving vertically (`zd = 0`, `zd = -xd tan phi` on the slope).
pub fn paper_pre_impact(f: &RatFunc, floor: Floor) -> Result<RatFunc> {
    let zd = match floor {
        Floor::Level => RatFunc::zero(),
        Floor::Slope => -(&sym(Sym::Xd) * &tan_phi()?),
    };
    let f = f.substitute(Atom::Sym(Sym::Zd), &zd)?;
    f.substitute(Atom::Sym(Sym::Th2d), &sym(Sym::Th1d))
}

/// The ingredients of an impact with Coulomb friction at the striking foot (not in the paper;
/// `docs/impacts.md`). The torso lock (level ground, Eq. 5) is bilateral and frictionless, so
/// it is applied first; the foot's impulse `Lambda = [Lambda_t, Lambda_n]` (along the unit
/// tangent and normal of the floor at the fore foot) then acts on the locked walker, and what
/// it must be is decided by the friction law at run time (Stronge's incremental model): the
/// post-impact velocity is `qdot+ = qdot_L + R Lambda`. For the double-support test the rear
/// foot's normal direction `r` is carried along.
#[derive(Clone, Debug)]
pub struct CoulombImpact {
    /// `qdot_L`: the velocities after the torso lock alone (a column; `qdot-` on the slope).
    pub locked_velocity: Matrix,
    /// `[v_t, v_n, v_r]` at `qdot_L`: the fore foot's tangential and normal velocity and the
    /// rear foot's normal velocity (a column).
    pub contact_velocity: Matrix,
    /// The Delassus matrix `W = J M_L^-1 J^T` over `(t, n, r)` (3x3, symmetric), `M_L^-1`
    /// the inverse mass matrix restricted to the lock.
    pub delassus: Matrix,
    /// `R = M_L^-1 [J_t; J_n]^T` (4x2): the velocity change per unit foot impulse.
    pub response: Matrix,
}

/// Derives [`CoulombImpact`] on `floor`, with the torso locked when `lock` (the active walker).
pub fn coulomb_impact(dynamics: &Dynamics, floor: Floor, lock: bool) -> Result<CoulombImpact> {
    let g = &dynamics.geometry;
    let (xf, zf) = (&g.fore_foot[0], &g.fore_foot[1]);
    let rows = [
        floor_tangent(floor, xf, zf),
        floor_gap(floor, xf, zf),
        floor_gap(floor, &sym(Sym::X), &sym(Sym::Z)),
    ];
    let j = Matrix::jacobian(&rows, &Q_SYMS);
    let qd = Matrix::column(QD_SYMS.iter().map(|s| sym(*s)).collect());
    let (mass_inv, locked_velocity) = if lock {
        let jl = Matrix::jacobian(&[&sym(Sym::Th1) - &sym(Sym::Th2)], &Q_SYMS);
        let m_jl = dynamics.mass_inv.mul(&jl.transpose())?;
        let x_l = jl.mul(&m_jl)?.inverse("X_L")?;
        let correction = m_jl.mul(&x_l)?;
        let mass_inv = dynamics
            .mass_inv
            .sub(&correction.mul(&jl.mul(&dynamics.mass_inv)?)?)?;
        let locked = qd.sub(&correction.mul(&jl.mul(&qd)?)?)?;
        (mass_inv, locked)
    } else {
        (dynamics.mass_inv.clone(), qd)
    };
    let contact_velocity = j.mul(&locked_velocity)?;
    let m_jt = mass_inv.mul(&j.transpose())?;
    let delassus = j.mul(&m_jt)?;
    let response = Matrix::from_rows(
        (0..4)
            .map(|i| vec![m_jt.get(i, 0).clone(), m_jt.get(i, 1).clone()])
            .collect(),
    )?;
    Ok(CoulombImpact {
        locked_velocity,
        contact_velocity,
        delassus,
        response,
    })
}
