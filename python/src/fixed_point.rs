//! `fixed_point(...)`: the limit cycle (fixed point of the Poincare map) and its Floquet
//! multipliers, as `walker fixed-point`; a failed search is a result.

use pyo3::prelude::*;
use walker::poincare::{FixedPointOptions, fixed_point as search};

use crate::error::ArgError;
use crate::options;
use crate::walker_args::{self, overrides};

/// Search the limit cycle from the start (the warm-up walk's) and return the command line's
/// JSON report as a string (`{"status", "state_plus", "T", "V", "section", ..}`, or
/// `{"status": "failed", "reason"}`), with the names of the model's state components. With
/// `sensitivities` (run-time parameter names) the report has `sensitivities` as
/// `walker fixed-point --sensitivities` (or `sensitivities_error`).
///
/// # Errors
/// `ValueError` naming a bad argument and its valid range.
#[pyfunction]
#[pyo3(signature = (*, scene, model, set, init, mu0, t_set, omega0, phi, c, friction, impact,
    method, rtol, atol, sensitivities))]
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
    sensitivities: Vec<String>,
) -> PyResult<(String, Vec<String>)> {
    let ov = overrides(mu0, c, t_set, phi, friction, impact)?;
    let mut setup = walker_args::setup_released(py, scene, model, &ov, &set)?;
    walker_args::set_omega0(&mut setup, omega0, |w| w > 0.0, "finite and > 0")?;
    let cfg = options::config(method, rtol, atol)?;
    let model = walker_args::model(&setup)?;
    let opts = FixedPointOptions {
        start: walker_args::start(&model, &init)?,
        refine: true,
        full_multipliers: true,
        ..FixedPointOptions::for_model(&model)
    };
    let wanted: Vec<&str> = sensitivities.iter().map(String::as_str).collect();
    walker::sensitivity::check_parameters(&setup, &cfg, &wanted).map_err(|e| match e {
        walker::sensitivity::SensitivityError::NotAParameter { name, model, known } => {
            ArgError::new(
                "sensitivities",
                format!(
                    "{} is not a run-time parameter of model `{model}`; valid: {known}",
                    walker::request::shown::name(&name)
                ),
            )
        }
        other => ArgError::new("sensitivities", other.to_string()),
    })?;
    let names = model.spec().state_names();
    // The report is made inside, so that the (large) error never leaves the thread. The search
    // cannot be asked to stop: on Ctrl-C it is left to end on its own (it is bounded by its
    // iterations and its warm-up walk).
    let json = crate::chunks::abandonable(py, move || {
        let failed = |reason: String| serde_json::json!({ "status": "failed", "reason": reason });
        match search(&model, &cfg, &opts) {
            Ok(fp) => {
                let mut j = serde_json::to_value(&fp).unwrap_or_else(|e| failed(e.to_string()));
                // Each multiplier's error bound, as `walker fixed-point --json` reports it.
                if let Some(obj) = j.as_object_mut() {
                    match walker::poincare::multiplier_errors(&model, &cfg, &fp) {
                        Ok(bounds) => {
                            let errors: Vec<Option<f64>> = bounds.iter().map(|b| b.error).collect();
                            obj.insert("multiplier_errors".into(), serde_json::json!(errors));
                        }
                        Err(e) => {
                            obj.insert("multiplier_errors_error".into(), e.to_string().into());
                        }
                    }
                }
                if !sensitivities.is_empty()
                    && let Some(obj) = j.as_object_mut()
                {
                    let wanted: Vec<&str> = sensitivities.iter().map(String::as_str).collect();
                    match walker::sensitivity::sensitivities(&setup, &cfg, &fp, &wanted) {
                        Ok(list) => {
                            let map: serde_json::Map<String, serde_json::Value> = list
                                .iter()
                                .map(|s| {
                                    let v =
                                        serde_json::to_value(s).unwrap_or(serde_json::Value::Null);
                                    (s.parameter.clone(), v)
                                })
                                .collect();
                            obj.insert("sensitivities".into(), map.into());
                        }
                        Err(e) => {
                            obj.insert("sensitivities_error".into(), e.to_string().into());
                        }
                    }
                }
                j.to_string()
            }
            Err(e) => failed(e.to_string()).to_string(),
        }
    })?;
    Ok((json, names))
}
