//! The phases of any model: the sliding stance with its friction (Eqs. 19-29), the stuck foot,
//! the output-following control with several outputs (Eqs. 30-31), and the impact maps at the
//! strike with the model's locks, with and without the old stance foot held (Eqs. 1, 6-16,
//! 39-46).

use walker_scene::model::Model;

use super::mechanics::Mechanics;
use crate::error::Result;
use crate::matrix::Matrix;
use crate::ratfunc::RatFunc;

/// The sliding stance: `M qdd + h = S u + (J + J_mu)^T lambda_n`, `J qdd = 0`.
#[derive(Clone, Debug)]
pub struct Sliding {
    /// The normal force `lambda_n`, the multiplier of the unit-normal constraint.
    pub normal_force: RatFunc,
    /// The vertical ground reaction, `lambda_n cos phi` (the paper's `lambda`, Eqs. 22-23 and
    /// Section 5.1).
    pub lambda: RatFunc,
    /// The denominator `J M^-1 (J + J_mu)^T` of the normal force (Eq. 22).
    pub lambda_den: RatFunc,
    /// `Y = I - (J + J_mu)^T J M^-1 / den` (Eqs. 28-29).
    pub projection: Matrix,
    /// `qdd` (Eq. 27), a column.
    pub accel: Matrix,
}

/// Derives the sliding stance of a model.
///
/// # Errors
/// An arithmetic error (a denominator that vanishes identically).
pub fn sliding(m: &Mechanics) -> Result<Sliding> {
    let n = m.syms.q.len();
    let jhat = m.contact.add(&m.friction)?;
    let j_minv = m.contact.mul(m.mass_inv()?)?;
    let su_minus_h = m.input_force.sub(&m.bias)?;
    let lambda_den = j_minv.mul(&jhat.transpose())?.scalar()?;
    let normal_force = (-j_minv.mul(&su_minus_h)?.scalar()?).div(&lambda_den)?;
    let forces = su_minus_h.add(&jhat.transpose().scale(&normal_force))?;
    let lambda = &normal_force * m.contact.get(0, 1);
    let accel = m.mass_inv()?.mul(&forces)?;
    let projection =
        Matrix::identity(n).sub(&jhat.transpose().mul(&j_minv)?.scale(&lambda_den.recip()?))?;
    Ok(Sliding {
        normal_force,
        lambda,
        lambda_den,
        projection,
        accel,
    })
}

/// A model's controlled outputs `y = h(q)`, their Jacobian `H = dh/dq` and the drift
/// `Hdot qdot` (`yddot = H qdd + Hdot qdot`).
#[derive(Clone, Debug)]
pub struct OutputMaps {
    /// `y`, one per output.
    pub y: Vec<RatFunc>,
    /// `H`, outputs x coordinates.
    pub jacobian: Matrix,
    /// `Hdot qdot = sum_j d(H qdot)/dq_j qdot_j`, one per output.
    pub drift: Vec<RatFunc>,
}

/// The outputs of `model` with their Jacobian and drift.
///
/// # Errors
/// An output expression that does not lower.
pub fn output_maps(m: &Mechanics, model: &Model) -> Result<OutputMaps> {
    let y = model
        .outputs
        .iter()
        .map(|o| m.syms.lower(&o.h))
        .collect::<Result<Vec<_>>>()?;
    let jacobian = Matrix::jacobian(&y, &m.syms.q);
    let hq = jacobian.mul(&m.qd_column())?;
    let drift = (0..y.len())
        .map(|i| {
            m.syms
                .q
                .iter()
                .zip(&m.syms.qd)
                .fold(RatFunc::zero(), |acc, (q, qd)| {
                    acc + &(hq.get(i, 0).diff(*q) * RatFunc::sym(*qd))
                })
        })
        .collect();
    Ok(OutputMaps { y, jacobian, drift })
}

/// The output-following control (Section 3.2) with `m` outputs and `m` inputs:
/// `yddot = A u - B`, `u = A^-1 (v + B)`.
#[derive(Clone, Debug)]
pub struct OutputControl {
    /// `H = dh/dq`, m x n.
    pub output_jacobian: Matrix,
    /// `A = H M^-1 Y S`, m x m.
    pub a: Matrix,
    /// `B = H M^-1 Y h - Hdot qdot`, a column (`Hdot = 0` for outputs linear in `q`, as the
    /// paper's `y = S^T q`).
    pub b: Matrix,
    /// `u = A^-1 (v + B)`, a column.
    pub u: Matrix,
}

/// Derives the control terms for a projection `Y` with `M qdd = Y (S u - h)`.
///
/// # Errors
/// A model without outputs, or `A` singular identically (the outputs are not independent
/// through the inputs).
pub fn output_control(m: &Mechanics, model: &Model, projection: &Matrix) -> Result<OutputControl> {
    let OutputMaps {
        jacobian: h_jac,
        drift,
        ..
    } = output_maps(m, model)?;
    let h_minv_y = h_jac.mul(m.mass_inv()?)?.mul(projection)?;
    let a = h_minv_y.mul(&m.input_map)?;
    let b = h_minv_y.mul(&m.bias)?.sub(&Matrix::column(drift))?;
    let v = Matrix::column(m.syms.aux.iter().map(|s| RatFunc::sym(*s)).collect());
    let u = a.inverse("A")?.mul(&v.add(&b)?)?;
    Ok(OutputControl {
        output_jacobian: h_jac,
        a,
        b,
        u,
    })
}

/// The stance foot stuck to the floor: both foot coordinates held.
#[derive(Clone, Debug)]
pub struct Stuck {
    /// `J_s`: the gradients of the foot's coordinate along the floor and of its gap.
    pub jacobian: Matrix,
    /// `[lambda_t, lambda_n]`, a column.
    pub forces: Matrix,
    /// `qdd`, a column (`xdd = zdd = 0`).
    pub accel: Matrix,
}

/// Derives the stuck stance by blocks: the foot coordinates `x`, `z` are held, so the other
/// coordinates obey their own block, `M_aa qdd_a = (S u - h)_a`, and the foot's rows give the
/// force the floor exerts, `J_f^T lambda = M_fa qdd_a - (S u - h)_f`, where `J_f` (the foot block
/// of `J_s`, the unit tangent and normal of the floor) is orthogonal, so `lambda = J_f (...)`.
/// The same as `M qdd + h = S u + J_s^T lambda`, `J_s qdd = 0` solved through `M^-1`, without
/// the full inverse (whose products are what makes larger models slow).
///
/// # Errors
/// An arithmetic error, or `M_aa` singular.
pub fn stuck(m: &Mechanics) -> Result<Stuck> {
    let n = m.syms.q.len();
    let (x, z) = (RatFunc::sym(m.syms.q[0]), RatFunc::sym(m.syms.q[1]));
    let jacobian = Matrix::jacobian(&[m.floor.tangent(&x, &z), m.floor.gap(&x, &z)], &m.syms.q);
    let rhs = m.input_force.sub(&m.bias)?;
    let block = |rows: std::ops::Range<usize>, cols: std::ops::Range<usize>| {
        Matrix::from_rows(
            rows.map(|i| cols.clone().map(|j| m.mass.get(i, j).clone()).collect())
                .collect(),
        )
    };
    let m_aa = block(2..n, 2..n)?;
    let m_fa = block(0..2, 2..n)?;
    let rhs_a = Matrix::column((2..n).map(|i| rhs.get(i, 0).clone()).collect());
    let rhs_f = Matrix::column((0..2).map(|i| rhs.get(i, 0).clone()).collect());
    let qdd_a = m_aa.inverse("M_aa")?.mul(&rhs_a)?;
    let j_f = Matrix::from_rows(
        (0..2)
            .map(|i| (0..2).map(|j| jacobian.get(i, j).clone()).collect())
            .collect(),
    )?;
    let forces = j_f.mul(&m_fa.mul(&qdd_a)?.sub(&rhs_f)?)?;
    let accel = Matrix::column(
        [RatFunc::zero(), RatFunc::zero()]
            .into_iter()
            .chain(qdd_a.entries().iter().cloned())
            .collect(),
    );
    Ok(Stuck {
        jacobian,
        forces,
        accel,
    })
}

/// A frictionless impact map: the constraint rows, their impulses and `qdot+`.
#[derive(Clone, Debug)]
pub struct ImpactMap {
    /// `J_I`, one row per constraint.
    pub jacobian: Matrix,
    /// `lambda_I = -(J_I M^-1 J_I^T)^-1 J_I qdot-`, a column.
    pub impulse: Matrix,
    /// `qdot+ = qdot- + M^-1 J_I^T lambda_I`, a column.
    pub velocity: Matrix,
}

/// The impact map for constraint functions `rows` of `q` (their rates are set to zero).
///
/// # Errors
/// Dependent constraints (`J_I M^-1 J_I^T` singular).
pub fn impact_map(m: &Mechanics, rows: &[RatFunc]) -> Result<ImpactMap> {
    let jacobian = Matrix::jacobian(rows, &m.syms.q);
    let x_inv = jacobian
        .mul(m.mass_inv()?)?
        .mul(&jacobian.transpose())?
        .inverse("X_I")?;
    let qd = m.qd_column();
    let impulse = x_inv.mul(&jacobian.mul(&qd)?)?.scale(&RatFunc::int(-1));
    let velocity = qd.add(&m.mass_inv()?.mul(&jacobian.transpose())?.mul(&impulse)?)?;
    Ok(ImpactMap {
        jacobian,
        impulse,
        velocity,
    })
}

/// The model's strike impacts: the striking point's gap, then (for the double-support test)
/// the old stance foot's gap, then the locks.
#[derive(Clone, Debug)]
pub struct StrikeImpacts {
    /// The old stance foot leaves the floor: `[strike, locks...]`.
    pub single: ImpactMap,
    /// The old stance foot held: `[strike, stance foot, locks...]` (Eq. 11, Eq. 46), when the
    /// model asks for the double-support test.
    pub double: Option<ImpactMap>,
}

/// The constraint rows of the model's strike: the striking point's gap then the locks, and
/// (for the double-support test) the same with the old stance foot's gap second.
#[derive(Clone, Debug)]
pub struct StrikeRows {
    /// `[strike, locks...]`.
    pub single: Vec<RatFunc>,
    /// `[strike, stance foot, locks...]`, when the model asks for the double-support test.
    pub double: Option<Vec<RatFunc>>,
}

/// The constraint rows of `model`'s strike.
///
/// # Errors
/// An unknown strike point, or a lock that does not lower.
pub fn strike_rows(m: &Mechanics, model: &Model) -> Result<StrikeRows> {
    let [px, pz] = m.point(&model.strike.point.name)?;
    let strike = m.floor.gap(px, pz);
    let locks = model
        .impact
        .locks
        .iter()
        .map(|e| m.syms.lower(e))
        .collect::<Result<Vec<_>>>()?;
    let single: Vec<RatFunc> = std::iter::once(strike.clone())
        .chain(locks.iter().cloned())
        .collect();
    let double = model.impact.double_support.then(|| {
        let (x, z) = (RatFunc::sym(m.syms.q[0]), RatFunc::sym(m.syms.q[1]));
        [strike, m.floor.gap(&x, &z)]
            .into_iter()
            .chain(locks)
            .collect()
    });
    Ok(StrikeRows { single, double })
}

/// Derives the strike impacts of `model`.
///
/// # Errors
/// An unknown strike point, a lock that does not lower, or dependent constraints.
pub fn strike_impacts(m: &Mechanics, model: &Model) -> Result<StrikeImpacts> {
    let rows = strike_rows(m, model)?;
    Ok(StrikeImpacts {
        single: impact_map(m, &rows.single)?,
        double: rows.double.map(|r| impact_map(m, &r)).transpose()?,
    })
}
