//! The builder a `build.rs` uses (as `prost_build::Config`).

use std::path::{Path, PathBuf};

use crate::emit::emit_plan;
use crate::error::Error;
use crate::ir::Module;
use crate::lower::lower;
use crate::options::{Division, EmitOptions, Float, FloatFunctions};
use crate::plan::Plan;
use crate::scene::Scene;
use crate::stats::{Stats, from_plan};

#[derive(Clone, Debug)]
enum SceneSource {
    File(PathBuf),
    Value(Box<Scene>),
}

/// Configures and runs the generator. See the crate docs for a `build.rs` example.
#[derive(Clone, Debug, Default)]
pub struct Config {
    scene: Option<SceneSource>,
    options: EmitOptions,
    out_file: Option<PathBuf>,
    rerun_if_changed: bool,
}

/// What [`Config::generate`] did.
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
    /// points, [`FloatFunctions::Inline`], the output file `$OUT_DIR/<scene name>.rs` and no
    /// `cargo:` lines.
    #[must_use]
    pub fn new() -> Config {
        Config::default()
    }

    /// Reads the scene from a TOML file (relative paths are relative to the working directory,
    /// which is the package root in a build script).
    pub fn scene_file(&mut self, path: impl AsRef<Path>) -> &mut Config {
        self.scene = Some(SceneSource::File(path.as_ref().to_path_buf()));
        self
    }

    /// Uses a scene built in code.
    pub fn scene(&mut self, scene: Scene) -> &mut Config {
        self.scene = Some(SceneSource::Value(Box::new(scene)));
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

    /// The file [`Config::generate`] writes (default: `$OUT_DIR/<scene name with _>.rs`).
    pub fn out_file(&mut self, path: impl AsRef<Path>) -> &mut Config {
        self.out_file = Some(path.as_ref().to_path_buf());
        self
    }

    /// Whether [`Config::generate`] prints `cargo:rerun-if-changed=<scene file>`.
    pub fn emit_rerun_if_changed(&mut self, yes: bool) -> &mut Config {
        self.rerun_if_changed = yes;
        self
    }

    /// The emit options currently set.
    #[must_use]
    pub fn options(&self) -> EmitOptions {
        self.options
    }

    /// Loads (or clones) and validates the scene.
    ///
    /// # Errors
    /// No scene was given, or it is invalid.
    pub fn load_scene(&self) -> Result<Scene, Error> {
        let scene = match &self.scene {
            None => return Err(Error::NoScene),
            Some(SceneSource::File(path)) => Scene::from_file(path)?,
            Some(SceneSource::Value(scene)) => (**scene).clone(),
        };
        scene.validate()?;
        Ok(scene)
    }

    /// The lowered module, with the scene's summary as the first header notes.
    ///
    /// # Errors
    /// The scene is invalid or cannot be lowered.
    pub fn module(&self) -> Result<Module, Error> {
        let scene = self.load_scene()?;
        let mut module = lower(&scene)?;
        let mut notes = scene.summary();
        notes.append(&mut module.notes);
        module.notes = notes;
        Ok(module)
    }

    fn build(&self) -> Result<(String, Stats), Error> {
        let module = self.module()?;
        let plan = Plan::new(&module, self.options.division)?;
        let source = emit_plan(&module, &plan, &self.options)?;
        Ok((source, from_plan(&module, &plan)))
    }

    /// The generated source, without writing anything.
    ///
    /// # Errors
    /// The scene is invalid or cannot be lowered or emitted.
    pub fn render(&self) -> Result<String, Error> {
        Ok(self.build()?.0)
    }

    /// The operation counts of the generated source.
    ///
    /// # Errors
    /// As [`Config::render`].
    pub fn stats(&self) -> Result<Stats, Error> {
        Ok(self.build()?.1)
    }

    /// Generates the source and writes it to the output file if its bytes changed (so that
    /// cargo does not rebuild needlessly). Creates the parent directory if needed.
    ///
    /// # Errors
    /// As [`Config::render`], or the file cannot be written.
    pub fn generate(&self) -> Result<GenerateReport, Error> {
        if self.rerun_if_changed
            && let Some(SceneSource::File(path)) = &self.scene
        {
            println!("cargo:rerun-if-changed={}", path.display());
        }
        let (source, stats) = self.build()?;
        let out_file = match &self.out_file {
            Some(path) => path.clone(),
            None => {
                let dir = std::env::var_os("OUT_DIR").ok_or(Error::NoOutFile)?;
                let scene = self.load_scene()?;
                PathBuf::from(dir).join(scene.default_file_name())
            }
        };
        let io = |source| Error::Io {
            path: out_file.clone(),
            source,
        };
        let unchanged = std::fs::read(&out_file).is_ok_and(|old| old == source.as_bytes());
        if !unchanged {
            if let Some(dir) = out_file.parent().filter(|d| !d.as_os_str().is_empty()) {
                std::fs::create_dir_all(dir).map_err(io)?;
            }
            std::fs::write(&out_file, source.as_bytes()).map_err(io)?;
        }
        Ok(GenerateReport {
            out_file: out_file.clone(),
            written: !unchanged,
            bytes: source.len(),
            stats,
        })
    }
}
