//! `walk_points(...)`: independent walks at the points of a parameter grid (columns `mu0`, `c`,
//! `t_set`, `phi`, `omega0`), each exactly as `simulate(...)` with those arguments, reduced to
//! its outcome (steps, status, last step). Every point is checked before any is walked. The
//! points are walked one after another on the calling thread (a Dask worker's task is one
//! core's work; parallelism comes from the workers), in chunks between checks for Ctrl-C.

use std::collections::HashMap;

use pyo3::prelude::*;
use pyo3::types::PyDict;
use walker::model::Model;
use walker::setup::Overrides;
use walker::sim::walk;

use crate::chunks::in_chunks;
use crate::error::{ArgError, check};
use crate::options;
use crate::table::{Outcome, Rows};

/// The grid columns a point may set.
pub const COLUMNS: [&str; 5] = ["mu0", "c", "t_set", "phi", "omega0"];

/// Points walked between two checks for Ctrl-C.
const CHUNK: usize = 16;

/// Walk every point of `grid` and return one row per point ([`Rows`]' columns).
///
/// # Errors
/// `ValueError` naming a bad column or argument (with the row) and its valid range.
#[pyfunction]
#[pyo3(signature = (*, scene, grid, friction, impact, method, rtol, atol, duration, max_steps,
    until_periodic))]
#[allow(clippy::too_many_arguments)]
pub fn walk_points<'py>(
    py: Python<'py>,
    scene: &str,
    grid: HashMap<String, Vec<f64>>,
    friction: Option<&str>,
    impact: Option<&str>,
    method: &str,
    rtol: Option<f64>,
    atol: Option<f64>,
    duration: Option<f64>,
    max_steps: i64,
    until_periodic: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let friction = options::friction(friction)?;
    let impact = options::impact(impact)?;
    let cfg = options::config(method, rtol, atol)?;
    let limits = options::limits(duration, max_steps, until_periodic)?;
    let mut n = None;
    for (name, col) in &grid {
        if !COLUMNS.contains(&name.as_str()) {
            return Err(ArgError::new(
                "grid",
                format!(
                    "unknown column {name:?}: must be one of {}",
                    COLUMNS.join(", ")
                ),
            )
            .into());
        }
        if *n.get_or_insert(col.len()) != col.len() {
            return Err(ArgError::new("grid", "the columns must have the same length").into());
        }
    }
    let n = n.unwrap_or(0);
    let at = |name: &str, k: usize| grid.get(name).map(|col| col[k]);
    let mut points: Vec<(Model, [f64; 8])> = Vec::with_capacity(n);
    for k in 0..n {
        let ov = Overrides {
            mu0: at("mu0", k),
            c: at("c", k),
            t_set: at("t_set", k),
            phi: at("phi", k),
            friction,
            impact,
        };
        let row = |e: ArgError| ArgError::new(&e.arg, format!("{} (grid row {k})", e.message));
        let model = options::setup(scene, &ov).map_err(row)?.model();
        let w0 = match at("omega0", k) {
            Some(w) => check("omega0", w, true, "finite").map_err(row)?,
            None => model.default_omega0(),
        };
        let initial = model.initial_state(w0);
        points.push((model, initial));
    }
    let mut outcomes: Vec<Outcome> = Vec::with_capacity(n);
    in_chunks(py, &mut outcomes, n, CHUNK, |out, range| {
        for (model, initial) in &points[range] {
            out.push(Outcome::of(walk(model, &cfg, *initial, &limits)));
        }
    })?;
    let mut rows = Rows::default();
    for o in &outcomes {
        rows.push(o);
    }
    rows.into_dict(py)
}
