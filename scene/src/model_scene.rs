//! A model scene: a model file plus the choices that make it a scene, so that a model's scene
//! is a file as the paper's scenes are. The generator reads the friction law, the parameters
//! fixed at generation and the kernels to generate; the simulator reads the same file, with the
//! run-time values the scene sets and its impact law.
//!
//! ```toml
//! name = "passive-slope"                # optional: the generated module's name
//! model = "../paper-passive.toml"       # required: relative to this file
//! friction = "tanh"                     # optional: "none", "tanh" or "coulomb"
//! impact = "frictionless"               # optional: the impact law (default: the model's)
//! kernels = ["accel", "stick", "impact"]  # optional: default every kernel of the model
//!
//! [fix]                                 # optional: parameters substituted at generation
//! m1 = 2.0
//!
//! [set]                                 # optional: run-time values of the scene (defaults
//! phi = 0.2                             # of parameters that are not fixed)
//! ```
//!
//! A file is a model scene when it has a top-level `model` key.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde::Deserialize;
use toml::Spanned;

use crate::model::source::SourceMap;
use crate::model::{Model, ModelError};
use crate::structure::{Friction, ImpactLaw};

/// Why a model scene cannot be loaded.
#[derive(Debug, thiserror::Error)]
pub enum ModelSceneError {
    /// The file cannot be read.
    #[error("cannot read scene file {path}: {source}")]
    Read {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
    /// A field is unknown, mistyped or invalid.
    #[error("scene {path}: {message}")]
    Invalid {
        /// The file.
        path: PathBuf,
        /// What is wrong, naming the field and what it takes.
        message: String,
    },
    /// The model file it names is invalid.
    #[error(transparent)]
    Model(#[from] ModelError),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawModelScene {
    name: Option<String>,
    model: String,
    friction: Option<String>,
    impact: Option<String>,
    #[serde(default)]
    fix: BTreeMap<String, Spanned<f64>>,
    #[serde(default)]
    set: BTreeMap<String, Spanned<f64>>,
    kernels: Option<Vec<String>>,
}

/// A model scene file, read: its model loaded and checked, and every value of `[fix]` and
/// `[set]` a parameter of the model within the range its model file gives (refused naming
/// the scene file, the line and column, the field and the range).
#[derive(Clone, Debug)]
pub struct ModelSceneFile {
    /// Where it was read from.
    pub path: PathBuf,
    /// The generated module's name (`None`: the model's).
    pub name: Option<String>,
    /// The model.
    pub model: Model,
    /// The model file's text, as read.
    pub model_text: String,
    /// The friction law (`None`: the model's first other than `none`).
    pub friction: Option<Friction>,
    /// The impact law (`None`: the model's).
    pub impact: Option<ImpactLaw>,
    /// The parameters fixed at generation.
    pub fix: BTreeMap<String, f64>,
    /// Run-time values of parameters that are not fixed.
    pub set: BTreeMap<String, f64>,
    /// The kernels to generate (`None`: every kernel).
    pub kernels: Option<Vec<String>>,
}

/// The text of a scene or model file: a regular file of at most
/// [`MAX_FILE_BYTES`](crate::limits::MAX_FILE_BYTES) (`read_input`).
fn read(path: &Path) -> Result<String, ModelSceneError> {
    crate::read::read_input(path, crate::limits::MAX_FILE_BYTES).map_err(|e| {
        ModelSceneError::Read {
            path: path.to_path_buf(),
            source: e.into(),
        }
    })
}

/// Whether the scene file at `path` is a model scene (it has a top-level `model` key). A file
/// that cannot be read or parsed is not one (the scene loader reports it).
#[must_use]
pub fn is_model_scene(path: &Path) -> bool {
    read(path)
        .ok()
        .and_then(|text| text.parse::<toml::Table>().ok())
        .is_some_and(|table| table.contains_key("model"))
}

impl ModelSceneFile {
    /// Loads a model scene file and its model.
    ///
    /// # Errors
    /// [`ModelSceneError::Invalid`] naming the field (an unknown field, a friction or impact law
    /// that is not one of the known ones, an empty `kernels` list, a parameter both fixed and
    /// set), [`ModelSceneError::Read`], or the model file's own errors.
    pub fn from_file(path: &Path) -> Result<ModelSceneFile, ModelSceneError> {
        let text = read(path)?;
        let base = path.parent().map_or_else(PathBuf::new, Path::to_path_buf);
        ModelSceneFile::from_toml(&text, path, |model| {
            let model_path = base.join(model);
            Ok((model_path.display().to_string(), read(&model_path)?))
        })
    }

    /// Reads a model scene from `text` (its origin `path`, for messages), its model's origin
    /// and text given by `model` from the scene's `model` field (a path relative to the scene).
    ///
    /// # Errors
    /// As [`ModelSceneFile::from_file`].
    pub fn from_toml(
        text: &str,
        path: &Path,
        model: impl Fn(&str) -> Result<(String, String), ModelSceneError>,
    ) -> Result<ModelSceneFile, ModelSceneError> {
        let invalid = |message: String| ModelSceneError::Invalid {
            path: path.to_path_buf(),
            message,
        };
        let raw: RawModelScene = toml::from_str(text).map_err(|e| invalid(e.to_string()))?;
        let (model_origin, model_text) = model(&raw.model)?;
        let model = Model::from_toml(&model_text, &model_origin)?;
        let friction = match raw.friction.as_deref() {
            None => None,
            Some("none") => Some(Friction::None),
            Some("tanh") => Some(Friction::Tanh),
            Some("coulomb") => Some(Friction::Coulomb),
            Some(other) => {
                return Err(invalid(format!(
                    "friction = \"{other}\": expected \"none\", \"tanh\" or \"coulomb\""
                )));
            }
        };
        let impact = match raw.impact.as_deref() {
            None => None,
            Some("frictionless") => Some(ImpactLaw::Frictionless),
            Some("coulomb") => Some(ImpactLaw::Coulomb),
            Some(other) => {
                return Err(invalid(format!(
                    "impact = \"{other}\": expected \"frictionless\" or \"coulomb\""
                )));
            }
        };
        if raw.kernels.as_ref().is_some_and(Vec::is_empty) {
            return Err(invalid(
                "kernels = []: list at least one kernel, or leave the field out for every kernel"
                    .to_owned(),
            ));
        }
        if let Some(name) = raw.set.keys().find(|k| raw.fix.contains_key(*k)) {
            return Err(invalid(format!(
                "set.{}: `{}` is fixed at generation ([fix]); a scene sets only the \
                 parameters it does not fix",
                echo(name),
                echo(name)
            )));
        }
        let source = SourceMap::new(text);
        for (table, values) in [("fix", &raw.fix), ("set", &raw.set)] {
            for (name, value) in values {
                check_value(&model, &model_origin, table, name, value).map_err(|why| {
                    let at = source.location(value.span().start);
                    invalid(format!("line {}, column {}: {why}", at.line, at.column))
                })?;
            }
        }
        let values = |m: BTreeMap<String, Spanned<f64>>| {
            m.into_iter()
                .map(|(k, v)| (k, v.into_inner()))
                .collect::<BTreeMap<_, _>>()
        };
        Ok(ModelSceneFile {
            path: path.to_path_buf(),
            name: raw.name,
            model,
            model_text,
            friction,
            impact,
            fix: values(raw.fix),
            set: values(raw.set),
            kernels: raw.kernels,
        })
    }
}

/// A name from a scene file as a message repeats it: control characters escaped, at most 80
/// characters (with `...`).
fn echo(name: &str) -> String {
    let mut out: String = name.chars().take(80).flat_map(char::escape_debug).collect();
    if name.chars().nth(80).is_some() {
        out.push_str("...");
    }
    out
}

/// Checks `table.name = value` of a scene against `model` (read from `origin`): `name` is one
/// of its parameters and `value` within the range its model file gives. The reason, if not.
fn check_value(
    model: &Model,
    origin: &str,
    table: &str,
    name: &str,
    value: &Spanned<f64>,
) -> Result<(), String> {
    let v = *value.get_ref();
    let Some(p) = model.parameters.iter().find(|p| p.name.name == name) else {
        let known: Vec<&str> = model
            .parameters
            .iter()
            .map(|p| p.name.name.as_str())
            .collect();
        return Err(format!(
            "{table}.{}: not a parameter of model `{}` ({origin}); its parameters: {}",
            echo(name),
            model.name,
            known.join(", ")
        ));
    };
    if p.range.contains(v) {
        Ok(())
    } else {
        Err(format!(
            "{table}.{name} = {v}: expected a value in {} (the range of `{name}` in {origin}, \
             line {})",
            p.range, p.name.location.line
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const MODEL: &str = "../compass-gait.toml";

    /// The scene `text` read beside the shipped models (`models/scenes/`).
    fn scene(text: &str) -> Result<ModelSceneFile, ModelSceneError> {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../models/scenes");
        ModelSceneFile::from_toml(text, &dir.join("bad.toml"), |m| {
            let p = dir.join(m);
            Ok((p.display().to_string(), read(&p)?))
        })
    }

    #[test]
    fn a_value_out_of_its_parameters_range_names_the_scene_file_line_field_and_range() {
        let text = format!("model = \"{MODEL}\"\n\n[set]\nphi = 5.0\n");
        let e = scene(&text)
            .expect_err("phi = 5 is out of range")
            .to_string();
        assert!(e.contains("bad.toml"), "{e}");
        assert!(e.contains("line 4, column 7"), "{e}");
        assert!(e.contains("set.phi = 5: expected a value in ["), "{e}");
    }

    #[test]
    fn a_non_finite_value_and_an_unknown_name_are_refused_with_their_line() {
        let text = format!("model = \"{MODEL}\"\n[fix]\ng = nan\n");
        let e = scene(&text).expect_err("NaN").to_string();
        assert!(e.contains("line 3, column 5: fix.g = NaN"), "{e}");
        let text = format!("model = \"{MODEL}\"\n[set]\n\"gr\\u001bavity\" = 9.8\n");
        let e = scene(&text).expect_err("unknown").to_string();
        assert!(
            e.contains("line 3") && e.contains("set.gr\\u{1b}avity: not a parameter"),
            "{e}"
        );
    }

    #[test]
    fn a_value_of_the_wrong_type_names_the_line() {
        let text = format!("model = \"{MODEL}\"\n[set]\nphi = \"steep\"\n");
        let e = scene(&text).expect_err("a string").to_string();
        assert!(e.contains("bad.toml") && e.contains("line 3"), "{e}");
    }
}
