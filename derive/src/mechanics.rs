//! The walker, written once from its physics, and everything the paper derives from it.
//!
//! Geometry (Fig. 1): the stance-leg end is at `(x, z)`; the hip at
//! `(x + l sin th1, z + l cos th1)`; the torso turns about the hip and has its centre of mass
//! there; the fore leg is the spoke at angle `th1 - alpha`. Kinetic and potential energy give
//! `M(q)` and `h(q, qdot)` through the Euler-Lagrange equations; contact geometry gives every
//! constraint Jacobian by differentiation.

use crate::error::{Error, Result};
use crate::matrix::Matrix;
use crate::poly::Q;
use crate::ratfunc::RatFunc;
use crate::symbol::{Atom, BaseAngle, Sym};
use crate::trig::sin_cos_combination;

/// The floor the stance foot slides on: level ground `z = 0` (Section 3) or a slope of angle
/// `phi` descending towards `+x`, `z = -x tan phi` (Section 5). The shared vocabulary's
/// [`walker_scene::Floor`], re-exported so that `walker_symbolic::mechanics::Floor` keeps working.
pub use walker_scene::Floor;

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

fn combination(angle: &[(Sym, i64)]) -> Result<Vec<(BaseAngle, i64)>> {
    angle
        .iter()
        .map(|&(s, n)| {
            let base = BaseAngle::of_symbol(s).ok_or_else(|| Error::UnsupportedAngle {
                what: format!("`{}` is not an angle", s.name()),
            })?;
            Ok((base, n * base.symbol_and_multiple().1))
        })
        .collect()
}

/// `sin(sum n_k s_k)` for angle symbols `s_k` and integers `n_k`.
pub fn sin(angle: &[(Sym, i64)]) -> Result<RatFunc> {
    Ok(sin_cos_combination(&combination(angle)?).0.into())
}

/// `cos(sum n_k s_k)`.
pub fn cos(angle: &[(Sym, i64)]) -> Result<RatFunc> {
    Ok(sin_cos_combination(&combination(angle)?).1.into())
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

/// The stance contact and its friction (Eqs. 21, 24, 36, 38).
#[derive(Clone, Debug)]
pub struct Contact {
    /// Holonomic constraint Jacobian `J` (a row).
    pub jacobian: Matrix,
    /// Friction Jacobian `J_mu` (a row).
    pub friction: Matrix,
}

/// The stance-foot constraint for a floor. `J` is the gradient of the signed distance of the
/// foot from the floor (`z` on level ground, `z cos phi + x sin phi` on the slope), so its
/// multiplier is the normal force; the friction acts along the floor with magnitude `mu`
/// times the normal force: `J_mu = mu [J_z, -J_x, 0, 0]`. On level ground these are
/// Eqs. 21 and 24; on the slope they are Eqs. 36 and 38 multiplied by `cos phi` (the paper
/// scales its multiplier to the vertical reaction, see [`Stance::lambda`]).
pub fn stance_contact(floor: Floor) -> Result<Contact> {
    let jacobian = Matrix::jacobian(&[floor_gap(floor, &sym(Sym::X), &sym(Sym::Z))], &Q_SYMS);
    let mu = sym(Sym::Mu);
    let friction = Matrix::row(vec![
        &mu * jacobian.get(0, 1),
        -(&mu * jacobian.get(0, 0)),
        int(0),
        int(0),
    ]);
    Ok(Contact { jacobian, friction })
}

/// Stance-phase quantities for one floor (Section 3.1; Section 5.1 for the slope).
#[derive(Clone, Debug)]
pub struct Stance {
    /// The contact.
    pub contact: Contact,
    /// `lambda` (Eqs. 22-23), the vertical ground reaction (the normal force times `cos phi`
    /// on the slope, as in Section 5.1).
    pub lambda: RatFunc,
    /// The normal force, the multiplier of the unit-normal constraint.
    pub normal_force: RatFunc,
    /// The denominator of the normal force, `J M^-1 (J + J_mu)^T` (Eq. 22); where it vanishes
    /// the sliding contact has no solution (Painleve's paradox).
    pub lambda_den: RatFunc,
    /// `Y` (Eqs. 28-29).
    pub projection: Matrix,
    /// `qddot` (Eq. 27).
    pub accel: Matrix,
}

/// Derives the stance phase on a floor: `M qdd + h = S u + (J + J_mu)^T lambda`, `J qdd = 0`.
pub fn stance(dynamics: &Dynamics, floor: Floor) -> Result<Stance> {
    let contact = stance_contact(floor)?;
    let jhat = contact.jacobian.add(&contact.friction)?;
    let j_minv = contact.jacobian.mul(&dynamics.mass_inv)?;
    let su_minus_h = dynamics.input_map.scale(&sym(Sym::U)).sub(&dynamics.bias)?;
    let lambda_den = j_minv.mul(&jhat.transpose())?.scalar()?;
    let normal_force = (-j_minv.mul(&su_minus_h)?.scalar()?).div(&lambda_den)?;
    let forces = su_minus_h.add(&jhat.transpose().scale(&normal_force))?;
    let lambda = &normal_force * contact.jacobian.get(0, 1);
    let accel = dynamics.mass_inv.mul(&forces)?;
    let projection =
        Matrix::identity(4).sub(&jhat.transpose().mul(&j_minv)?.scale(&lambda_den.recip()?))?;
    Ok(Stance {
        contact,
        lambda,
        normal_force,
        lambda_den,
        projection,
        accel,
    })
}

/// The stance foot stuck to the floor: the stick phase of Coulomb friction with stick-slip.
///
/// Not in the paper, which models sliding only (Eq. 25 "without considering the static friction
/// effect"); this is Eq. 19 with both foot coordinates held instead of one:
/// `M qdd + h = S u + J_s^T [lambda_t, lambda_n]`, `J_s qdd = 0`.
#[derive(Clone, Debug)]
pub struct Stick {
    /// `J_s`, two rows: the gradient of the foot's coordinate along the floor (unit tangent
    /// `(cos phi, -sin phi)`, `+x` on level ground) and of its signed distance from the floor
    /// (unit normal). Constant: the constraints are scleronomic and linear in `q`, so
    /// `d/dt (J_s qdot) = J_s qddot` (checked by [`stick`]).
    pub jacobian: Matrix,
    /// `[lambda_t, lambda_n]` (a column): the tangential force on the foot along the floor's
    /// `+x` direction and the normal force.
    pub forces: Matrix,
    /// `qddot` (a column); `xdd = zdd = 0`.
    pub accel: Matrix,
    /// `Y_s = I - J_s^T (J_s M^-1 J_s^T)^-1 J_s M^-1`, so that `M qdd = Y_s (S u - h)` (the stick
    /// counterpart of Eq. 28).
    pub projection: Matrix,
}

/// The foot's coordinate along the floor: `x` on level ground, `x cos phi - z sin phi` on the
/// slope (along the unit tangent `(cos phi, -sin phi)`, positive down the slope).
pub fn floor_tangent(floor: Floor, x: &RatFunc, z: &RatFunc) -> RatFunc {
    match floor {
        Floor::Level => x.clone(),
        Floor::Slope => {
            &(x * &RatFunc::cos_of(BaseAngle::Phi)) - &(z * &RatFunc::sin_of(BaseAngle::Phi))
        }
    }
}

/// Derives the stick phase on a floor (see [`Stick`]): the constraint Jacobian by
/// differentiation of the contact geometry (foot coordinate along the floor, then
/// [`floor_gap`]), the multipliers `lambda = -(J_s M^-1 J_s^T)^-1 J_s M^-1 (S u - h)` and
/// `qdd = M^-1 (S u - h + J_s^T lambda)`.
///
/// # Errors
/// [`Error::CheckFailed`] if `J_s` were not constant along the motion (then `J_s qdd = 0`
/// would not be the acceleration-level constraint), or an arithmetic error.
pub fn stick(dynamics: &Dynamics, floor: Floor) -> Result<Stick> {
    let (x, z) = (sym(Sym::X), sym(Sym::Z));
    let jacobian = Matrix::jacobian(
        &[floor_tangent(floor, &x, &z), floor_gap(floor, &x, &z)],
        &Q_SYMS,
    );
    // The acceleration-level constraint is J_s qdd + Jdot_s qd = 0; it is J_s qdd = 0 only
    // because every entry of J_s is constant along the motion.
    if jacobian
        .entries()
        .iter()
        .any(|e| !time_derivative(e).is_zero())
    {
        return Err(Error::CheckFailed {
            what: "the stick constraint Jacobian is constant".to_owned(),
        });
    }
    let j_minv = jacobian.mul(&dynamics.mass_inv)?;
    let schur_inv = j_minv
        .mul(&jacobian.transpose())?
        .inverse("J_s M^-1 J_s^T")?;
    let su_minus_h = dynamics.input_map.scale(&sym(Sym::U)).sub(&dynamics.bias)?;
    let forces = schur_inv.mul(&j_minv.mul(&su_minus_h)?)?.scale(&int(-1));
    let accel = dynamics
        .mass_inv
        .mul(&su_minus_h.add(&jacobian.transpose().mul(&forces)?)?)?;
    let projection =
        Matrix::identity(4).sub(&jacobian.transpose().mul(&schur_inv)?.mul(&j_minv)?)?;
    Ok(Stick {
        jacobian,
        forces,
        accel,
        projection,
    })
}

/// The output-following control (Section 3.2, Eqs. 30-31).
#[derive(Clone, Debug)]
pub struct Control {
    /// `A = S^T M^-1 Y S`.
    pub a: RatFunc,
    /// `B = S^T M^-1 Y h`.
    pub b: RatFunc,
}

/// Derives `A` and `B` so that `yddot = A u - B` (Eq. 30).
///
/// # Errors
/// An arithmetic error of the matrix products.
pub fn control(dynamics: &Dynamics, stance: &Stance) -> Result<Control> {
    control_through(dynamics, &stance.projection)
}

/// `A_s` and `B_s` of the stick phase, `yddot = A_s u - B_s`: Eqs. 30-31 with the stick
/// projection `Y_s` in place of `Y` (not in the paper).
///
/// # Errors
/// An arithmetic error of the matrix products.
pub fn stick_control(dynamics: &Dynamics, stick: &Stick) -> Result<Control> {
    control_through(dynamics, &stick.projection)
}

/// `A = S^T M^-1 Y S`, `B = S^T M^-1 Y h` for a projection `Y` with `M qdd = Y (S u - h)`.
fn control_through(dynamics: &Dynamics, projection: &Matrix) -> Result<Control> {
    let st_minv_y = dynamics
        .input_map
        .transpose()
        .mul(&dynamics.mass_inv)?
        .mul(projection)?;
    Ok(Control {
        a: st_minv_y.mul(&dynamics.input_map)?.scalar()?,
        b: st_minv_y.mul(&dynamics.bias)?.scalar()?,
    })
}

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

/// Signed distance of a point `(x, z)` from the floor: `z` on level ground,
/// `z cos phi + x sin phi` on the slope `z = -x tan phi`. Its gradient is the unit normal.
pub fn floor_gap(floor: Floor, x: &RatFunc, z: &RatFunc) -> RatFunc {
    match floor {
        Floor::Level => z.clone(),
        Floor::Slope => {
            &(z * &RatFunc::cos_of(BaseAngle::Phi)) + &(x * &RatFunc::sin_of(BaseAngle::Phi))
        }
    }
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

/// The desired output `y_d(t)` of Section 3.2 on `0 <= t < T_set`, and its first two time
/// derivatives.
pub fn desired_output() -> Result<[RatFunc; 3]> {
    let s = sym(Sym::T).div(&sym(Sym::TSet))?;
    let alpha = sym(Sym::Alpha);
    let s3 = s.powi(3)?;
    let s4 = s.powi(4)?;
    let s5 = s.powi(5)?;
    let poly = &(&(&int(6) * &s5) - &(&int(15) * &s4)) + &(&int(10) * &s3);
    let yd = &(&alpha * &poly) - &(&alpha * &frac(1, 2));
    let ydd = yd.diff(Sym::T);
    let yddd = ydd.diff(Sym::T);
    Ok([yd, ydd, yddd])
}

/// Checks the boundary conditions of `y_d` symbolically: `y_d(0) = -alpha/2`,
/// `y_d(T_set) = alpha/2`, and zero first and second derivatives at both ends.
pub fn check_desired_output() -> Result<()> {
    let [yd, ydd, yddd] = desired_output()?;
    let half_alpha = &sym(Sym::Alpha) * &frac(1, 2);
    let at = |f: &RatFunc, t: &RatFunc| f.substitute(Atom::Sym(Sym::T), t);
    let t_set = sym(Sym::TSet);
    let zero = RatFunc::zero();
    let checks = [
        (at(&yd, &zero)?, -&half_alpha, "y_d(0) = -alpha/2"),
        (at(&yd, &t_set)?, half_alpha.clone(), "y_d(T_set) = alpha/2"),
        (at(&ydd, &zero)?, RatFunc::zero(), "y_d'(0) = 0"),
        (at(&ydd, &t_set)?, RatFunc::zero(), "y_d'(T_set) = 0"),
        (at(&yddd, &zero)?, RatFunc::zero(), "y_d''(0) = 0"),
        (at(&yddd, &t_set)?, RatFunc::zero(), "y_d''(T_set) = 0"),
    ];
    for (got, want, what) in checks {
        if got != want {
            return Err(Error::CheckFailed {
                what: what.to_owned(),
            });
        }
    }
    Ok(())
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

/// `m_t = m1 + m2`.
pub fn total_mass() -> RatFunc {
    sym(Sym::M1) + &sym(Sym::M2)
}

/// `I_t = I1 + I2`.
pub fn total_inertia() -> RatFunc {
    sym(Sym::I1) + &sym(Sym::I2)
}
