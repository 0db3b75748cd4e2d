//! The output-following control with the stance foot stuck (`closed_loop_stick`): the stick
//! phase of exact Coulomb friction under the controller of Section 3.2, which the paper does
//! not model (it slides only).
//!
//! With both foot coordinates held, the angles obey their own block,
//! `qdd_a = M_aa^-1 (S u - h)_a` (see [`super::phases::stuck`]), so the outputs' accelerations
//! are `yddot = H_a qdd_a + Hdot qdot = A_s u - B_s` with `A_s = H_a M_aa^-1 S_a` and
//! `B_s = H_a M_aa^-1 h_a - Hdot qdot` (`H_a`, `S_a`, `h_a`: the angles' columns and rows). The
//! control is recomputed for these dynamics, `u = A_s^-1 (v + B_s)` (Eq. 31 with the stuck
//! `A_s`, `B_s`), so that `yddot = v` while the foot sticks; the kernel gives the stuck
//! accelerations and the ground force with that `u`. The same as `A_s = H M^-1 Y_s S` with the
//! stick projection `Y_s = I - J_s^T (J_s M^-1 J_s^T)^-1 J_s M^-1` (the paper's
//! `closed_loop_stick_level`), without `M^-1`.

use walker_scene::model::Model;

use super::assemble::{kernel, named, names, solve_only, with_solve};
use super::mechanics::Mechanics;
use super::phases::{OutputControl, OutputMaps, Stuck, output_maps};
use super::program::Program;
use super::structured::{dot, factored_angles, foot_forces};
use crate::error::Result;
use crate::kernels::{Kernel, Shape, Staged};
use crate::matrix::Matrix;
use crate::ratfunc::RatFunc;
use crate::symbol::{Atom, Symbols};

/// The rows `rows` and columns `cols` of `a`.
fn block(a: &Matrix, rows: std::ops::Range<usize>, cols: std::ops::Range<usize>) -> Result<Matrix> {
    Matrix::from_rows(
        rows.map(|i| cols.clone().map(|j| a.get(i, j).clone()).collect())
            .collect(),
    )
}

/// The control of the stuck stance in closed form: `A_s`, `B_s` and `u = A_s^-1 (v + B_s)`
/// (`output_jacobian` is `H`).
///
/// # Errors
/// An output that does not lower, `M_aa` or `A_s` singular identically.
pub fn stuck_control(m: &Mechanics, model: &Model) -> Result<OutputControl> {
    let n = m.syms.q.len();
    let OutputMaps {
        jacobian: h_jac,
        drift,
        ..
    } = output_maps(m, model)?;
    let outputs = h_jac.rows();
    let m_aa_inv = block(&m.mass, 2..n, 2..n)?.inverse("M_aa")?;
    let h_a = block(&h_jac, 0..outputs, 2..n)?;
    let h_minv = h_a.mul(&m_aa_inv)?;
    let s_a = block(&m.input_map, 2..n, 0..m.input_map.cols())?;
    let bias_a = block(&m.bias, 2..n, 0..1)?;
    let a = h_minv.mul(&s_a)?;
    let b = h_minv.mul(&bias_a)?.sub(&Matrix::column(drift))?;
    let v = Matrix::column(m.syms.aux.iter().map(|s| RatFunc::sym(*s)).collect());
    let u = a.inverse("A_s")?.mul(&v.add(&b)?)?;
    Ok(OutputControl {
        output_jacobian: h_jac,
        a,
        b,
        u,
    })
}

/// The structured solve of `closed_loop_stick`: `M_aa` factored, `W_a = M_aa^-1 S_a` and
/// `c_a = M_aa^-1 h_a` by its substitutions, `A_s = H_a W_a`, `B_s = H_a c_a - Hdot qdot`,
/// `u` by the adjugate of `A_s`, `qdd_a = W_a u - c_a`, the force from the foot's rows.
fn solve(m: &Mechanics, model: &Model, table: &mut Symbols) -> Result<Staged> {
    let n = m.syms.q.len();
    let mut p = Program::new(table, "closed_loop_stick");
    let factor = factored_angles(&mut p, m)?;
    let maps = output_maps(m, model)?;
    let outputs = maps.y.len();
    let drift = p.bind_all(&maps.drift)?;
    let h = p.bind_matrix(&block(&maps.jacobian, 0..outputs, 2..n)?)?;
    let bias = p.bind_all(m.bias.entries())?;
    let c = p.solve(&factor, &bias[2..])?;
    let mut w = Vec::with_capacity(m.input_map.cols());
    for j in 0..m.input_map.cols() {
        let sj: Vec<RatFunc> = (2..n).map(|i| m.input_map.get(i, j).clone()).collect();
        let sj = p.bind_all(&sj)?;
        w.push(p.solve(&factor, &sj)?);
    }
    let mut a = Matrix::zeros(outputs, w.len());
    let mut rhs = Vec::with_capacity(outputs);
    for (i, (drift_i, aux)) in drift.iter().zip(&m.syms.aux).enumerate() {
        let hi: Vec<RatFunc> = (0..n - 2).map(|k| h.get(i, k).clone()).collect();
        for (j, wj) in w.iter().enumerate() {
            a.set(i, j, p.bind(dot(&hi, wj))?);
        }
        let b = p.bind(&dot(&hi, &c) - drift_i)?;
        rhs.push(&RatFunc::sym(*aux) + &b);
    }
    let u = p.small_solve(&a, &Matrix::column(rhs), "A_s")?;
    let u = u.entries().to_vec();
    let mut qdd_a = Vec::with_capacity(n - 2);
    for (i, ci) in c.iter().enumerate() {
        let mut acc = -ci.clone();
        for (wj, uj) in w.iter().zip(&u) {
            acc = &acc + &(&wj[i] * uj);
        }
        qdd_a.push(p.bind(acc)?);
    }
    // S u - h with the computed u, for the foot's rows.
    let mut f = Vec::with_capacity(n);
    for (i, hi) in bias.iter().enumerate() {
        let mut acc = -hi.clone();
        for (j, uj) in u.iter().enumerate() {
            acc = &acc + &(m.input_map.get(i, j) * uj);
        }
        f.push(acc);
    }
    let forces = foot_forces(&mut p, m, &f, &qdd_a)?;
    let mut out = vec![RatFunc::zero(), RatFunc::zero()];
    out.extend(qdd_a);
    out.extend(u);
    out.extend(forces);
    Ok(p.finish(out))
}

/// The `closed_loop_stick` kernel of a model with outputs: `qdd`, `u`, `lambda_t`, `lambda_n`;
/// in closed form from the stuck stance `stuck` where it was derived, and as a structured solve
/// always.
///
/// # Errors
/// As [`stuck_control`], or the structured solve's `M_aa` or `A_s` singular identically.
pub(super) fn closed_loop_stick(
    m: &Mechanics,
    model: &Model,
    stuck: Option<&Stuck>,
    table: &mut Symbols,
) -> Result<Kernel> {
    let n = m.syms.q.len();
    let (doc, eq) = (
        "Accelerations qddot, inputs u and the ground force `[lambda_t, lambda_n]` with the stance foot stuck, under the output-following control recomputed for the stuck dynamics, with yddot = v",
        "stick phase; Eqs. 30-31 with both foot coordinates held",
    );
    let solved = solve(m, model, table)?;
    let t = &*table;
    let k = match stuck {
        Some(st) => {
            let c = stuck_control(m, model)?;
            let with_u = |r: &RatFunc| -> Result<RatFunc> {
                let mut r = r.clone();
                for (u, value) in m.syms.inputs.iter().zip(c.u.entries()) {
                    r = r.substitute(Atom::Sym(*u), value)?;
                }
                Ok(r)
            };
            let mut outputs = named("qdd", &st.accel.try_map(with_u)?);
            outputs.extend(named("u", &c.u));
            outputs.push(("lambda_t".into(), with_u(st.forces.get(0, 0))?));
            outputs.push(("lambda_n".into(), with_u(st.forces.get(1, 0))?));
            let mut k = kernel(t, "closed_loop_stick", doc, eq, outputs, Shape::Parts, &[]);
            // u once, then the stuck stance with that u (as `closed_loop`).
            k.staged = Some(Staged {
                locals: m
                    .syms
                    .inputs
                    .iter()
                    .copied()
                    .zip(c.u.entries().iter().cloned())
                    .collect(),
                outputs: st
                    .accel
                    .entries()
                    .iter()
                    .cloned()
                    .chain(m.syms.inputs.iter().map(|u| RatFunc::sym(*u)))
                    .chain(st.forces.entries().iter().cloned())
                    .collect(),
            });
            k
        }
        None => {
            let mut parts = names("qdd", n, 1);
            parts.extend(names("u", m.syms.inputs.len(), 1));
            parts.extend(["lambda_t".to_owned(), "lambda_n".to_owned()]);
            solve_only("closed_loop_stick", doc, eq, parts, Shape::Parts)
        }
    };
    Ok(with_solve(k, solved, stuck.is_some(), t))
}
