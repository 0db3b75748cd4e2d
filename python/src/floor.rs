//! Floors for Python (`docs/floors.md`): `floor=` of `simulate` and `survive`, a floor file's
//! path or a dict of the file's structure. A dict is written as the TOML of a floor file and
//! read by the file's parser (`walker_scene::floor`), so that it gets exactly a file's checks;
//! an error names the key (`floor['mu0.hi']`). `survive(...)`, the walks on a floor, is
//! `survive.rs`.

use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use walker::floor::{FloorFile, FloorFileError, FloorPlan, FloorWalker};
use walker::request::{Field, RequestError, Role};
use walker::setup::Setup;

use crate::error::ArgError;

/// The deepest nesting of lists and tables a floor dict may have (a floor file has two).
const MAX_DEPTH: usize = 4;

/// The key `path` of a floor dict as an error names it: `floor['mu0']['hi']`.
fn key(path: &[String]) -> String {
    let mut s = String::from("floor");
    for p in path {
        if p.parse::<usize>().is_ok() {
            s.push_str(&format!("[{p}]"));
        } else {
            s.push_str(&format!("['{}']", crate::error::echo(p)));
        }
    }
    s
}

/// A type error about the value at `path` of a floor dict.
fn type_error(path: &[String], v: &Bound<'_, PyAny>, must_be: &str) -> PyErr {
    let ty = v
        .get_type()
        .name()
        .map_or_else(|_| "?".to_owned(), |n| n.to_string());
    PyTypeError::new_err(format!("invalid {}: a {ty}: must be {must_be}", key(path)))
}

/// The TOML value of `v`, the value at `path` of a floor dict: a bool, an int, a float, a
/// string, a list or tuple, or a dict with string keys.
fn toml_value(v: &Bound<'_, PyAny>, path: &mut Vec<String>) -> PyResult<toml::Value> {
    if path.len() > MAX_DEPTH {
        return Err(type_error(
            path,
            v,
            "a value of a floor file (nested too deep)",
        ));
    }
    if v.is_instance_of::<PyBool>() {
        return Ok(toml::Value::Boolean(v.extract()?));
    }
    if v.is_instance_of::<PyInt>() {
        return match v.extract::<i64>() {
            Ok(i) => Ok(toml::Value::Integer(i)),
            Err(_) => {
                Err(ArgError::new(&key(path), "an integer too large: must fit in 64 bits").into())
            }
        };
    }
    if v.is_instance_of::<PyFloat>() {
        return Ok(toml::Value::Float(v.extract()?));
    }
    if v.is_instance_of::<PyString>() {
        return Ok(toml::Value::String(v.extract()?));
    }
    if v.is_instance_of::<PyList>() || v.is_instance_of::<PyTuple>() {
        let mut out = Vec::new();
        for (i, x) in v.try_iter()?.enumerate() {
            path.push(i.to_string());
            out.push(toml_value(&x?, path)?);
            path.pop();
        }
        return Ok(toml::Value::Array(out));
    }
    if let Ok(d) = v.cast::<PyDict>() {
        let mut table = toml::Table::new();
        for (k, x) in d.iter() {
            let Ok(name) = k.extract::<String>() else {
                return Err(type_error(path, &k, "a dict with string keys"));
            };
            path.push(name.clone());
            let value = toml_value(&x, path)?;
            path.pop();
            table.insert(name, value);
        }
        return Ok(toml::Value::Table(table));
    }
    Err(type_error(
        path,
        v,
        "a number, a string, a list or a dict (a value of a floor file)",
    ))
}

/// The floor of `floor=`: a path (`str`) of a floor file, or a dict of its structure.
///
/// # Errors
/// `TypeError` for another type or a value of a type no floor file has; `ValueError` naming
/// the file (a path) or the key (a dict) for a value the file's parser refuses.
pub fn floor_spec(floor: &Bound<'_, PyAny>) -> PyResult<FloorPlan> {
    if let Ok(path) = floor.extract::<String>() {
        return FloorFile::from_file(std::path::Path::new(&path))
            .map(|f| f.spec)
            .map_err(|e| ArgError::new("floor", e.to_string()).into());
    }
    if floor.cast::<PyDict>().is_err() {
        return Err(type_error(&[], floor, "a floor file's path or a dict"));
    }
    let toml::Value::Table(table) = toml_value(floor, &mut Vec::new())? else {
        return Err(type_error(&[], floor, "a floor file's path or a dict"));
    };
    let text = toml::to_string(&table)
        .map_err(|e| ArgError::new("floor", format!("cannot be written as TOML: {e}")))?;
    FloorFile::from_toml(&text, "floor")
        .map(|f| f.spec)
        .map_err(|e| match e {
            FloorFileError::Invalid { field, message, .. } => {
                let parts: Vec<String> = field
                    .split(['.', '[', ']'])
                    .filter(|p| !p.is_empty())
                    .map(str::to_owned)
                    .collect();
                ArgError::new(&key(&parts), message).into()
            }
            e @ FloorFileError::Read { .. } => ArgError::new("floor", e.to_string()).into(),
        })
}

/// Checks that neither `mu0=` nor `set` gives the friction coefficient that `floor=` sets per
/// step, and neither `phi=` nor `set` the slope it sets. `mu0=` with any floor is refused (as
/// `--mu0` with `--floor`); `set` may give what the floor does not set.
///
/// # Errors
/// Either gives it (named `mu0`, `phi` or `set['name']`).
pub fn mu0_once(
    setup: &Setup,
    floor: &FloorPlan,
    mu0: Option<f64>,
    phi: Option<f64>,
    set: &[(String, f64)],
) -> Result<(), ArgError> {
    walker::request::floor_once(true, false, mu0.is_some()).map_err(ArgError::from)?;
    let spec = setup.walker.spec();
    let parts = [
        (floor.mu0.is_some(), spec.mu0, "each sets mu0; give one"),
        (floor.phi.is_some(), spec.slope, "each sets phi; give one"),
    ];
    for (sets, index, why) in parts {
        let Some(i) = index.filter(|_| sets) else {
            continue;
        };
        let name = &spec.model.parameters[i].name.name;
        if set.iter().any(|(n, _)| n == name) {
            return Err(ArgError::from(RequestError::Conflict {
                field: Field::Parameter(name.clone()),
                other: Field::Floor,
                why,
            }));
        }
    }
    if floor.phi.is_some() && phi.is_some() {
        return Err(ArgError::from(RequestError::Conflict {
            field: Field::Role(Role::Slope),
            other: Field::Floor,
            why: "each sets phi; give one",
        }));
    }
    Ok(())
}

/// The walker of `setup` on `floor`.
///
/// # Errors
/// The floor cannot set the walker's friction or slope (named `floor`).
pub fn walker_on(setup: &Setup, floor: FloorPlan) -> Result<FloorWalker<'_>, ArgError> {
    FloorWalker::new(setup, floor).map_err(|e| ArgError::new("floor", e.to_string()))
}
