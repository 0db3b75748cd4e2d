//! `fixed_point(...)`: the limit cycle (fixed point of the Poincare map) and its Floquet
//! multipliers, as `walker fixed-point`; a failed search is a result.

use pyo3::prelude::*;
use walker::poincare::{FixedPointOptions, fixed_point as search};

use crate::options;
use crate::walker_args::{self, overrides};

/// Search the limit cycle from the start (the warm-up walk's) and return the command line's
/// JSON report as a string (`{"status", "state_plus", "T", "V", "section", ..}`, or
/// `{"status": "failed", "reason"}`), with the names of the model's state components.
///
/// # Errors
/// `ValueError` naming a bad argument and its valid range.
#[pyfunction]
#[pyo3(signature = (*, scene, model, set, init, mu0, t_set, omega0, phi, c, friction, impact,
    method, rtol, atol))]
#[allow(clippy::too_many_arguments)]
pub fn fixed_point(
    py: Python<'_>,
    scene: Option<&str>,
    model: Option<&str>,
    set: Vec<(String, f64)>,
    init: Vec<(String, f64)>,
    mu0: Option<f64>,
    t_set: Option<f64>,
    omega0: Option<f64>,
    phi: Option<f64>,
    c: Option<f64>,
    friction: Option<&str>,
    impact: Option<&str>,
    method: &str,
    rtol: Option<f64>,
    atol: Option<f64>,
) -> PyResult<(String, Vec<String>)> {
    let ov = overrides(mu0, c, t_set, phi, friction, impact)?;
    let mut setup = walker_args::setup_released(py, scene, model, &ov, &set)?;
    walker_args::set_omega0(&mut setup, omega0, |w| w > 0.0, "finite and > 0")?;
    let cfg = options::config(method, rtol, atol)?;
    let model = walker_args::model(&setup)?;
    let opts = FixedPointOptions {
        start: walker_args::start(&model, &init)?,
        ..FixedPointOptions::for_model(&model)
    };
    let names = model.spec().state_names();
    // The report is made inside, so that the (large) error never leaves the thread. The search
    // cannot be asked to stop: on Ctrl-C it is left to end on its own (it is bounded by its
    // iterations and its warm-up walk).
    let json = crate::chunks::abandonable(py, move || {
        let failed = |reason: String| serde_json::json!({ "status": "failed", "reason": reason });
        match search(&model, &cfg, &opts) {
            Ok(fp) => {
                serde_json::to_string(&fp).unwrap_or_else(|e| failed(e.to_string()).to_string())
            }
            Err(e) => failed(e.to_string()).to_string(),
        }
    })?;
    Ok((json, names))
}
