//! The stance and impact kernels of any model as structured solves ([`Program`]): the same
//! equations as `phases` (Eqs. 19-31, 39-46), solved through an `L D L^T` factorisation of `M`
//! instead of the closed-form `M^-1`.
//!
//! - Sliding stance (Eqs. 22-27): `a = M^-1 (S u - h)`, `b = M^-1 (J + J_mu)^T`, the normal force
//!   `lambda_n = -J a / J b` and `qdd = a + b lambda_n` (which is `M^-1 Y (S u - h)`).
//! - Output-following control (Eqs. 30-31): with `W = M^-1 S`, `c = M^-1 h` and their
//!   projections `W' = W - b (J W) / J b`, `c' = c - b (J c) / J b` (that is `M^-1 Y S` and
//!   `M^-1 Y h`): `A = H W'`, `B = H c' - Hdot qdot`, `u = A^-1 (v + B)`, `qdd = W' u - c'`.
//! - Stuck foot: the angles' block `M_aa qdd_a = (S u - h)_a`, the force from the foot's rows.
//! - Impacts (Eqs. 6-16): `K = M^-1 J_I^T`, the Delassus matrix `X = J_I K` (symmetric positive
//!   definite for independent constraints, factored again by `L D L^T`),
//!   `lambda_I = -X^-1 J_I qdot-`, `qdot+ = qdot- + K lambda_I`.

use walker_scene::model::Model;

use super::mechanics::Mechanics;
use super::phases::output_maps;
use super::program::{Ldlt, Program};
use crate::error::Result;
use crate::kernels::Staged;
use crate::matrix::Matrix;
use crate::ratfunc::RatFunc;
use crate::symbol::Symbols;

/// The structured solves of a model's kernels, by kernel name.
#[derive(Clone, Debug)]
pub struct StructuredKernels {
    /// `lambda`: the vertical ground reaction.
    pub lambda: Staged,
    /// `accel`: `qdd` of the sliding stance.
    pub accel: Staged,
    /// `control`: `A` (row-major) then `B`, for a model with outputs.
    pub control: Option<Staged>,
    /// `closed_loop`: `qdd` then `u`, for a model with outputs.
    pub closed_loop: Option<Staged>,
    /// `stick`: `qdd`, `lambda_t`, `lambda_n`.
    pub stick: Staged,
    /// `impact`: `lambda_I` then `qdot+`.
    pub impact: Staged,
    /// `impact_double`: the same with the old stance foot held.
    pub impact_double: Option<Staged>,
}

/// `M` bound (its lower triangle, mirrored) and factored.
pub(super) fn factored_mass(p: &mut Program, m: &Mechanics) -> Result<Ldlt> {
    let n = m.syms.q.len();
    let mut mm = Matrix::zeros(n, n);
    for i in 0..n {
        for j in 0..=i {
            let v = p.bind(m.mass.get(i, j).clone())?;
            mm.set(i, j, v.clone());
            mm.set(j, i, v);
        }
    }
    p.ldlt(&mm, "M")
}

/// `a . b`, unbound.
pub(super) fn dot(a: &[RatFunc], b: &[RatFunc]) -> RatFunc {
    a.iter()
        .zip(b)
        .fold(RatFunc::zero(), |acc, (x, y)| &acc + &(x * y))
}

/// The sliding stance's shared part: `J` (bound), `b = M^-1 (J + J_mu)^T` and `J b`.
struct Slide {
    factor: Ldlt,
    contact: Vec<RatFunc>,
    b: Vec<RatFunc>,
    den: RatFunc,
}

fn slide(p: &mut Program, m: &Mechanics) -> Result<Slide> {
    let factor = factored_mass(p, m)?;
    let contact = p.bind_all(m.contact.entries())?;
    let jhat = p.bind_all(m.contact.add(&m.friction)?.entries())?;
    let b = p.solve(&factor, &jhat)?;
    let den = p.bind(dot(&contact, &b))?;
    Ok(Slide {
        factor,
        contact,
        b,
        den,
    })
}

/// `x - b (J x) / J b`: the projection `M^-1 Y M` of a solution `x = M^-1 r`.
fn project(p: &mut Program, s: &Slide, x: &[RatFunc]) -> Result<Vec<RatFunc>> {
    let k = p.bind(dot(&s.contact, x).div(&s.den)?)?;
    let projected: Vec<RatFunc> = x.iter().zip(&s.b).map(|(xi, bi)| xi - &(bi * &k)).collect();
    p.bind_all(&projected)
}

fn sliding(m: &Mechanics, table: &mut Symbols, name: &str) -> Result<(Staged, Staged)> {
    let mut p = Program::new(table, name);
    let s = slide(&mut p, m)?;
    let f = p.bind_all(m.input_force.sub(&m.bias)?.entries())?;
    let a = p.solve(&s.factor, &f)?;
    let normal = p.bind(-dot(&s.contact, &a).div(&s.den)?)?;
    let lambda = &normal * &s.contact[1];
    let accel: Vec<RatFunc> = a
        .iter()
        .zip(&s.b)
        .map(|(ai, bi)| ai + &(bi * &normal))
        .collect();
    let accel = p.bind_all(&accel)?;
    let program = p.finish(Vec::new());
    let with = |outputs: Vec<RatFunc>| Staged {
        locals: program.locals.clone(),
        outputs,
    };
    Ok((with(vec![lambda]), with(accel)))
}

/// `A`, `B` (Eqs. 30-31) by the structured solve, with the projected solutions they are built
/// from: `w[j] = M^-1 Y S_j` and `c = M^-1 Y h`.
struct Control {
    a: Matrix,
    b: Vec<RatFunc>,
    w: Vec<Vec<RatFunc>>,
    c: Vec<RatFunc>,
}

fn control(p: &mut Program, m: &Mechanics, model: &Model) -> Result<Control> {
    let s = slide(p, m)?;
    let n = m.syms.q.len();
    let maps = output_maps(m, model)?;
    let rows = maps.y.len();
    let drift = p.bind_all(&maps.drift)?;
    let h = p.bind_matrix(&maps.jacobian)?;
    let bias = p.bind_all(m.bias.entries())?;
    let c = p.solve(&s.factor, &bias)?;
    let c = project(p, &s, &c)?;
    let mut w = Vec::with_capacity(m.input_map.cols());
    for j in 0..m.input_map.cols() {
        let sj: Vec<RatFunc> = (0..n).map(|i| m.input_map.get(i, j).clone()).collect();
        let sj = p.bind_all(&sj)?;
        let x = p.solve(&s.factor, &sj)?;
        w.push(project(p, &s, &x)?);
    }
    let mut a = Matrix::zeros(rows, w.len());
    let mut b = Vec::with_capacity(rows);
    for (i, drift_i) in drift.iter().enumerate().take(rows) {
        let hi: Vec<RatFunc> = (0..n).map(|k| h.get(i, k).clone()).collect();
        for (j, wj) in w.iter().enumerate() {
            a.set(i, j, p.bind(dot(&hi, wj))?);
        }
        b.push(p.bind(&dot(&hi, &c) - drift_i)?);
    }
    Ok(Control { a, b, w, c })
}

/// Derives the structured solve of every stance and impact kernel of `model`, adding their
/// locals to `table`.
///
/// # Errors
/// `M`, `M_aa` or a Delassus matrix singular identically; an output or lock that does not
/// lower; a control matrix `A` larger than 3x3.
pub fn structured_kernels(
    m: &Mechanics,
    model: &Model,
    table: &mut Symbols,
) -> Result<StructuredKernels> {
    let n = m.syms.q.len();
    let (lambda, accel) = sliding(m, table, "sliding")?;
    let (control_kernel, closed_loop) = if model.outputs.is_empty() {
        (None, None)
    } else {
        let mut p = Program::new(table, "control");
        let c = control(&mut p, m, model)?;
        let mut outputs = c.a.entries().to_vec();
        outputs.extend(c.b.iter().cloned());
        let control_kernel = p.finish(outputs);

        let mut p = Program::new(table, "closed_loop");
        let c = control(&mut p, m, model)?;
        let v: Vec<RatFunc> = m.syms.aux.iter().map(|s| RatFunc::sym(*s)).collect();
        let rhs: Vec<RatFunc> = v.iter().zip(&c.b).map(|(vi, bi)| vi + bi).collect();
        let u = p.small_solve(&c.a, &Matrix::column(rhs), "A")?;
        let u = u.entries().to_vec();
        let mut qdd = Vec::with_capacity(n);
        for i in 0..n {
            let mut acc = -c.c[i].clone();
            for (wj, uj) in c.w.iter().zip(&u) {
                acc = &acc + &(&wj[i] * uj);
            }
            qdd.push(p.bind(acc)?);
        }
        qdd.extend(u);
        (Some(control_kernel), Some(p.finish(qdd)))
    };
    let stick = stick(m, table)?;
    let impacts = super::phases::strike_rows(m, model)?;
    let single = impact(m, table, "impact", &impacts.single)?;
    let impact_double = impacts
        .double
        .as_ref()
        .map(|rows| impact(m, table, "impact_double", rows))
        .transpose()?;
    Ok(StructuredKernels {
        lambda,
        accel,
        control: control_kernel,
        closed_loop,
        stick,
        impact: single,
        impact_double,
    })
}

/// The stuck foot by the angles' block (see [`super::phases::stuck`]).
fn stick(m: &Mechanics, table: &mut Symbols) -> Result<Staged> {
    let mut p = Program::new(table, "stick");
    let factor = factored_angles(&mut p, m)?;
    let f = p.bind_all(m.input_force.sub(&m.bias)?.entries())?;
    let qdd_a = p.solve(&factor, &f[2..])?;
    let forces = foot_forces(&mut p, m, &f, &qdd_a)?;
    let mut outputs = vec![RatFunc::zero(), RatFunc::zero()];
    outputs.extend(qdd_a);
    outputs.extend(forces);
    Ok(p.finish(outputs))
}

/// The angles' block `M_aa` of `M` (the coordinates after the foot's `x`, `z`) bound and
/// factored.
pub(super) fn factored_angles(p: &mut Program, m: &Mechanics) -> Result<Ldlt> {
    let n = m.syms.q.len();
    let mut maa = Matrix::zeros(n - 2, n - 2);
    for i in 2..n {
        for j in 2..=i {
            let v = p.bind(m.mass.get(i, j).clone())?;
            maa.set(i - 2, j - 2, v.clone());
            maa.set(j - 2, i - 2, v);
        }
    }
    p.ldlt(&maa, "M_aa")
}

/// The stuck foot's force `[lambda_t, lambda_n]` from the foot's rows of the equations of
/// motion, `J_f (M_fa qdd_a - f_f)`, for the generalised force `f = S u - h` (bound) and the
/// angles' accelerations `qdd_a`.
pub(super) fn foot_forces(
    p: &mut Program,
    m: &Mechanics,
    f: &[RatFunc],
    qdd_a: &[RatFunc],
) -> Result<Vec<RatFunc>> {
    let n = m.syms.q.len();
    let (x, z) = (RatFunc::sym(m.syms.q[0]), RatFunc::sym(m.syms.q[1]));
    let foot = Matrix::jacobian(&[m.floor.tangent(&x, &z), m.floor.gap(&x, &z)], &m.syms.q);
    let mut rows = Vec::with_capacity(2);
    for (i, fi) in f.iter().enumerate().take(2) {
        let mfa: Vec<RatFunc> = (2..n).map(|j| m.mass.get(i, j).clone()).collect();
        let mfa = p.bind_all(&mfa)?;
        rows.push(p.bind(&dot(&mfa, qdd_a) - fi)?);
    }
    let mut forces = Vec::with_capacity(2);
    for i in 0..2 {
        let force = &(foot.get(i, 0) * &rows[0]) + &(foot.get(i, 1) * &rows[1]);
        forces.push(p.bind(force)?);
    }
    Ok(forces)
}

/// An impact map for constraint rows `J_I`: `lambda_I` then `qdot+`.
fn impact(m: &Mechanics, table: &mut Symbols, name: &str, rows: &[RatFunc]) -> Result<Staged> {
    let n = m.syms.q.len();
    let k = rows.len();
    let mut p = Program::new(table, name);
    let factor = factored_mass(&mut p, m)?;
    let jac = p.bind_matrix(&Matrix::jacobian(rows, &m.syms.q))?;
    let mut kk = Vec::with_capacity(k);
    for r in 0..k {
        let jr: Vec<RatFunc> = (0..n).map(|i| jac.get(r, i).clone()).collect();
        kk.push(p.solve(&factor, &jr)?);
    }
    let mut x = Matrix::zeros(k, k);
    for r in 0..k {
        let jr: Vec<RatFunc> = (0..n).map(|i| jac.get(r, i).clone()).collect();
        for (s, ks) in kk.iter().enumerate().take(r + 1) {
            let v = p.bind(dot(&jr, ks))?;
            x.set(r, s, v.clone());
            x.set(s, r, v);
        }
    }
    let delassus = p.ldlt(&x, "X_I")?;
    let qd: Vec<RatFunc> = m.syms.qd.iter().map(|s| RatFunc::sym(*s)).collect();
    let mut w = Vec::with_capacity(k);
    for r in 0..k {
        let jr: Vec<RatFunc> = (0..n).map(|i| jac.get(r, i).clone()).collect();
        w.push(p.bind(-dot(&jr, &qd))?);
    }
    let impulse = p.solve(&delassus, &w)?;
    let mut outputs = impulse.clone();
    for i in 0..n {
        let mut v = qd[i].clone();
        for (kr, l) in kk.iter().zip(&impulse) {
            v = &v + &(&kr[i] * l);
        }
        outputs.push(p.bind(v)?);
    }
    Ok(p.finish(outputs))
}
