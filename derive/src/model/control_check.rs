//! Whether the output-following control can be applied: `A = H M^-1 Y S` (Eq. 30) regular at
//! the model's start posture (`[start]`), and not singular identically.
//!
//! The structured solve inverts `A` by its adjugate over locals, so an `A` that is singular for
//! every state (two outputs that the inputs cannot move independently) is not visible
//! symbolically; it is found here in floating point, at the parameters' defaults, where `A` is
//! evaluated from the `control` kernel: singular at three generic configurations means singular
//! identically (a regular `A` is singular only on a set of measure zero). At the start posture a
//! singular `A` would stop every walk at its first step.

use walker_scene::model::Model;

use super::mechanics::{default_point, generic_point};
use super::table::ModelSymbols;
use crate::error::{Error, Result};
use crate::kernels::Kernel;
use crate::symbol::Point;

/// `|det A|` relative to the product of its rows' norms (Hadamard's bound): zero for a
/// singular `A`, one for orthogonal rows. Gaussian elimination with partial pivoting.
fn relative_det(mut a: Vec<Vec<f64>>) -> f64 {
    let n = a.len();
    let hadamard: f64 = a
        .iter()
        .map(|r| r.iter().map(|x| x * x).sum::<f64>().sqrt())
        .product();
    if hadamard.is_nan() || hadamard <= 0.0 || hadamard.is_infinite() {
        return 0.0;
    }
    let mut det = 1.0;
    for c in 0..n {
        let Some(p) = (c..n).max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs())) else {
            return 0.0;
        };
        if a[p][c] == 0.0 {
            return 0.0;
        }
        a.swap(c, p);
        det *= a[c][c];
        let pivot = a[c].clone();
        for row in a.iter_mut().skip(c + 1) {
            let f = row[c] / pivot[c];
            for (x, y) in row.iter_mut().zip(&pivot).skip(c) {
                *x -= f * y;
            }
        }
    }
    (det / hadamard).abs()
}

/// `A` from the `control` kernel at `p`, row-major as the kernel gives it.
fn a_at(control: &Kernel, p: &Point<f64>, m: usize) -> Vec<Vec<f64>> {
    let out = control
        .eval_solve(p)
        .or_else(|| control.eval_closed(p))
        .unwrap_or_default();
    (0..m)
        .map(|i| {
            (0..m)
                .map(|j| out.get(i * m + j).copied().unwrap_or(0.0))
                .collect()
        })
        .collect()
}

/// Below this relative determinant `A` counts as singular: `1e-10`, far above the rounding of
/// an `A` of order one evaluated through a few solves (about `1e-14`), far below the value of a
/// regular `A` at a generic posture.
const SINGULAR: f64 = 1e-10;

/// Checks the control of `model`, whose `control` kernel is `control` (symbols in `table`).
///
/// # Errors
/// [`Error::CheckFailed`] naming the model file, line and column: `A` singular identically
/// (at the first output), or at the start posture (at the first start value).
pub fn check_control(
    model: &Model,
    syms: &ModelSymbols,
    table: &crate::symbol::Symbols,
    control: &Kernel,
) -> Result<()> {
    let m = model.outputs.len();
    let Some(first) = model.outputs.first() else {
        return Ok(());
    };
    let regular_somewhere = (1..=3)
        .any(|c| relative_det(a_at(control, &generic_point(model, syms, table, c), m)) > SINGULAR);
    if !regular_somewhere {
        return Err(Error::CheckFailed {
            what: format!(
                "{}:{}: the outputs make A (Eq. 30) singular at every posture: they are not \
                 independent through the inputs",
                model.path, first.h.location
            ),
        });
    }
    let Some(at) = model.start.first() else {
        return Ok(());
    };
    let mut p = default_point(model, syms, table);
    let params = p.clone();
    for v in &model.start {
        let value = syms.lower(&v.value)?.eval(&params);
        let s = if v.velocity {
            syms.qd[v.coordinate]
        } else {
            syms.q[v.coordinate]
        };
        p.set_sym(s, value);
    }
    let det = relative_det(a_at(control, &p, m));
    if det > SINGULAR {
        Ok(())
    } else {
        Err(Error::CheckFailed {
            what: format!(
                "{}:{}: the outputs make A (Eq. 30) singular at the start posture [start] \
                 (relative determinant {det:.1e}): no walk could take its first step",
                model.path, at.value.location
            ),
        })
    }
}
