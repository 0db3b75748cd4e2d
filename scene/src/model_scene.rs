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
    fix: BTreeMap<String, f64>,
    #[serde(default)]
    set: BTreeMap<String, f64>,
    kernels: Option<Vec<String>>,
}

/// A model scene file, read (its model loaded and checked; its parameter names not yet checked
/// against the model, which the generator and the simulator do, each naming the field).
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
                "set.{name}: `{name}` is fixed at generation ([fix]); a scene sets only the \
                 parameters it does not fix"
            )));
        }
        Ok(ModelSceneFile {
            path: path.to_path_buf(),
            name: raw.name,
            model,
            model_text,
            friction,
            impact,
            fix: raw.fix,
            set: raw.set,
            kernels: raw.kernels,
        })
    }
}
