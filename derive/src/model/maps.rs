//! The matrices the stance and impact kernels are built from, as kernels of their own: the input
//! map `S`, the impact's constraint rows `J_I` (with and without the old stance foot), and the
//! controlled outputs `y = h(q)` with their Jacobian `H` and drift `Hdot qdot` (Eqs. 30-31).
//!
//! A user's own solver (a QP controller, a contact-implicit optimiser) needs exactly these; the
//! verification suite feeds them, with `M` and `h`, to generic linear algebra and compares its
//! solves with the generated closed forms and structured solves.

use walker_scene::model::Model;

use super::assemble::{kernel, named};
use super::mechanics::Mechanics;
use super::phases::{OutputMaps, StrikeRows, output_maps};
use crate::error::Result;
use crate::kernels::{Kernel, Shape};
use crate::matrix::Matrix;
use crate::ratfunc::RatFunc;
use crate::symbol::Symbols;

/// The map kernels of a model: `input_map` (for a model with inputs), `impact_rows`,
/// `impact_double_rows` (for the double-support test) and `outputs` (for a model with outputs).
///
/// # Errors
/// An output expression that does not lower.
pub fn map_kernels(
    m: &Mechanics,
    model: &Model,
    rows: &StrikeRows,
    table: &Symbols,
) -> Result<Vec<Kernel>> {
    let n = m.syms.q.len();
    let mut kernels = Vec::new();
    if m.input_map.cols() > 0 {
        kernels.push(kernel(
            table,
            "input_map",
            "Input map `S`: the generalised force of each input per unit input, one column per input",
            "Eq. 19",
            named("S", &m.input_map),
            Shape::Matrix(n, m.input_map.cols()),
            &[],
        ));
    }
    let jacobian = |r: &[RatFunc]| Matrix::jacobian(r, &m.syms.q);
    kernels.push(kernel(
        table,
        "impact_rows",
        "Constraint rows `J_I` of the impact: the gradients of the striking point's gap and of the locks",
        "Eqs. 6-10",
        named("JI", &jacobian(&rows.single)),
        Shape::Matrix(rows.single.len(), n),
        &[],
    ));
    if let Some(double) = &rows.double {
        kernels.push(kernel(
            table,
            "impact_double_rows",
            "Constraint rows `J_I` of the double-support test: the striking point, the old stance foot, the locks",
            "Eqs. 11, 46",
            named("JI", &jacobian(double)),
            Shape::Matrix(double.len(), n),
            &[],
        ));
    }
    if !model.outputs.is_empty() {
        let OutputMaps { y, jacobian, drift } = output_maps(m, model)?;
        let mut outputs = named("y", &Matrix::column(y));
        outputs.extend(named("H", &jacobian));
        outputs.extend(named("Hdqd", &Matrix::column(drift)));
        kernels.push(kernel(
            table,
            "outputs",
            "Controlled outputs `y = h(q)`, their Jacobian `H` and the drift `Hdot qdot`",
            "Eqs. 30-31",
            outputs,
            Shape::Parts,
            &[],
        ));
    }
    Ok(kernels)
}
