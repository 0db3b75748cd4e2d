//! `describe(...)`: what a scene or a model file offers a caller: its parameters (values,
//! units, ranges, docs; which belong to the start), its state components, inputs and start,
//! and its friction and impact laws. The names to give `set`, `init`, a sweep's `param` and a
//! grid's columns.

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::table::names_dict;
use crate::walker_args::{self, overrides};

/// Describe the walker of `scene` or `model` with the values of `set`.
///
/// # Errors
/// `ValueError` naming a bad argument.
#[pyfunction]
#[pyo3(signature = (*, scene, model, set, friction, impact))]
pub fn describe<'py>(
    py: Python<'py>,
    scene: Option<&str>,
    model: Option<&str>,
    set: Vec<(String, f64)>,
    friction: Option<&str>,
    impact: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    let ov = overrides(None, None, None, None, friction, impact)?;
    let setup = walker_args::setup_released(py, scene, model, &ov, &set)?;
    let model = walker_args::model(&setup)?;
    let spec = model.spec();
    let d = PyDict::new(py);
    d.set_item("model", spec.name())?;
    d.set_item("scene", &setup.name)?;
    d.set_item("title", spec.model.title.as_deref())?;
    d.set_item("friction", setup.friction.to_string())?;
    d.set_item("impact", setup.impact.to_string())?;
    let start: Vec<&str> = model.start_parameters().collect();
    let params: Vec<(String, f64, String, String, String, bool)> = spec
        .model
        .parameters
        .iter()
        .zip(setup.params.values())
        .map(|(p, &v)| {
            (
                p.name.name.clone(),
                v,
                p.unit.clone(),
                p.range.to_string(),
                p.doc.clone(),
                start.contains(&p.name.name.as_str()),
            )
        })
        .collect();
    d.set_item("parameters", params)?;
    names_dict(&d, spec)?;
    d.set_item("start", model.start_state().to_vec())?;
    Ok(d)
}
