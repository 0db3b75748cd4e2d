//! The ingredients of a model's impact with Coulomb friction at the striking point
//! (`impact_coulomb`; `docs/impacts.md`; not in the paper).
//!
//! The model's locks (`[impact] locks`) are bilateral and frictionless, so they act first:
//! `M_L^-1 = M^-1 - M^-1 J_L^T (J_L M^-1 J_L^T)^-1 J_L M^-1` is the inverse mass matrix
//! restricted to them and `qdot_L = qdot- - M^-1 J_L^T (J_L M^-1 J_L^T)^-1 J_L qdot-` the
//! velocities after them (`M_L = M`, `qdot_L = qdot-` without locks). The striking point's
//! impulse `[Lambda_t, Lambda_n]` along the floor's unit tangent (towards `+x`, down a slope)
//! and unit normal (up) then acts on the locked walker, `qdot+ = qdot_L + R Lambda`, and the
//! friction law decides at run time what it is. The contact rows are `J = [J_t; J_n; J_r]`: the
//! gradients of the striking point's coordinate along the floor, of its gap, and of the old
//! stance foot's gap (`r`, for the double-support test; given for a model without that test
//! too, whose simulator ignores it).
//!
//! Outputs, named as the paper's `impact_coulomb_level`: `qdl` (`qdot_L`), `v_t, v_n, v_r` (`J qdot_L`),
//! the upper triangle of the Delassus matrix `W = J M_L^-1 J^T` over `(t, n, r)`, and
//! `R = M_L^-1 [J_t; J_n]^T` (`n x 2`, row-major).

use walker_scene::model::Model;

use super::assemble::{kernel, kernel_args, named, names, solve_only, with_solve};
use super::mechanics::Mechanics;
use super::program::Program;
use super::structured::{dot, factored_mass};
use crate::error::Result;
use crate::kernels::{Kernel, Shape, Staged};
use crate::matrix::Matrix;
use crate::ratfunc::RatFunc;
use crate::symbol::Symbols;

/// The Delassus entries the kernel gives, `(name, row, column)` over `(t, n, r)`.
const DELASSUS: [(&str, usize, usize); 6] = [
    ("W_tt", 0, 0),
    ("W_tn", 0, 1),
    ("W_tr", 0, 2),
    ("W_nn", 1, 1),
    ("W_nr", 1, 2),
    ("W_rr", 2, 2),
];

/// The constraint functions of a model's Coulomb impact.
#[derive(Clone, Debug)]
pub struct CoulombRows {
    /// `[t, n, r]`: the striking point's coordinate along the floor and its gap, the old
    /// stance foot's gap.
    pub contact: Vec<RatFunc>,
    /// The locks.
    pub locks: Vec<RatFunc>,
}

/// The constraint functions of `model`'s Coulomb impact.
///
/// # Errors
/// An unknown strike point, or a lock that does not lower.
pub fn coulomb_rows(m: &Mechanics, model: &Model) -> Result<CoulombRows> {
    let [px, pz] = m.point(&model.strike.point.name)?;
    let (x, z) = (RatFunc::sym(m.syms.q[0]), RatFunc::sym(m.syms.q[1]));
    let contact = vec![
        m.floor.tangent(px, pz),
        m.floor.gap(px, pz),
        m.floor.gap(&x, &z),
    ];
    let locks = model
        .impact
        .locks
        .iter()
        .map(|e| m.syms.lower(e))
        .collect::<Result<Vec<_>>>()?;
    Ok(CoulombRows { contact, locks })
}

/// The Coulomb impact's ingredients in closed form.
#[derive(Clone, Debug)]
pub struct CoulombImpact {
    /// `qdot_L`, a column.
    pub locked_velocity: Matrix,
    /// `[v_t, v_n, v_r] = J qdot_L`, a column.
    pub contact_velocity: Matrix,
    /// `W = J M_L^-1 J^T`, 3x3.
    pub delassus: Matrix,
    /// `R = M_L^-1 [J_t; J_n]^T`, n x 2.
    pub response: Matrix,
}

/// Derives the Coulomb impact of `model` through the closed-form `M^-1`.
///
/// # Errors
/// No closed-form `M^-1`, an unknown strike point, a lock that does not lower, or dependent
/// locks.
pub fn coulomb_impact(m: &Mechanics, model: &Model) -> Result<CoulombImpact> {
    let n = m.syms.q.len();
    let rows = coulomb_rows(m, model)?;
    let j = Matrix::jacobian(&rows.contact, &m.syms.q);
    let qd = m.qd_column();
    let minv = m.mass_inv()?;
    let (mass_inv, locked_velocity) = if rows.locks.is_empty() {
        (minv.clone(), qd)
    } else {
        let jl = Matrix::jacobian(&rows.locks, &m.syms.q);
        let m_jl = minv.mul(&jl.transpose())?;
        let x_l = jl.mul(&m_jl)?.inverse("X_L")?;
        let correction = m_jl.mul(&x_l)?;
        let mass_inv = minv.sub(&correction.mul(&jl.mul(minv)?)?)?;
        let locked = qd.sub(&correction.mul(&jl.mul(&qd)?)?)?;
        (mass_inv, locked)
    };
    let contact_velocity = j.mul(&locked_velocity)?;
    let m_jt = mass_inv.mul(&j.transpose())?;
    let delassus = j.mul(&m_jt)?;
    let response = Matrix::from_rows(
        (0..n)
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

/// The outputs of the closed form, in the kernel's order (also the paper's
/// `impact_coulomb_level` and `impact_coulomb_slope`).
pub(crate) fn coulomb_outputs(c: &CoulombImpact) -> Vec<(String, RatFunc)> {
    let mut o = named("qdl", &c.locked_velocity);
    o.extend(
        ["v_t", "v_n", "v_r"]
            .iter()
            .zip(c.contact_velocity.entries())
            .map(|(name, r)| ((*name).to_owned(), r.clone())),
    );
    for (name, i, j) in DELASSUS {
        o.push((name.to_owned(), c.delassus.get(i, j).clone()));
    }
    o.extend(named("R", &c.response));
    o
}

/// The structured solve: `M` factored; with locks `K_L = M^-1 J_L^T` and
/// `X_L = J_L K_L` (factored), `M_L^-1 b = x - K_L X_L^-1 J_L x` for `x = M^-1 b`, and
/// `qdot_L = qdot- - K_L X_L^-1 J_L qdot-`; then `M_L^-1 J_a^T` for each contact row `a`,
/// `v = J qdot_L`, `W_ab = J_a . M_L^-1 J_b^T`, `R` the first two of those columns.
fn solve(m: &Mechanics, model: &Model, table: &mut Symbols) -> Result<Staged> {
    let n = m.syms.q.len();
    let rows = coulomb_rows(m, model)?;
    let mut p = Program::new(table, "impact_coulomb");
    let factor = factored_mass(&mut p, m)?;
    let row_vecs = |p: &mut Program, fs: &[RatFunc]| -> Result<Vec<Vec<RatFunc>>> {
        let jac = p.bind_matrix(&Matrix::jacobian(fs, &m.syms.q))?;
        Ok((0..fs.len())
            .map(|r| (0..n).map(|i| jac.get(r, i).clone()).collect())
            .collect())
    };
    let contact = row_vecs(&mut p, &rows.contact)?;
    let locks = row_vecs(&mut p, &rows.locks)?;
    let mut k_l = Vec::with_capacity(locks.len());
    for jl in &locks {
        k_l.push(p.solve(&factor, jl)?);
    }
    let mut x_l = Matrix::zeros(locks.len(), locks.len());
    for (r, jr) in locks.iter().enumerate() {
        for (s, ks) in k_l.iter().enumerate().take(r + 1) {
            let v = p.bind(dot(jr, ks))?;
            x_l.set(r, s, v.clone());
            x_l.set(s, r, v);
        }
    }
    let lock_factor = if locks.is_empty() {
        None
    } else {
        Some(p.ldlt(&x_l, "X_L")?)
    };
    // x - K_L X_L^-1 J_L x: the part of x that the locks allow.
    let restrict = |p: &mut Program, x: Vec<RatFunc>| -> Result<Vec<RatFunc>> {
        let Some(lf) = &lock_factor else {
            return Ok(x);
        };
        let jx = p.bind_all(&locks.iter().map(|jl| dot(jl, &x)).collect::<Vec<_>>())?;
        let s = p.solve(lf, &jx)?;
        let restricted: Vec<RatFunc> = (0..n)
            .map(|i| {
                k_l.iter()
                    .zip(&s)
                    .fold(x[i].clone(), |acc, (k, si)| &acc - &(&k[i] * si))
            })
            .collect();
        p.bind_all(&restricted)
    };
    let qd: Vec<RatFunc> = m.syms.qd.iter().map(|s| RatFunc::sym(*s)).collect();
    let qdl = restrict(&mut p, qd)?;
    let mut columns = Vec::with_capacity(3);
    for ja in &contact {
        let x = p.solve(&factor, ja)?;
        columns.push(restrict(&mut p, x)?);
    }
    let mut out = qdl.clone();
    for ja in &contact {
        out.push(p.bind(dot(ja, &qdl))?);
    }
    for (_, a, b) in DELASSUS {
        out.push(p.bind(dot(&contact[a], &columns[b]))?);
    }
    for (t, n) in columns[0].iter().zip(&columns[1]) {
        out.extend([t.clone(), n.clone()]);
    }
    Ok(p.finish(out))
}

/// The `impact_coulomb` kernel: in closed form where `closed` (the closed-form `M^-1` is
/// small), as a structured solve always; it takes every velocity, as the other impact kernels.
///
/// # Errors
/// As [`coulomb_impact`], or the structured solve's `M` or `X_L` singular identically.
pub(super) fn impact_coulomb(
    m: &Mechanics,
    model: &Model,
    closed: bool,
    table: &mut Symbols,
) -> Result<Kernel> {
    let n = m.syms.q.len();
    let (doc, eq) = (
        "Impact with Coulomb friction at the striking point: `qdl` after the locks, `[v_t, v_n, v_r]`, Delassus `W`, response `R`",
        walker_scene::catalog::IMPACT_COULOMB_EQUATION,
    );
    let solved = solve(m, model, table)?;
    let t = &*table;
    let k = if closed {
        let c = coulomb_impact(m, model)?;
        kernel(
            t,
            "impact_coulomb",
            doc,
            eq,
            coulomb_outputs(&c),
            Shape::Parts,
            &[],
        )
    } else {
        let mut parts = names("qdl", n, 1);
        parts.extend(["v_t", "v_n", "v_r"].map(str::to_owned));
        parts.extend(DELASSUS.map(|(name, _, _)| name.to_owned()));
        parts.extend(names("R", n, 2));
        solve_only("impact_coulomb", doc, eq, parts, Shape::Parts)
    };
    let mut k = with_solve(k, solved, closed, t);
    k.args = kernel_args(t, &k, &m.syms.qd);
    Ok(k)
}
