//! A scene file for a model: a model file plus the choices that make it a scene (the friction
//! law, the parameters fixed at generation, the kernels to generate), so that a model's scene is
//! a file as the paper's scenes are:
//!
//! ```toml
//! name = "compass-gait-coulomb"        # optional: the generated module's name
//! model = "../models/compass-gait.toml" # required: relative to this file
//! friction = "coulomb"                  # optional: "none", "tanh" or "coulomb"
//! kernels = ["accel", "stick", "impact"]  # optional: default every kernel of the model
//!
//! [fix]                                 # optional: parameters substituted at generation
//! phi = 0.05235987755982988
//! ```
//!
//! A file is a model scene when it has a top-level `model` key; `--scene` and
//! [`crate::Config::scene_file`] take either kind.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde::Deserialize;
use walker_scene::Friction;
use walker_scene::model::Model;

use crate::error::Error;
use crate::model::ModelScene;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawModelScene {
    name: Option<String>,
    model: String,
    friction: Option<String>,
    #[serde(default)]
    fix: BTreeMap<String, f64>,
    kernels: Option<Vec<String>>,
}

fn invalid(path: &Path, message: impl Into<String>) -> Error {
    Error::ModelScene {
        path: path.to_path_buf(),
        message: message.into(),
    }
}

fn read(path: &Path) -> Result<String, Error> {
    std::fs::read_to_string(path).map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })
}

/// Whether the scene file at `path` is a model scene (it has a top-level `model` key). A file
/// that cannot be read or parsed is not one (the scene loader reports it).
pub(crate) fn is_model_scene(path: &Path) -> bool {
    read(path)
        .ok()
        .and_then(|text| text.parse::<toml::Table>().ok())
        .is_some_and(|table| table.contains_key("model"))
}

/// Loads a model scene file and its model.
///
/// # Errors
/// [`Error::ModelScene`] naming the file and the field (an unknown field, a friction law that
/// is not one of the three, a `kernels` list that is empty), [`Error::Io`], or the model file's
/// own errors.
pub(crate) fn load_model_scene(path: &Path) -> Result<ModelScene, Error> {
    let text = read(path)?;
    let raw: RawModelScene = toml::from_str(&text).map_err(|e| invalid(path, e.to_string()))?;
    let base = path.parent().map_or_else(PathBuf::new, Path::to_path_buf);
    let model = Model::from_file(&base.join(&raw.model))?;
    let mut scene = ModelScene::new(model);
    if let Some(law) = &raw.friction {
        scene.friction = match law.as_str() {
            "none" => Friction::None,
            "tanh" => Friction::Tanh,
            "coulomb" => Friction::Coulomb,
            other => {
                return Err(invalid(
                    path,
                    format!("friction = \"{other}\": expected \"none\", \"tanh\" or \"coulomb\""),
                ));
            }
        };
    }
    scene.fixed = raw.fix;
    if let Some(kernels) = raw.kernels {
        if kernels.is_empty() {
            return Err(invalid(
                path,
                "kernels = []: list at least one kernel, or leave the field out for every kernel",
            ));
        }
        scene.kernels = Some(kernels);
    }
    scene.name = raw.name;
    Ok(scene)
}
