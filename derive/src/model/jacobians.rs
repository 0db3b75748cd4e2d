//! The partial derivatives of a model's stance and impact maps, for implicit integrators,
//! variational equations and the Jacobian of a Poincare map: closed forms only, derived where
//! the closed-form stance and impact are (a structured solve has no closed form to
//! differentiate), absent otherwise.
//!
//! Columns, every one present even where it is identically zero (the foot's `x`, `z`), so that
//! a simulator indexes them uniformly:
//! - `accel_jacobian` (a model without inputs): `d qdd / d [q, qdot, mu]`, `n x (2n + 1)`;
//! - `closed_loop_jacobian` (a model with outputs): `d [qdd, u] / d [q, qdot, mu, v]` of
//!   `closed_loop`'s outputs, `(n + m) x (2n + 1 + m)` (the inputs' rows for the input power's
//!   integrand);
//! - `impact_jacobian`: `d qdot+ / d [q, qdot]` of `impact`'s `qdot+`, `n x 2n`;
//! - `stick_jacobian` (a model without inputs, where the stuck stance has its closed form):
//!   `d [qdd, lambda_t, lambda_n] / d [q, qdot]` of `stick`'s outputs, `(n + 2) x 2n`: the
//!   stuck phase of exact Coulomb friction in the variational equations, and the gradient of
//!   its slip guard `|lambda_t| - mu0 lambda_n` for the saltation where the foot starts to
//!   slip. `stick` has no friction coefficient (the floor holds the foot), so no `mu` column.
//!
//! `mu` is the friction coefficient itself: the code generator substitutes the scene's friction
//! law for it afterwards, and the caller applies the chain rule `d mu / d xdot`.
//!
//! Each kernel's outputs are the derivatives themselves (`(N' D - N D') / D^2`, cancelled), and
//! its staged form, which the code generator evaluates, is the quotient rule over the map's own
//! numerator and denominator: `f = N / D` and `D` once per row, then `(N' - f D') / D` per
//! column. Expanded, the products `N' D` and `N D'` multiply the parameters' polynomials of
//! both factors into new ones: with the parameters given at run time, the hoisted part
//! (`prepare`) of the paper's passive walker grew to 13419 operations in 3629 `let`s, on
//! which rustc's debug-info generation overflowed its stack; staged, no product is formed.

use super::assemble::{kernel, named, names, solve_only, with_solve};
use super::forward::differentiate;
use super::mechanics::Mechanics;
use super::program::Program;
use super::structured::StructuredKernels;
use crate::error::Result;
use crate::kernels::{Kernel, Shape, Staged};
use crate::matrix::Matrix;
use crate::ratfunc::{RatFunc, diff_poly};
use crate::symbol::{Atom, Sym, Symbols};

/// The closed forms the Jacobians differentiate: the sliding stance's `qdd` (of a model without
/// inputs), the closed loop's `qdd` (with outputs) and the impact's `qdot+`, each a column.
pub(super) struct Differentiated<'a> {
    /// `accel`'s `qdd`, for a model without inputs.
    pub(super) accel: Option<&'a Matrix>,
    /// `closed_loop`'s `[qdd, u]` with `u` substituted, a column.
    pub(super) closed_loop: Option<&'a Matrix>,
    /// `impact`'s `qdot+`.
    pub(super) impact: &'a Matrix,
}

/// `d f / d vars` (rows of `f`, columns of `vars`, row-major) and its staged form by the
/// quotient rule. The derivatives are the staged form composed (its locals substituted back,
/// last to first, as [`Kernel::check_staged`] does): the quotient rule of [`RatFunc::diff`],
/// cancelled step by step, so that the check finds the same denominators and compares the
/// numerators directly (`RatFunc::diff`'s single cancellation of `(N' D - N D') / D^2` leaves
/// other representations of the same functions, whose comparison multiplies them out: three
/// times the derivation's time for the passive walker).
fn jacobian(
    f: &Matrix,
    vars: &[Sym],
    table: &mut Symbols,
    name: &'static str,
) -> Result<(Vec<RatFunc>, Staged)> {
    let mut p = Program::new(table, name);
    let mut outputs = Vec::with_capacity(f.entries().len() * vars.len());
    for r in f.entries() {
        let value = p.bind(r.clone())?;
        let den = p.bind(r.den().clone().into())?;
        for &x in vars {
            let dn: RatFunc = diff_poly(r.num(), x).into();
            let dd: RatFunc = diff_poly(r.den(), x).into();
            outputs.push((&dn - &(&value * &dd)).div(&den)?);
        }
    }
    let staged = p.finish(outputs);
    let mut full = Vec::with_capacity(staged.outputs.len());
    for out in &staged.outputs {
        let mut r = out.clone();
        for (s, value) in staged.locals.iter().rev() {
            r = r.substitute(Atom::Sym(*s), value)?;
        }
        full.push(r);
    }
    Ok((full, staged))
}

/// A Jacobian kernel: the derivatives as outputs, the quotient rule as the staged form.
#[allow(clippy::too_many_arguments)]
fn jacobian_kernel(
    table: &mut Symbols,
    name: &'static str,
    doc: &'static str,
    equation: &'static str,
    f: &Matrix,
    vars: &[Sym],
    always: &[Sym],
) -> Result<Kernel> {
    let (full, staged) = jacobian(f, vars, table, name)?;
    let full = Matrix::from_rows(full.chunks(vars.len()).map(<[RatFunc]>::to_vec).collect())?;
    let mut k = kernel(
        table,
        name,
        doc,
        equation,
        named("J", &full),
        Shape::Matrix(f.rows(), vars.len()),
        always,
    );
    k.staged = Some(staged);
    Ok(k)
}

/// The Jacobian kernels of the closed forms in `of`.
///
/// # Errors
/// A full symbol table.
pub(super) fn jacobian_kernels(
    m: &Mechanics,
    of: &Differentiated,
    table: &mut Symbols,
) -> Result<Vec<Kernel>> {
    let state: Vec<Sym> = m.syms.q.iter().chain(&m.syms.qd).copied().collect();
    let mut kernels = Vec::new();
    if let Some(accel) = of.accel {
        let mut vars = state.clone();
        vars.push(m.syms.mu);
        kernels.push(jacobian_kernel(
            table,
            "accel_jacobian",
            "Partial derivatives of the sliding stance's accelerations by (q, qdot, mu)",
            "Eq. 27",
            accel,
            &vars,
            &[],
        )?);
    }
    if let Some(closed_loop) = of.closed_loop {
        let mut vars = state.clone();
        vars.push(m.syms.mu);
        vars.extend(&m.syms.aux);
        kernels.push(jacobian_kernel(
            table,
            "closed_loop_jacobian",
            "Partial derivatives of the closed-loop accelerations and inputs by (q, qdot, mu, v)",
            "Eqs. 27, 31",
            closed_loop,
            &vars,
            &[],
        )?);
    }
    kernels.push(jacobian_kernel(
        table,
        "impact_jacobian",
        "Partial derivatives of the post-impact velocities by (q, qdot)",
        "Eqs. 6-16, 39-42",
        of.impact,
        &state,
        &m.syms.qd,
    )?);
    Ok(kernels)
}

/// `stick_jacobian`: `d [qdd, lambda_t, lambda_n] / d [q, qdot]` of the stuck stance's closed
/// form `stick` (a column), every column present (see the module documentation).
///
/// # Errors
/// A full symbol table.
pub(super) fn stick_jacobian(m: &Mechanics, stick: &Matrix, table: &mut Symbols) -> Result<Kernel> {
    let state: Vec<Sym> = m.syms.q.iter().chain(&m.syms.qd).copied().collect();
    jacobian_kernel(
        table,
        "stick_jacobian",
        "Partial derivatives of the stuck stance's accelerations and ground force by (q, qdot)",
        "stick phase; Eq. 19 with both foot coordinates held",
        stick,
        &state,
        &[],
    )
}

/// The most coordinates for which a model without closed forms gets Jacobian kernels (its
/// structured solves differentiated): five, as many as the Poincare map's variational equations
/// take (`walker`'s `poincare/map.rs`). The five-link biped's (seven coordinates) would have
/// 16 000 and 12 500 operations and take 3.4 s to derive and lower at every run-time load
/// (against 0.2 s), for a map that could not use them.
pub const MAX_STRUCTURED_JACOBIAN_COORDINATES: usize = 5;

/// The stance's Jacobian kernels of a model without closed forms, by forward-mode
/// differentiation of its structured solves (`forward.rs`), with the closed forms' columns:
/// `accel_jacobian` (without inputs, `d qdd / d [q, qdot, mu]`) or, with outputs,
/// `closed_loop_jacobian` (`d [qdd, u] / d [q, qdot, mu, v]`) and `closed_loop_stick_jacobian`
/// (`d [qdd, u, lambda_t, lambda_n] / d [q, qdot, v]` of `closed_loop_stick`, the held foot:
/// without it the held foot is differentiated through the sliding kernel at the friction ratio
/// that holds it, which divides by the foot's compliance to friction and, for the three-link
/// biped, amplified rounding to `1e-9` relative). The impact's Jacobian is left to the Poincare
/// map, which differentiates the impact's solve in its own way (linear in the velocities).
///
/// # Errors
/// A full symbol table, or an arithmetic error of the differentiation.
pub(super) fn structured_jacobian_kernels(
    m: &Mechanics,
    solves: &StructuredKernels,
    loop_stick: Option<&Kernel>,
    table: &mut Symbols,
) -> Result<Vec<Kernel>> {
    let n = m.syms.q.len();
    if n > MAX_STRUCTURED_JACOBIAN_COORDINATES {
        return Ok(Vec::new());
    }
    let inputs = m.syms.inputs.len();
    let state: Vec<Sym> = m.syms.q.iter().chain(&m.syms.qd).copied().collect();
    let mut with_mu = state.clone();
    with_mu.push(m.syms.mu);
    let mut kernels = Vec::new();
    let mut push = |name: &'static str,
                    doc: &'static str,
                    equation: &'static str,
                    program: &Staged,
                    rows: usize,
                    vars: &[Sym],
                    table: &mut Symbols|
     -> Result<()> {
        // Named apart from the closed form's staged locals (`jacobian`).
        let staged = differentiate(program, vars, table, &format!("{name}.forward"))?;
        let k = solve_only(
            name,
            doc,
            equation,
            names("J", rows, vars.len()),
            Shape::Matrix(rows, vars.len()),
        );
        kernels.push(with_solve(k, staged, false, table));
        Ok(())
    };
    match &solves.closed_loop {
        Some(closed_loop) => {
            let mut vars = with_mu.clone();
            vars.extend(&m.syms.aux);
            push(
                "closed_loop_jacobian",
                "Partial derivatives of the closed-loop accelerations and inputs by (q, qdot, mu, v)",
                "Eqs. 27, 31",
                closed_loop,
                n + inputs,
                &vars,
                table,
            )?;
            if let Some(held) = loop_stick.and_then(|k| k.solve.as_ref()) {
                let mut vars = state.clone();
                vars.extend(&m.syms.aux);
                push(
                    "closed_loop_stick_jacobian",
                    "Partial derivatives of the held foot's closed-loop accelerations, inputs and ground force by (q, qdot, v)",
                    "stick phase; Eqs. 30-31 with both foot coordinates held",
                    held,
                    n + inputs + 2,
                    &vars,
                    table,
                )?;
            }
        }
        None if inputs == 0 => push(
            "accel_jacobian",
            "Partial derivatives of the sliding stance's accelerations by (q, qdot, mu)",
            "Eq. 27",
            &solves.accel,
            n,
            &with_mu,
            table,
        )?,
        None => {}
    }
    Ok(kernels)
}
