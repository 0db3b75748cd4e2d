//! Errors of a model's derivation at their place in the model file: a singular matrix is
//! reported by the engine by its name (`M`, `A`, `X_I`, ...); here it becomes the model's own
//! words, with the file, line and column of the declaration responsible.

use walker_scene::model::{Location, Model};

use super::mechanics::generic_point;
use super::table::ModelSymbols;
use crate::error::Error;
use crate::matrix::Matrix;

/// `path:line:col: what`.
fn at(model: &Model, location: Location, what: impl std::fmt::Display) -> Error {
    Error::CheckFailed {
        what: format!("{}:{location}: {what}", model.path),
    }
}

/// Where the symbol called `name` is declared: a coordinate (or its velocity or acceleration),
/// a parameter, an input or an output's auxiliary input.
pub(crate) fn declaration(model: &Model, name: &str) -> Option<Location> {
    let coordinate = model.coordinates.iter().find(|c| {
        let n = c.name.name.as_str();
        name.strip_prefix(n)
            .is_some_and(|rest| rest.is_empty() || rest == "d" || rest == "dd")
    });
    coordinate
        .map(|c| c.name.location)
        .or_else(|| {
            model
                .parameters
                .iter()
                .find(|p| p.name.name == name)
                .map(|p| p.name.location)
        })
        .or_else(|| {
            model
                .inputs
                .iter()
                .find(|i| i.name.name == name)
                .map(|i| i.name.location)
        })
        .or_else(|| {
            model
                .outputs
                .iter()
                .find(|o| o.aux.name == name)
                .map(|o| o.aux.location)
        })
}

/// The error of a symbol table that refuses the symbol called `name` (too many symbols or
/// angles, a name taken twice): at the symbol's declaration.
pub(crate) fn symbol_error(model: &Model, name: &str, err: Error) -> Error {
    let what = match &err {
        Error::CheckFailed { what } => what.clone(),
        other => other.to_string(),
    };
    match declaration(model, name) {
        Some(location) => at(model, location, format!("symbol `{name}`: {what}")),
        None => Error::CheckFailed {
            what: format!("{}: symbol `{name}`: {what}", model.path),
        },
    }
}

/// The coordinates whose combination moves nothing: those with a component above `1e-6` of the
/// largest in a null vector of `M` at a generic configuration (Gaussian elimination with full
/// pivoting; pivots below `1e-9` of the largest diagonal entry count as zero, as in the
/// regularity test of `M`). Empty if `M` is regular there.
pub(crate) fn dependent_coordinates(
    model: &Model,
    syms: &ModelSymbols,
    mass: &Matrix,
) -> Vec<usize> {
    let n = syms.q.len();
    let p = generic_point(model, syms, &syms.table, 1);
    let mut a: Vec<Vec<f64>> = (0..n)
        .map(|i| (0..n).map(|j| mass.get(i, j).eval(&p)).collect())
        .collect();
    let scale = (0..n).map(|i| a[i][i].abs()).fold(0.0, f64::max);
    if !scale.is_finite() || scale == 0.0 {
        return (0..n).collect();
    }
    // Row echelon form with full pivoting; `cols[k]` is the column of pivot k.
    let mut cols: Vec<usize> = (0..n).collect();
    let mut rank = 0;
    while rank < n {
        let mut best = (rank, rank, 0.0);
        for (i, row) in a.iter().enumerate().skip(rank) {
            for (jj, &c) in cols.iter().enumerate().skip(rank) {
                if row[c].abs() > best.2 {
                    best = (i, jj, row[c].abs());
                }
            }
        }
        if best.2 <= 1e-9 * scale {
            break;
        }
        a.swap(rank, best.0);
        cols.swap(rank, best.1);
        let pc = cols[rank];
        for i in rank + 1..n {
            let f = a[i][pc] / a[rank][pc];
            for &c in &cols {
                a[i][c] -= f * a[rank][c];
            }
        }
        rank += 1;
    }
    if rank == n {
        return Vec::new();
    }
    // The null vector with the first free column at one, by back substitution.
    let mut v = vec![0.0; n];
    v[cols[rank]] = 1.0;
    for k in (0..rank).rev() {
        let pc = cols[k];
        let s: f64 = cols[k + 1..].iter().map(|&c| a[k][c] * v[c]).sum();
        v[pc] = -s / a[k][pc];
    }
    let largest = v.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    (0..n).filter(|&i| v[i].abs() > 1e-6 * largest).collect()
}

/// A singular matrix of the derivation (the engine's [`Error::SingularMatrix`]) in the model's
/// words, at the declaration responsible: `A` or `A_s` at the first output, `X_I` or `X_L` at
/// the first impact lock (or the striking point), `M` or `M_aa` at the first coordinate.
/// Other errors are returned as they are.
pub(crate) fn singular(model: &Model, err: Error) -> Error {
    let Error::SingularMatrix { name } = &err else {
        return err;
    };
    match name.as_str() {
        "A" | "A_s" => match model.outputs.first() {
            Some(o) => at(
                model,
                o.h.location,
                format!(
                    "the outputs make {name} (Eq. 30) singular at every posture: they are not \
                     independent through the inputs"
                ),
            ),
            None => err,
        },
        "X_I" | "X_L" => {
            let location = model
                .impact
                .locks
                .first()
                .map_or(model.strike.point.location, |l| l.location);
            at(
                model,
                location,
                format!(
                    "the impact's constraints (the striking point `{}` and the locks) are not \
                     independent: {name} = J M^-1 J^T is singular",
                    model.strike.point.name
                ),
            )
        }
        "M" | "M_aa" => match model.coordinates.first() {
            Some(c) => at(
                model,
                c.name.location,
                format!(
                    "the mass matrix {name} is singular: the bodies do not move independently \
                     in the coordinates"
                ),
            ),
            None => err,
        },
        _ => Error::CheckFailed {
            what: format!("{}: {err}", model.path),
        },
    }
}
