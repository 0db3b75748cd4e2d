//! A scene file for a model (the format is `walker_scene::model_scene`): the model file plus
//! the friction law, the parameters fixed at generation and the kernels to generate. `--scene`
//! and [`crate::Config::scene_file`] take either kind of scene.

use std::path::Path;

use walker_scene::{ModelSceneError, ModelSceneFile};

use crate::error::Error;
use crate::model::ModelScene;

pub(crate) use walker_scene::is_model_scene;

/// Loads a model scene file and its model, as a scene for the generator (its run-time values,
/// `[set]`, and its impact law are the simulator's).
///
/// # Errors
/// [`Error::ModelScene`] naming the file and the field (an unknown field, a friction law that
/// is not one of the three, a `kernels` list that is empty), [`Error::Io`], or the model file's
/// own errors.
pub(crate) fn load_model_scene(path: &Path) -> Result<ModelScene, Error> {
    let file = ModelSceneFile::from_file(path).map_err(|e| match e {
        ModelSceneError::Read { path, source } => Error::Io { path, source },
        ModelSceneError::Invalid { path, message } => Error::ModelScene { path, message },
        ModelSceneError::Model(e) => Error::from(e),
    })?;
    let mut scene = ModelScene::new(file.model);
    if let Some(law) = file.friction {
        scene.friction = law;
    }
    scene.fixed = file.fix;
    scene.kernels = file.kernels;
    scene.name = file.name;
    Ok(scene)
}
