//! The builder a `build.rs` uses (as `prost_build::Config`): one or many scenes, one
//! derivation for all of them.

use std::path::{Path, PathBuf};

use crate::emit::emit_plan;
use crate::error::Error;
use crate::ir::Module;
use crate::lower::{Derivation, derive, lower};
use crate::model::{ModelScene, derive_model, lower_model};
use crate::model_scene::{is_model_scene, load_model_scene};
use crate::options::{Division, EmitOptions, Float, FloatFunctions};
use crate::plan::Plan;
use crate::stats::{Stats, from_plan};
use walker_scene::model::Model;
use walker_scene::{Friction, Scene};

#[derive(Clone, Debug)]
enum SceneSource {
    File(PathBuf),
    Value(Box<Scene>),
}

/// Configures and runs the generator. See the crate docs for a `build.rs` example.
#[derive(Clone, Debug, Default)]
pub struct Config {
    scenes: Vec<SceneSource>,
    options: EmitOptions,
    out_file: Option<PathBuf>,
    out_dir: Option<PathBuf>,
    rerun_if_changed: bool,
    model: Option<ModelSource>,
}

/// A model file and the choices that make it a scene ([`ModelScene`]).
#[derive(Clone, Debug, Default)]
struct ModelSource {
    path: PathBuf,
    fixed: Vec<(String, f64)>,
    friction: Option<Friction>,
}

/// What [`Config::generate`] did (and [`Config::generate_all`] for each scene).
#[derive(Clone, Debug)]
pub struct GenerateReport {
    /// The output file.
    pub out_file: PathBuf,
    /// Whether the file was written (`false`: it already had these bytes).
    pub written: bool,
    /// The size of the generated source in bytes.
    pub bytes: usize,
    /// Operation counts of the generated code.
    pub stats: Stats,
}

impl Config {
    /// A configuration with no scene, `f64`, std, [`Division::SharedReciprocal`], checked entry
    /// points, [`FloatFunctions::Inline`], the output files `$OUT_DIR/<scene name>.rs` and no
    /// `cargo:` lines.
    #[must_use]
    pub fn new() -> Config {
        Config::default()
    }

    /// Adds a scene read from a TOML file (relative paths are relative to the working directory,
    /// which is the package root in a build script).
    pub fn scene_file(&mut self, path: impl AsRef<Path>) -> &mut Config {
        self.scenes
            .push(SceneSource::File(path.as_ref().to_path_buf()));
        self
    }

    /// Adds scenes read from TOML files, in order (as [`Config::scene_file`] for each); then
    /// [`Config::generate_all`] writes one file per scene from one derivation.
    pub fn scene_files<P: AsRef<Path>>(
        &mut self,
        paths: impl IntoIterator<Item = P>,
    ) -> &mut Config {
        for path in paths {
            self.scene_file(path);
        }
        self
    }

    /// Adds a scene built in code.
    pub fn scene(&mut self, scene: Scene) -> &mut Config {
        self.scenes.push(SceneSource::Value(Box::new(scene)));
        self
    }

    /// The float type `F` of the generated code.
    pub fn float(&mut self, float: Float) -> &mut Config {
        self.options.float = float;
        self
    }

    /// Whether the generated code must be `no_std` (float functions from `libm`).
    pub fn no_std(&mut self, no_std: bool) -> &mut Config {
        self.options.no_std = no_std;
        self
    }

    /// How divisions by shared denominators are evaluated.
    pub fn division(&mut self, division: Division) -> &mut Config {
        self.options.division = division;
        self
    }

    /// Whether to emit checked entry points (default `true`): next to each kernel `k`, a
    /// `k_checked` returning `Result<_, KernelError>` that names the first non-finite argument
    /// or output, and once per file the `KernelError` enum. `false` leaves them out (smaller
    /// code for embedded users); the unchecked kernels are the same either way.
    pub fn checked(&mut self, checked: bool) -> &mut Config {
        self.options.checked = checked;
        self
    }

    /// How `sin_cos` and `tanh` are evaluated in `f64` std code (default
    /// [`FloatFunctions::Inline`]: the file's own accurate and fast functions;
    /// [`FloatFunctions::Std`]: std's methods). No effect on `f32` or no-std code.
    pub fn float_functions(&mut self, float_functions: FloatFunctions) -> &mut Config {
        self.options.float_functions = float_functions;
        self
    }

    /// The file [`Config::generate`] writes for the one scene (default: in the output directory,
    /// named by [`Scene::default_file_name`]). Not allowed with several scenes.
    pub fn out_file(&mut self, path: impl AsRef<Path>) -> &mut Config {
        self.out_file = Some(path.as_ref().to_path_buf());
        self
    }

    /// The directory [`Config::generate_all`] writes each scene's file into, named by
    /// [`Scene::default_file_name`] (default: `$OUT_DIR`).
    pub fn out_dir(&mut self, path: impl AsRef<Path>) -> &mut Config {
        self.out_dir = Some(path.as_ref().to_path_buf());
        self
    }

    /// Whether generating prints `cargo:rerun-if-changed=<scene file>` for each scene file.
    pub fn emit_rerun_if_changed(&mut self, yes: bool) -> &mut Config {
        self.rerun_if_changed = yes;
        self
    }

    /// The emit options currently set.
    #[must_use]
    pub fn options(&self) -> EmitOptions {
        self.options
    }

    /// The one scene of a single-scene call.
    fn single(&self) -> Result<&SceneSource, Error> {
        match self.scenes.as_slice() {
            [] => Err(Error::NoScene),
            [one] => Ok(one),
            many => Err(Error::SeveralScenes { count: many.len() }),
        }
    }

    /// Loads (or clones) and validates the scene.
    ///
    /// # Errors
    /// No scene or more than one was given, or it is invalid.
    pub fn load_scene(&self) -> Result<Scene, Error> {
        load(self.single()?)
    }

    /// Generates the kernels of a model file (`docs/model-format.md`) instead of scenes: every
    /// kernel of the model, with the parameters given to [`Config::fix`] (and the model's
    /// generation-stage parameters) substituted, and the friction law of [`Config::friction`]
    /// (default: the model's first law other than `none`). The default output file is
    /// `<model name with _>.rs`.
    pub fn model_file(&mut self, path: impl AsRef<Path>) -> &mut Config {
        self.model.get_or_insert_with(ModelSource::default).path = path.as_ref().to_path_buf();
        self
    }

    /// Fixes a model parameter at generation time (see [`Config::model_file`]).
    pub fn fix(&mut self, name: &str, value: f64) -> &mut Config {
        self.model
            .get_or_insert_with(ModelSource::default)
            .fixed
            .push((name.to_owned(), value));
        self
    }

    /// The stance friction law of a model's kernels (see [`Config::model_file`]).
    pub fn friction(&mut self, law: Friction) -> &mut Config {
        self.model.get_or_insert_with(ModelSource::default).friction = Some(law);
        self
    }

    /// The model scene of [`Config::model_file`], loaded and checked.
    ///
    /// # Errors
    /// The model file is invalid, or a fixed parameter or the friction law is not the model's.
    pub fn load_model(&self) -> Result<Option<ModelScene>, Error> {
        let Some(source) = &self.model else {
            // A scene file that names a model (`model = "..."`) is a model scene.
            if let [SceneSource::File(path)] = self.scenes.as_slice()
                && is_model_scene(path)
            {
                let scene = load_model_scene(path)?;
                scene.validate()?;
                return Ok(Some(scene));
            }
            return Ok(None);
        };
        if !self.scenes.is_empty() {
            return Err(Error::SceneAndModel);
        }
        let model = Model::from_file(&source.path)?;
        let mut scene = ModelScene::new(model);
        scene.fixed.extend(source.fixed.iter().cloned());
        if let Some(f) = source.friction {
            scene.friction = f;
        }
        scene.validate()?;
        Ok(Some(scene))
    }

    /// The source and operation counts of a model scene.
    fn build_model(&self, scene: &ModelScene) -> Result<(String, Stats), Error> {
        let module = lower_model(&derive_model(&scene.model)?, scene)?;
        self.build_module(&module)
    }

    /// The source and operation counts of a lowered module.
    fn build_module(&self, module: &Module) -> Result<(String, Stats), Error> {
        let plan = Plan::new(module, self.options.division)?;
        let source = emit_plan(module, &plan, &self.options)?;
        Ok((source, from_plan(module, &plan)))
    }

    /// The lowered module, with the scene's (or model's) summary as the first header notes.
    ///
    /// # Errors
    /// No scene or more than one was given, or it is invalid or cannot be lowered; or the model
    /// file is invalid or cannot be derived.
    pub fn module(&self) -> Result<Module, Error> {
        if let Some(model) = self.load_model()? {
            return lower_model(&derive_model(&model.model)?, &model);
        }
        let scene = self.load_scene()?;
        module_of(&derive()?, &scene)
    }

    /// The source and operation counts of `scene`'s file, lowered from `derivation`.
    fn build(&self, derivation: &Derivation, scene: &Scene) -> Result<(String, Stats), Error> {
        self.build_module(&module_of(derivation, scene)?)
    }

    /// The source and operation counts of the one scene (one derivation).
    fn build_single(&self) -> Result<(String, Stats), Error> {
        if let Some(model) = self.load_model()? {
            return self.build_model(&model);
        }
        let scene = self.load_scene()?;
        self.build(&derive()?, &scene)
    }

    /// The generated source, without writing anything.
    ///
    /// # Errors
    /// No scene or more than one was given, or it is invalid or cannot be lowered or emitted.
    pub fn render(&self) -> Result<String, Error> {
        Ok(self.build_single()?.0)
    }

    /// The operation counts of the generated source.
    ///
    /// # Errors
    /// As [`Config::render`].
    pub fn stats(&self) -> Result<Stats, Error> {
        Ok(self.build_single()?.1)
    }

    /// Generates the source of the one scene and writes it to the output file if its bytes
    /// changed (so that cargo does not rebuild needlessly). Creates the parent directory if
    /// needed.
    ///
    /// # Errors
    /// As [`Config::render`], or no output file is known, or the file cannot be written.
    pub fn generate(&self) -> Result<GenerateReport, Error> {
        if self.model.is_none() {
            self.single()?;
        }
        self.generate_all()?.pop().ok_or(Error::NoScene)
    }

    /// Derives the kernels once and, for every scene in the order given, generates its source
    /// and writes it (if its bytes changed) to the output file (one scene only) or to
    /// `<out_dir or $OUT_DIR>/<`[`Scene::default_file_name`]`>`. Creates directories if needed.
    ///
    /// # Errors
    /// No scene was given, a scene is invalid or cannot be lowered or emitted, an output file
    /// is set for several scenes, no output directory is known, or a file cannot be written.
    /// Files of the scenes before the failing one are written.
    pub fn generate_all(&self) -> Result<Vec<GenerateReport>, Error> {
        if let Some(model) = self.load_model()? {
            if self.rerun_if_changed {
                println!("cargo:rerun-if-changed={}", model.model.path);
                for source in &self.scenes {
                    if let SceneSource::File(path) = source {
                        println!("cargo:rerun-if-changed={}", path.display());
                    }
                }
            }
            let (source, stats) = self.build_model(&model)?;
            let out_file = self.out_file_in(&format!(
                "{}.rs",
                model
                    .name
                    .as_deref()
                    .unwrap_or(&model.model.name)
                    .replace('-', "_")
            ))?;
            return Ok(vec![write_if_changed(out_file, &source, stats)?]);
        }
        if self.scenes.is_empty() {
            return Err(Error::NoScene);
        }
        if self.out_file.is_some() && self.scenes.len() > 1 {
            return Err(Error::SeveralScenes {
                count: self.scenes.len(),
            });
        }
        if self.rerun_if_changed {
            for source in &self.scenes {
                if let SceneSource::File(path) = source {
                    println!("cargo:rerun-if-changed={}", path.display());
                }
            }
        }
        let derivation = derive()?;
        let mut reports = Vec::with_capacity(self.scenes.len());
        for source in &self.scenes {
            let scene = load(source)?;
            let (source, stats) = self.build(&derivation, &scene)?;
            let out_file = self.out_file_of(&scene)?;
            reports.push(write_if_changed(out_file, &source, stats)?);
        }
        Ok(reports)
    }

    /// Where `scene`'s file goes: the output file, else the output directory (or `$OUT_DIR`)
    /// joined with the scene's default file name.
    fn out_file_of(&self, scene: &Scene) -> Result<PathBuf, Error> {
        self.out_file_in(&scene.default_file_name())
    }

    /// The output file, else `file_name` in the output directory (or `$OUT_DIR`).
    fn out_file_in(&self, file_name: &str) -> Result<PathBuf, Error> {
        if let Some(path) = &self.out_file {
            return Ok(path.clone());
        }
        let dir = match &self.out_dir {
            Some(dir) => dir.clone(),
            None => PathBuf::from(std::env::var_os("OUT_DIR").ok_or(Error::NoOutFile)?),
        };
        Ok(dir.join(file_name))
    }
}

/// Loads (or clones) and validates one scene.
fn load(source: &SceneSource) -> Result<Scene, Error> {
    let scene = match source {
        SceneSource::File(path) if is_model_scene(path) => {
            return Err(Error::ModelScene {
                path: path.clone(),
                message: "a model scene (a scene naming a model file) is generated on its own: \
                          give it as the only scene"
                    .to_owned(),
            });
        }
        SceneSource::File(path) => Scene::from_file(path)?,
        SceneSource::Value(scene) => (**scene).clone(),
    };
    scene.validate()?;
    Ok(scene)
}

/// `scene` lowered from `derivation`, with the scene's summary as the first header notes.
fn module_of(derivation: &Derivation, scene: &Scene) -> Result<Module, Error> {
    let mut module = lower(derivation, scene)?;
    let mut notes = scene.summary();
    notes.append(&mut module.notes);
    module.notes = notes;
    Ok(module)
}

/// Whether `out_file` is a regular file that holds exactly `source`: read only when its
/// metadata says it is a regular file of `source`'s length, so that a device or a pipe as the
/// target (`/dev/full`, a FIFO) is never read, and a large file is not read whole.
pub(crate) fn holds(out_file: &Path, source: &str) -> bool {
    std::fs::metadata(out_file)
        .is_ok_and(|m| m.file_type().is_file() && m.len() == source.len() as u64)
        && std::fs::read(out_file).is_ok_and(|old| old == source.as_bytes())
}

/// Writes `source` to `out_file` unless it is a regular file that already holds these bytes
/// (the target is not read otherwise).
fn write_if_changed(
    out_file: PathBuf,
    source: &str,
    stats: Stats,
) -> Result<GenerateReport, Error> {
    let io = |source| Error::Io {
        path: out_file.clone(),
        source,
    };
    let unchanged = holds(&out_file, source);
    if !unchanged {
        if let Some(dir) = out_file.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).map_err(io)?;
        }
        std::fs::write(&out_file, source.as_bytes()).map_err(io)?;
    }
    Ok(GenerateReport {
        written: !unchanged,
        bytes: source.len(),
        stats,
        out_file,
    })
}
