//! What a simulator reports of a model's gait besides its state (Eqs. 33-34, 47): the
//! outputs and their rates (`output_rates`), the rate at which each input does work
//! (`input_rates`: the input power is `u_i w_i`), and the total mass (`total_mass`, for the
//! specific resistance); and the partial derivatives of the rates by the state
//! (`output_rates_jacobian`, `input_rates_jacobian`: the chain rule of a stance Jacobian
//! through the control's `v(y, ydot)` and through the power's integrand), every column of
//! `[q, qdot]` present.

use walker_scene::model::Model;

use super::assemble::{kernel, named};
use super::mechanics::Mechanics;
use super::phases::output_maps;
use crate::error::Result;
use crate::kernels::{Kernel, Shape};
use crate::matrix::Matrix;
use crate::ratfunc::RatFunc;
use crate::symbol::Symbols;

/// The descriptor kernels of `model`: `output_rates` (with outputs), `input_rates` (with
/// inputs) and `total_mass`.
///
/// # Errors
/// An output or a body's mass that does not lower.
pub(super) fn descriptor_kernels(
    m: &Mechanics,
    model: &Model,
    table: &Symbols,
) -> Result<Vec<Kernel>> {
    let mut kernels = Vec::new();
    let qd = m.qd_column();
    let state: Vec<_> = m.syms.q.iter().chain(&m.syms.qd).copied().collect();
    let n2 = state.len();
    if !model.outputs.is_empty() {
        let maps = output_maps(m, model)?;
        let rates = maps.jacobian.mul(&qd)?;
        let both: Vec<RatFunc> = maps.y.iter().chain(rates.entries()).cloned().collect();
        let mut outputs = named("y", &Matrix::column(maps.y));
        outputs.extend(named("yd", &rates));
        kernels.push(kernel(
            table,
            "output_rates",
            "Controlled outputs `y = h(q)` and their rates `ydot = H qdot`",
            "Eqs. 30-32",
            outputs,
            Shape::Parts,
            &[],
        ));
        kernels.push(kernel(
            table,
            "output_rates_jacobian",
            "Partial derivatives of the outputs and their rates `[y, ydot]` by `(q, qdot)`",
            "Eqs. 30-32",
            named("J", &Matrix::jacobian(&both, &state)),
            Shape::Matrix(both.len(), n2),
            &[],
        ));
    }
    let inputs = m.input_map.cols();
    if inputs > 0 {
        let w = m.input_map.transpose().mul(&qd)?;
        kernels.push(kernel(
            table,
            "input_rates",
            "The rate `w = S^T qdot` at which each input does work: its power is `u w`",
            "Eq. 34",
            named("w", &w),
            Shape::Vector(inputs),
            &[],
        ));
        kernels.push(kernel(
            table,
            "input_rates_jacobian",
            "Partial derivatives of the inputs' rates `w` by `(q, qdot)`",
            "Eq. 34",
            named("J", &Matrix::jacobian(w.entries(), &state)),
            Shape::Matrix(inputs, n2),
            &[],
        ));
    }
    let mut mass = RatFunc::zero();
    for b in &model.bodies {
        mass = mass + &m.syms.lower(&b.mass)?;
    }
    kernels.push(kernel(
        table,
        "total_mass",
        "Total mass of the bodies",
        "Eq. 47",
        vec![("m_total".into(), mass)],
        Shape::Scalar,
        &[],
    ));
    Ok(kernels)
}
