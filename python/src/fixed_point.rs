//! `fixed_point(...)`: the limit cycle (fixed point of the Poincare map) and its Floquet
//! multipliers, as `walker fixed-point`; a failed search is a result.

use pyo3::prelude::*;
use walker::poincare::{FixedPointOptions, fixed_point as search};
use walker::setup::Overrides;

use crate::error::check;
use crate::options;

/// Search the limit cycle and return the command line's JSON report as a string (`{"status",
/// "state_plus", "T", "V", ..}`, or `{"status": "failed", "reason"}`).
///
/// # Errors
/// `ValueError` naming a bad argument and its valid range.
#[pyfunction]
#[pyo3(signature = (*, scene, mu0, t_set, omega0, phi, c, friction, impact, method, rtol, atol))]
#[allow(clippy::too_many_arguments)]
pub fn fixed_point(
    py: Python<'_>,
    scene: &str,
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
) -> PyResult<String> {
    let ov = Overrides {
        mu0,
        c,
        t_set,
        phi,
        friction: options::friction(friction)?,
        impact: options::impact(impact)?,
    };
    let setup = options::setup(scene, &ov)?;
    let cfg = options::config(method, rtol, atol)?;
    let model = setup.model();
    let mut opts = FixedPointOptions::for_model(&model);
    if let Some(w) = omega0 {
        opts.omega0 = check("omega0", w, w > 0.0, "finite and > 0")?;
    }
    let result = py.detach(|| search(&model, &cfg, &opts));
    let json = match result {
        Ok(fp) => serde_json::to_string(&fp).unwrap_or_else(|e| {
            serde_json::json!({ "status": "failed", "reason": e.to_string() }).to_string()
        }),
        Err(e) => serde_json::json!({ "status": "failed", "reason": e.to_string() }).to_string(),
    };
    Ok(json)
}
