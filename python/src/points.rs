//! `walk_points(...)`: independent walks at the points of a parameter grid, each exactly as
//! `simulate(...)` with that point's values, reduced to its outcome (steps, status, last step).
//! A column is a keyword (`mu0`, `c`, `t_set`, `phi` by their roles in the model, `omega0`
//! the paper's start parameter) or the name of any parameter of the model. Every point is
//! checked before any is walked. The points are walked one after another on one work thread
//! (a Dask worker's task is one core's work; parallelism comes from the workers) with the GIL
//! released, each walk asking before every step whether Ctrl-C was pressed (`crate::chunks`).
//! The grid streams: its columns come as bytes of `float64` (8 bytes a value, not a Python
//! float each), and a point's model is built when it is checked and again when it is walked,
//! never kept for all points, so that a call's memory is its columns and its results.

use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict};
use walker::model::Model;
use walker::setup::{Overrides, Setup};
use walker::sim::{Stopped, walk_stoppable};
use walker::vector::Vector;

use crate::chunks::{asked, stoppable};
use crate::error::ArgError;
use crate::options;
use crate::table::{Outcome, RESULT_COLUMNS, Rows, names_dict};
use crate::walker_args::{self, overrides};

/// The keyword columns: parameters by their role in the model, and the start parameter.
pub const KEYWORDS: [&str; 5] = ["mu0", "c", "t_set", "phi", "omega0"];

/// The most points a grid may have: its results are a few hundred bytes a point.
pub const MAX_GRID_POINTS: usize = 10_000_000;

/// The parameter a column sets: a keyword's by its role in the model (`t_set`: `T_set`), any
/// other column's its own name.
fn column_parameter(setup: &Setup, name: &str) -> Option<String> {
    let spec = setup.walker.spec();
    let role = |i: Option<usize>| i.map(|i| spec.model.parameters[i].name.name.clone());
    match name {
        "mu0" => role(spec.mu0),
        "c" => role(spec.c),
        "phi" => role(spec.slope),
        "t_set" => Some("T_set".to_owned()),
        other => Some(other.to_owned()),
    }
}

/// A grid column given as the bytes of `float64` values in native order.
fn floats(name: &str, bytes: &[u8]) -> Result<Vec<f64>, ArgError> {
    if !bytes.len().is_multiple_of(8) {
        return Err(ArgError::new(
            name,
            "the grid column must hold float64 values",
        ));
    }
    Ok(bytes
        .chunks_exact(8)
        .map(|b| f64::from_ne_bytes([b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7]]))
        .collect())
}

/// The model and the start of grid row `k`: `base` with the row's values, its start with the
/// components `init`, checked.
fn point(
    base: &Setup,
    grid: &[(String, Vec<f64>)],
    init: &[(usize, f64)],
    k: usize,
) -> Result<(Model, Vector), ArgError> {
    let row = |e: ArgError| ArgError::new(&e.arg, format!("{} (grid row {k})", e.message));
    let mut setup = base.clone();
    for (name, col) in grid {
        set_column(&mut setup, name, col[k]).map_err(|e| row(e.named(name)))?;
    }
    let model = walker_args::model(&setup).map_err(row)?;
    let start = model.start_state_replacing(init);
    walker_args::on_the_floor(&model, &start, init).map_err(row)?;
    Ok((model, start))
}

/// Sets column `name` of a point to `value` on `setup`: a keyword by its role, any other
/// column by its parameter name.
fn set_column(setup: &mut Setup, name: &str, value: f64) -> Result<(), ArgError> {
    let none = Overrides::default();
    let ov = match name {
        "mu0" => Overrides {
            mu0: Some(value),
            ..none
        },
        "c" => Overrides {
            c: Some(value),
            ..none
        },
        "t_set" => Overrides {
            t_set: Some(value),
            ..none
        },
        "phi" => Overrides {
            phi: Some(value),
            ..none
        },
        "omega0" => return walker_args::set_omega0(setup, Some(value), |_| true, "finite"),
        other => return Ok(setup.set(other, value)?),
    };
    Ok(setup.apply(&ov)?)
}

/// Walk every point of `grid` (columns in the caller's order) and return one row per point
/// ([`Rows`]' columns) with the model's names; with `check_only`, check every argument and
/// point as for the walks and return no rows (a Dask client's check before it sends work).
///
/// # Errors
/// `ValueError` naming a bad column or argument (with the row) and its valid range.
#[pyfunction]
#[pyo3(signature = (*, scene, model, set, init, grid, friction, impact, method, rtol, atol,
    duration, max_steps, until_periodic, check_only=false))]
#[allow(clippy::too_many_arguments)]
pub fn walk_points<'py>(
    py: Python<'py>,
    scene: Option<&str>,
    model: Option<&str>,
    set: Vec<(String, f64)>,
    init: Vec<(String, f64)>,
    grid: Vec<(String, Bound<'py, PyBytes>)>,
    friction: Option<&str>,
    impact: Option<&str>,
    method: &str,
    rtol: Option<f64>,
    atol: Option<f64>,
    duration: Option<f64>,
    max_steps: i64,
    until_periodic: Option<f64>,
    check_only: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let ov = overrides(None, None, None, None, friction, impact)?;
    let base = walker_args::setup_released(py, scene, model, &ov, &set)?;
    let cfg = options::config(method, rtol, atol)?;
    let limits = options::limits(duration, max_steps, until_periodic)?;
    let grid: Vec<(String, Vec<f64>)> = grid
        .iter()
        .map(|(name, b)| Ok((name.clone(), floats(name, b.as_bytes())?)))
        .collect::<Result<_, ArgError>>()?;
    let mut n = None;
    let mut seen: Vec<(String, &str)> = Vec::new();
    for (name, col) in &grid {
        if !KEYWORDS.contains(&name.as_str()) && base.params.index(name).is_err() {
            let params: Vec<&str> = base.params.iter().map(|(p, _)| p).collect();
            return Err(ArgError::new(
                "grid",
                format!(
                    "unknown column {name:?}: must be one of {} or a parameter of model `{}` ({})",
                    KEYWORDS.join(", "),
                    base.walker.spec().name(),
                    params.join(", ")
                ),
            )
            .into());
        }
        if RESULT_COLUMNS.contains(&name.as_str()) {
            return Err(ArgError::new(
                "grid",
                format!("column {name:?} has the name of a result column"),
            )
            .into());
        }
        if *n.get_or_insert(col.len()) != col.len() {
            return Err(ArgError::new("grid", "the columns must have the same length").into());
        }
        if let Some(p) = column_parameter(&base, name) {
            if let Some((_, other)) = seen.iter().find(|(q, _)| *q == p) {
                return Err(ArgError::new(
                    "grid",
                    format!("columns {other:?} and {name:?} both set {p}; give one"),
                )
                .into());
            }
            seen.push((p, name.as_str()));
        }
    }
    let n = n.unwrap_or(0);
    if n > MAX_GRID_POINTS {
        return Err(ArgError::new("grid", format!("{n} points: at most {MAX_GRID_POINTS}")).into());
    }
    // The same start for every point: its names are checked once, not per row.
    let init = walker_args::check_init(base.walker.spec(), &init)?;
    let spec = std::sync::Arc::clone(base.walker.spec());
    let rows = stoppable(py, |stop| {
        // Every point is checked before any is walked; its model is not kept.
        for k in 0..n {
            if asked(stop) {
                return Ok(Err(Stopped));
            }
            point(&base, &grid, &init, k)?;
        }
        let mut rows = Rows::new(spec.n);
        for k in (0..n).filter(|_| !check_only) {
            let (model, start) = point(&base, &grid, &init, k)?;
            match walk_stoppable(&model, &cfg, &start, &limits, &|| asked(stop)) {
                Ok(w) => rows.push(&Outcome::of(w)),
                Err(Stopped) => return Ok(Err(Stopped)),
            }
        }
        Ok::<_, ArgError>(Ok(rows))
    })??;
    let Ok(rows) = rows else {
        return Err(pyo3::exceptions::PyKeyboardInterrupt::new_err(()));
    };
    let d = rows.into_dict(py)?;
    names_dict(&d, &spec)?;
    Ok(d)
}
