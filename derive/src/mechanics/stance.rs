//! The stance phases: the sliding contact with its friction (Section 3.1; Section 5.1 for
//! the slope), the stuck foot (stick phase, not in the paper), and the output-following
//! control terms of both (Section 3.2).

use super::dynamics::Dynamics;
use super::floor::{floor_gap, floor_tangent};
use super::terms::{Q_SYMS, int, sym, time_derivative};
use crate::error::{Error, Result};
use crate::matrix::Matrix;
use crate::ratfunc::RatFunc;
use crate::symbol::Sym;
use walker_scene::Floor;

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
