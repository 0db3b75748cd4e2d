//! Building a model's [`Kernel`] values: output names, arguments (the symbols other than
//! parameters and locals that a kernel's forms contain), closed forms and structured solves.

use crate::kernels::{Kernel, Shape, Staged};
use crate::matrix::Matrix;
use crate::ratfunc::RatFunc;
use crate::symbol::{Sym, SymKind, Symbols};

/// The entries of `m` as outputs `prefix{i}{j}` (a matrix; `prefix{i}_{j}` past ten rows) or
/// `prefix{k}` (a row or column).
pub(crate) fn named(prefix: &str, m: &Matrix) -> Vec<(String, RatFunc)> {
    let c = m.cols();
    m.entries()
        .iter()
        .enumerate()
        .map(|(k, r)| {
            // Row and column run together while the row has one digit (every shipped model's
            // matrices); past ten rows an underscore parts them (`J1_11` is not `J11_1`).
            let name = if m.rows() > 10 && c > 1 {
                format!("{prefix}{}_{}", k / c, k % c)
            } else if m.rows() > 1 && c > 1 {
                format!("{prefix}{}{}", k / c, k % c)
            } else {
                format!("{prefix}{k}")
            };
            (name, r.clone())
        })
        .collect()
}

/// The symbols other than parameters and locals that `exprs` contain (plus `always`), in table
/// order.
pub(super) fn args_of<'r>(
    symbols: &Symbols,
    exprs: impl Iterator<Item = &'r RatFunc>,
    always: &[Sym],
) -> Vec<Sym> {
    let mut used = std::collections::BTreeSet::new();
    for r in exprs {
        for p in [r.num(), r.den()] {
            for slot in p.slots() {
                if let Some(s) = symbols.symbol_of_slot(slot)
                    && !matches!(symbols.kind(s), SymKind::Parameter | SymKind::Local)
                {
                    used.insert(s);
                }
            }
        }
    }
    used.extend(always.iter().copied());
    used.into_iter().collect()
}

/// `k` with its structured solve: the closed form and the solve both, when the closed form
/// exists (`closed`); else the solve alone, its outputs under the kernel's output names. The
/// arguments are those of every form.
pub(super) fn with_solve(mut k: Kernel, solve: Staged, closed: bool, symbols: &Symbols) -> Kernel {
    if !closed {
        for ((_, out), expr) in k.outputs.iter_mut().zip(&solve.outputs) {
            *out = expr.clone();
        }
        k.staged = None;
        k.closed = false;
    }
    k.solve = Some(solve);
    let always = k.args.clone();
    k.args = kernel_args(symbols, &k, &always);
    k
}

/// The arguments of `k` over all its forms: the symbols other than parameters, locals and the
/// symbols its staged form binds (the closed loop's `u`, computed inside), plus `always`.
pub(super) fn kernel_args(symbols: &Symbols, k: &Kernel, always: &[Sym]) -> Vec<Sym> {
    let bound: Vec<Sym> = [&k.staged, &k.solve]
        .into_iter()
        .flatten()
        .flat_map(|st| st.locals.iter().map(|(s, _)| *s))
        .collect();
    let mut args = args_of(symbols, k.expressions(), always);
    args.retain(|s| !bound.contains(s) || always.contains(s));
    args
}

/// A kernel of closed forms; its arguments are what the outputs contain, and `always`.
pub(super) fn kernel(
    symbols: &Symbols,
    name: &'static str,
    doc: &'static str,
    equation: &'static str,
    outputs: Vec<(String, RatFunc)>,
    shape: Shape,
    always: &[Sym],
) -> Kernel {
    let args = args_of(symbols, outputs.iter().map(|(_, r)| r), always);
    Kernel::closed_form(name, doc, equation, args, outputs, shape)
}

/// The output names [`named`] gives a `rows x cols` matrix.
pub(super) fn names(prefix: &str, rows: usize, cols: usize) -> Vec<String> {
    (0..rows * cols)
        .map(|k| {
            // As `named`: past ten rows an underscore parts row and column.
            if rows > 10 && cols > 1 {
                format!("{prefix}{}_{}", k / cols, k % cols)
            } else if rows > 1 && cols > 1 {
                format!("{prefix}{}{}", k / cols, k % cols)
            } else {
                format!("{prefix}{k}")
            }
        })
        .collect()
}

/// A kernel that only has its structured solve: its outputs are the solve's, named.
pub(super) fn solve_only(
    name: &'static str,
    doc: &'static str,
    equation: &'static str,
    names: Vec<String>,
    shape: Shape,
) -> Kernel {
    Kernel {
        name,
        doc,
        equation,
        args: Vec::new(),
        outputs: names.into_iter().map(|n| (n, RatFunc::zero())).collect(),
        shape,
        staged: None,
        solve: None,
        closed: false,
    }
}
