//! `walk_points(...)`: independent walks at the points of a parameter grid, each exactly as
//! `simulate(...)` with that point's values, reduced to its outcome (steps, status, last step).
//! A column is a keyword (`mu0`, `c`, `t_set`, `phi` by their roles in the model, `omega0`
//! the paper's start parameter) or the name of any parameter of the model. Every point is
//! checked before any is walked. The points are walked one after another on the calling thread
//! (a Dask worker's task is one core's work; parallelism comes from the workers), in chunks
//! between checks for Ctrl-C.

use pyo3::prelude::*;
use pyo3::types::PyDict;
use walker::model::Model;
use walker::setup::{Overrides, Setup};
use walker::sim::walk;
use walker::vector::Vector;

use crate::chunks::in_chunks;
use crate::error::ArgError;
use crate::options;
use crate::table::{Outcome, RESULT_COLUMNS, Rows, names_dict};
use crate::walker_args::{self, overrides};

/// The keyword columns: parameters by their role in the model, and the start parameter.
pub const KEYWORDS: [&str; 5] = ["mu0", "c", "t_set", "phi", "omega0"];

/// Points walked between two checks for Ctrl-C.
const CHUNK: usize = 16;

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
/// ([`Rows`]' columns) with the model's names.
///
/// # Errors
/// `ValueError` naming a bad column or argument (with the row) and its valid range.
#[pyfunction]
#[pyo3(signature = (*, scene, model, set, init, grid, friction, impact, method, rtol, atol,
    duration, max_steps, until_periodic))]
#[allow(clippy::too_many_arguments)]
pub fn walk_points<'py>(
    py: Python<'py>,
    scene: Option<&str>,
    model: Option<&str>,
    set: Vec<(String, f64)>,
    init: Vec<(String, f64)>,
    grid: Vec<(String, Vec<f64>)>,
    friction: Option<&str>,
    impact: Option<&str>,
    method: &str,
    rtol: Option<f64>,
    atol: Option<f64>,
    duration: Option<f64>,
    max_steps: i64,
    until_periodic: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let ov = overrides(None, None, None, None, friction, impact)?;
    let base = walker_args::setup(scene, model, &ov, &set)?;
    let cfg = options::config(method, rtol, atol)?;
    let limits = options::limits(duration, max_steps, until_periodic)?;
    let mut n = None;
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
    }
    let n = n.unwrap_or(0);
    // The same start for every point: its names are checked once, not per row.
    let init = walker_args::check_init(base.walker.spec(), &init)?;
    let mut points: Vec<(Model, Vector)> = Vec::with_capacity(n);
    for k in 0..n {
        let row = |e: ArgError| ArgError::new(&e.arg, format!("{} (grid row {k})", e.message));
        let mut setup = base.clone();
        for (name, col) in &grid {
            set_column(&mut setup, name, col[k]).map_err(|e| row(e.named(name)))?;
        }
        let model = walker_args::model(&setup).map_err(row)?;
        let start = model.start_state_replacing(&init);
        points.push((model, start));
    }
    let mut outcomes: Vec<Outcome> = Vec::with_capacity(n);
    in_chunks(py, &mut outcomes, n, CHUNK, |out, range| {
        for (model, start) in &points[range] {
            out.push(Outcome::of(walk(model, &cfg, start, &limits)));
        }
    })?;
    let spec = base.walker.spec();
    let mut rows = Rows::new(spec.n);
    for o in &outcomes {
        rows.push(o);
    }
    let d = rows.into_dict(py)?;
    names_dict(&d, spec)?;
    Ok(d)
}
