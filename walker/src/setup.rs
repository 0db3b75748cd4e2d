//! From a scene or a model file to a [`Setup`] (a walker, its friction and impact laws and its
//! parameters), and from a setup to a [`Model`] to simulate.
//!
//! A scene is a model plus the choices that make it a scene (`walker_scene::model_scene`): the
//! friction law, the parameters it fixes, run-time values, the impact law. The built-in scenes
//! `active-level` and `passive-slope` are the files `models/scenes/active-level.toml` and
//! `models/scenes/passive-slope.toml`, compiled in; a scene may also be a file, in the model-scene
//! format or in the paper's scene format (`walker/scenes/*.toml`: floor, friction, torso), which
//! names the paper's walkers. Every parameter is checked against the range its model file gives.
//!
//! A model's kernels come from the variants compiled into this library ([`crate::compiled`])
//! or registered ([`register`]) when the model file has the canonical content of one of
//! them; otherwise from a
//! [`RuntimeSource`] the caller gives (the `walker-load` crate derives the file at run time).

use std::path::{Path, PathBuf};
use std::sync::{Arc, OnceLock, PoisonError, RwLock};

use walker_scene::model::Model as ModelFile;
use walker_scene::model::ModelError;
use walker_scene::{
    Floor, Friction, ImpactLaw, ModelSceneError, ModelSceneFile, Scene, SceneError, Torso,
    is_model_scene,
};

use crate::compiled::MODELS;
use crate::model::{
    Compiled, KernelSource, Model, NoKernels, ParamError, Parameters, Spec, SpecError, Walker,
};
use crate::request::{self, Field, Role};

/// The built-in scenes: their names and their files (`models/scenes/`).
const BUILT_IN: [(&str, &str); 2] = [
    (
        "active-level",
        include_str!("../../models/scenes/active-level.toml"),
    ),
    (
        "passive-slope",
        include_str!("../../models/scenes/passive-slope.toml"),
    ),
];

/// The longest scene or model file read (bytes): a scene is a few hundred bytes, the largest
/// shipped model a dozen kilobytes.
pub const MAX_FILE_BYTES: u64 = walker_scene::limits::MAX_FILE_BYTES;

/// Derives a model file that is not compiled in and gives its kernels (the `walker-load`
/// crate's), or says why it cannot.
pub type RuntimeSource = dyn Fn(&ModelFile) -> Result<Arc<dyn KernelSource>, String> + Sync;

/// Why a scene, a model file or a parameter set cannot be simulated.
#[derive(Debug, thiserror::Error)]
pub enum SetupError {
    /// A scene or model file cannot be read, is not a regular file (a device or a pipe could
    /// be read without end), or is longer than [`MAX_FILE_BYTES`].
    #[error("{what} file {}: {message}", request::shown::name(&path.display().to_string()))]
    File {
        /// `"scene"` or `"model"`.
        what: &'static str,
        /// The file.
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
    /// A start parameter (`omega0`) that the model does not have.
    #[error("model `{model}` has no start parameter {name}")]
    NoStartParameter {
        /// The model.
        model: String,
        /// The parameter asked for.
        name: String,
    },
    /// The scene is neither a built-in name nor a `.toml` file.
    #[error("unknown scene {}; use active-level, passive-slope or a FILE.toml", request::shown::text(.0))]
    UnknownScene(String),
    /// A scene file in the paper's format could not be read or is invalid.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// A model scene could not be read or is invalid.
    #[error(transparent)]
    ModelScene(#[from] ModelSceneError),
    /// A model file is invalid.
    #[error(transparent)]
    Model(#[from] ModelError),
    /// A model file cannot be simulated.
    #[error(transparent)]
    Spec(#[from] SpecError),
    /// The paper's scene format names a structure the paper has no walker for.
    #[error(
        "floor = {floor} with torso = {torso} is not simulated (level/actuated or slope/passive)"
    )]
    Unsupported {
        /// The scene's floor.
        floor: Floor,
        /// The scene's torso.
        torso: Torso,
    },
    /// A parameter is unknown or out of its range.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// A flag that names a role the model does not have (`--phi` on a level floor).
    #[error("{flag}: model `{model}` has no {role}")]
    NoRole {
        /// The flag or field.
        flag: &'static str,
        /// The model.
        model: String,
        /// The role, in words.
        role: &'static str,
    },
    /// The model's kernels cannot be prepared.
    #[error(transparent)]
    NoKernels(#[from] NoKernels),
    /// The request gives one parameter twice (by its role and by its name, or one name
    /// twice).
    #[error(transparent)]
    Request(#[from] crate::request::RequestError),
    /// The model file is not compiled in and no run-time source was given or it failed.
    #[error("model `{model}`: {message}")]
    NotCompiled {
        /// The model.
        model: String,
        /// Why.
        message: String,
    },
}

impl SetupError {
    /// The parameter or field the error is about, if it is about one.
    #[must_use]
    pub fn param(&self) -> Option<&str> {
        match self {
            SetupError::Param(e) => Some(e.name()),
            SetupError::NoRole { flag, .. } => Some(flag),
            SetupError::File { what, .. } => Some(what),
            SetupError::NoStartParameter { name, .. } => Some(name),
            _ => None,
        }
    }
}

/// Changes to a scene from flags or a caller: parameters by name, and the laws.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Overrides {
    /// The friction coefficient (the model's `[stance] mu0` parameter).
    pub mu0: Option<f64>,
    /// The tanh law's sharpness (the model's `[stance] c` parameter).
    pub c: Option<f64>,
    /// The paper's ramp duration, the parameter `T_set`.
    pub t_set: Option<f64>,
    /// The slope angle (the model's `[floor] slope` parameter).
    pub phi: Option<f64>,
    /// Any parameter by name (`--set name=value`), applied after the named ones.
    pub set: Vec<(String, f64)>,
    /// The friction law.
    pub friction: Option<Friction>,
    /// The impact law.
    pub impact: Option<ImpactLaw>,
}

/// A resolved scene: a walker, the laws of its contacts, and its parameters.
#[derive(Clone, Debug)]
pub struct Setup {
    /// The walker (its model file and where its kernels come from).
    pub walker: Walker,
    /// The scene's name (a built-in name, a scene's `name`, or the model's name).
    pub name: String,
    /// The friction law of the stance foot.
    pub friction: Friction,
    /// The impact law at the strike.
    pub impact: ImpactLaw,
    /// The parameters: the model's defaults, the scene's values, then the overrides.
    pub params: Parameters,
    /// The parameters the scene fixes at generation: while they keep these values the
    /// compiled variant with them substituted runs (the fast path); another value runs a
    /// variant that takes them at run time.
    pub fixed: Vec<(String, f64)>,
}

/// The compiled models a program adds to this library's own ([`crate::compiled::MODELS`]).
static REGISTERED: RwLock<Vec<&'static Compiled>> = RwLock::new(Vec::new());

/// Adds compiled models to those [`walker_of`] (and so every scene, model file and front end)
/// looks a model file up in: a user's crate that compiles its own model files from its build
/// script (`walker_gen::Compile`) registers its `MODELS` once, and every model file with the
/// same canonical content then runs its compiled kernels, with no change to this library. A
/// model registered twice is kept once; the registered models are looked up before the
/// shipped ones.
pub fn register(models: &'static [Compiled]) {
    let mut registered = REGISTERED.write().unwrap_or_else(PoisonError::into_inner);
    for c in models {
        if !registered.iter().any(|r| std::ptr::eq(*r, c)) {
            registered.push(c);
        }
    }
}

/// The compiled model whose canonical content is `canonical`: a registered one, else a
/// shipped one.
fn compiled_by_canonical(canonical: &str) -> Option<&'static Compiled> {
    let registered = REGISTERED.read().unwrap_or_else(PoisonError::into_inner);
    registered
        .iter()
        .copied()
        .chain(MODELS)
        .find(|c| c.canonical == canonical)
}

impl Walker {
    /// The walker of a compiled model (a user crate's `MODELS` entry, or one of
    /// [`crate::compiled::MODELS`]): its model file as it was compiled, its kernels from its
    /// variants.
    ///
    /// # Errors
    /// The model's text does not parse or cannot be simulated (a model compiled by another
    /// version of the generator).
    pub fn from_compiled(compiled: &'static Compiled) -> Result<Walker, SetupError> {
        let path = format!("{}.toml", compiled.name);
        let model = ModelFile::from_toml(compiled.source, &path)?;
        let source: Arc<dyn KernelSource> = Arc::new(*compiled);
        Ok(Walker::new(Spec::new(model)?, source))
    }
}

/// The walker of a model file: the compiled variants of a registered ([`register`]) or shipped
/// model with the same canonical content ([`ModelFile::canonical`]: layout, comments, names
/// and docs aside), else the run-time source.
///
/// # Errors
/// The model cannot be simulated, or is not compiled in and the run-time source fails.
pub fn walker_of(model: ModelFile, runtime: Option<&RuntimeSource>) -> Result<Walker, SetupError> {
    if let Some(c) = compiled_by_canonical(&model.canonical()) {
        let source: Arc<dyn KernelSource> = Arc::new(*c);
        return Ok(Walker::new(Spec::new(model)?, source));
    }
    let name = model.name.clone();
    let Some(runtime) = runtime else {
        return Err(SetupError::NotCompiled {
            model: name,
            message: "it is not one of the models compiled into this program, and no \
                      run-time source was given (the `walker` command line derives model files \
                      at run time)"
                .to_owned(),
        });
    };
    // The simulator's checks first: a model it refuses costs no derivation.
    let spec = Spec::new(model)?;
    let source = runtime(&spec.model).map_err(|message| SetupError::NotCompiled {
        model: name,
        message,
    })?;
    Ok(Walker::new(spec, source))
}

/// The shipped compiled model whose file is `models/<file name>` (for the built-in scenes,
/// which name their model by a relative path).
fn compiled_by_file(path: &str) -> Option<&'static Compiled> {
    let stem = Path::new(path).file_stem()?.to_str()?;
    MODELS.iter().find(|c| c.name == stem)
}

/// Checks that the `what` file (`"scene"` or `"model"`) at `path` is a regular file of at most
/// [`MAX_FILE_BYTES`].
fn check_file(what: &'static str, path: &Path) -> Result<(), SetupError> {
    let error = |message: String| SetupError::File {
        what,
        path: path.to_path_buf(),
        message,
    };
    let meta = std::fs::metadata(path).map_err(|e| error(format!("cannot be read: {e}")))?;
    if !meta.is_file() {
        return Err(error("is not a regular file".to_owned()));
    }
    if meta.len() > MAX_FILE_BYTES {
        return Err(error(format!(
            "has {} bytes; at most {MAX_FILE_BYTES}",
            meta.len()
        )));
    }
    Ok(())
}

/// A model file's text: a regular file of at most [`MAX_FILE_BYTES`], its kind checked before
/// it is opened (`walker_scene::read_input`).
fn read_model(path: &Path) -> Result<String, SetupError> {
    walker_scene::read_input(path, MAX_FILE_BYTES).map_err(|e| SetupError::File {
        what: "model",
        path: path.to_path_buf(),
        message: e.reason(),
    })
}

impl Setup {
    /// The built-in scene `active-level`: the paper's active walker (Table 1, `mu0 = 0.4`,
    /// `T_set = 0.3`).
    ///
    /// # Errors
    /// Never for the shipped files (a test loads every built-in scene).
    pub fn active_level() -> Result<Setup, SetupError> {
        Setup::built_in("active-level")
    }

    /// The built-in scene `passive-slope`: the paper's passive wheel (Table 1, `phi = 0.2`,
    /// `mu0 = 0.2`).
    ///
    /// # Errors
    /// Never for the shipped files (a test loads every built-in scene).
    pub fn passive_slope() -> Result<Setup, SetupError> {
        Setup::built_in("passive-slope")
    }

    /// The built-in scene called `name`. The scene and its model file are parsed and checked
    /// once per process and the result shared (a sweep builds a setup per grid point; parsing
    /// both files each time took `walker reproduce`'s peak memory from 24 MiB to 44 MiB).
    ///
    /// # Errors
    /// An unknown name.
    pub fn built_in(name: &str) -> Result<Setup, SetupError> {
        static PARSED: [OnceLock<Setup>; BUILT_IN.len()] =
            [const { OnceLock::new() }; BUILT_IN.len()];
        let i = BUILT_IN
            .iter()
            .position(|(n, _)| *n == name)
            .ok_or_else(|| SetupError::UnknownScene(name.to_owned()))?;
        if let Some(setup) = PARSED[i].get() {
            return Ok(setup.clone());
        }
        let setup = Setup::parse_built_in(i)?;
        Ok(PARSED[i].get_or_init(|| setup).clone())
    }

    /// Parses and checks the built-in scene `BUILT_IN[i]` and its model file.
    fn parse_built_in(i: usize) -> Result<Setup, SetupError> {
        let (name, text) = BUILT_IN[i];
        let path = Path::new("models/scenes").join(format!("{name}.toml"));
        let file = ModelSceneFile::from_toml(text, &path, |model| {
            let c = compiled_by_file(model).ok_or_else(|| ModelSceneError::Invalid {
                path: path.clone(),
                message: format!("model = \"{model}\" is not a compiled model"),
            })?;
            Ok((format!("models/{}.toml", c.name), c.source.to_owned()))
        })?;
        Setup::from_model_scene(file, None)
    }

    /// Resolves `scene` (a built-in name or the path of a scene file of either format) with
    /// the overrides, every parameter checked against its range. A model scene whose model is
    /// not compiled in takes its kernels from `runtime`.
    ///
    /// # Errors
    /// An unknown scene, an invalid scene or model file, an unknown parameter, a value out of
    /// its range or fixed by the scene, or kernels that cannot be had.
    pub fn resolve(
        scene: &str,
        ov: &Overrides,
        runtime: Option<&RuntimeSource>,
    ) -> Result<Setup, SetupError> {
        let mut setup = if BUILT_IN.iter().any(|(n, _)| *n == scene) {
            Setup::built_in(scene)?
        } else if scene.ends_with(".toml") {
            let path = Path::new(scene);
            check_file("scene", path)?;
            if is_model_scene(path) {
                Setup::from_model_scene(ModelSceneFile::from_file(path)?, runtime)?
            } else {
                Setup::from_paper_scene(&Scene::from_file(path)?)?
            }
        } else {
            return Err(SetupError::UnknownScene(scene.to_owned()));
        };
        setup.apply(ov)?;
        Ok(setup)
    }

    /// The model file at `path` as a scene of its own (its defaults, its first friction law
    /// other than `none`, its impact law), with the overrides.
    ///
    /// # Errors
    /// As [`Setup::resolve`].
    pub fn from_model_file(
        path: &Path,
        ov: &Overrides,
        runtime: Option<&RuntimeSource>,
    ) -> Result<Setup, SetupError> {
        let text = read_model(path)?;
        let model = ModelFile::from_toml(&text, &path.display().to_string())?;
        let mut setup = Setup::of(walker_of(model, runtime)?);
        setup.apply(ov)?;
        Ok(setup)
    }

    /// The walker's model as a scene of its own: its defaults, its first friction law other
    /// than `none`, its impact law, named after the model (for a walker a program made itself,
    /// such as [`Walker::from_compiled`]).
    #[must_use]
    pub fn of(walker: Walker) -> Setup {
        let model = &walker.spec().model;
        let (friction, impact) = (model.stance.default_friction(), model.impact.law);
        Setup {
            params: walker.defaults(),
            name: walker.spec().name().to_owned(),
            walker,
            friction,
            impact,
            fixed: Vec::new(),
        }
    }

    /// The setup of a model scene (not yet overridden).
    fn from_model_scene(
        file: ModelSceneFile,
        runtime: Option<&RuntimeSource>,
    ) -> Result<Setup, SetupError> {
        let friction = file
            .friction
            .unwrap_or_else(|| file.model.stance.default_friction());
        let impact = file.impact.unwrap_or(file.model.impact.law);
        let name = file.name.clone().unwrap_or_else(|| file.model.name.clone());
        let walker = walker_of(file.model, runtime)?;
        let mut params = walker.defaults();
        for (n, v) in file.fix.iter().chain(&file.set) {
            params.set(n, *v)?;
        }
        Ok(Setup {
            walker,
            name,
            friction,
            impact,
            params,
            fixed: file.fix.into_iter().collect(),
        })
    }

    /// The setup of a scene in the paper's format: the paper's active walker (level floor,
    /// actuated torso) or passive wheel (slope, passive), its fixed values as run-time values
    /// (`phi = 0.2` on a slope unless given, as the paper's Section 5).
    fn from_paper_scene(scene: &Scene) -> Result<Setup, SetupError> {
        let name = match (scene.floor, scene.torso) {
            (Floor::Level, Torso::Actuated) => "active-level",
            (Floor::Slope, Torso::Passive) => "passive-slope",
            (floor, torso) => return Err(SetupError::Unsupported { floor, torso }),
        };
        let built = Setup::built_in(name)?;
        let mut params = built.walker.defaults();
        if scene.floor == Floor::Slope {
            params.set("phi", 0.2)?;
        }
        for (param, v) in &scene.fixed {
            params.set(param.name(), *v)?;
        }
        Ok(Setup {
            walker: built.walker,
            name: scene.name.clone(),
            friction: scene.friction,
            impact: scene.impact,
            params,
            fixed: Vec::new(),
        })
    }

    /// Applies the overrides: the laws, then the parameters by role, then by name.
    ///
    /// # Errors
    /// A role the model does not have, an unknown parameter, a value out of range or fixed.
    pub fn apply(&mut self, ov: &Overrides) -> Result<(), SetupError> {
        if let Some(f) = ov.friction {
            self.friction = f;
        }
        if let Some(law) = ov.impact {
            self.impact = law;
        }
        let spec = Arc::clone(self.walker.spec());
        let role = |index: Option<usize>, flag: &'static str, role: &'static str| {
            index
                .map(|i| spec.model.parameters[i].name.name.clone())
                .ok_or_else(|| SetupError::NoRole {
                    flag,
                    model: spec.name().to_owned(),
                    role,
                })
        };
        let mut named = Vec::new();
        let mut fields = Vec::new();
        if let Some(v) = ov.mu0 {
            named.push((role(spec.mu0, "mu0", "friction coefficient")?, v));
            fields.push(Field::Role(Role::Mu0));
        }
        if let Some(v) = ov.c {
            named.push((role(spec.c, "c", "tanh friction law")?, v));
            fields.push(Field::Role(Role::C));
        }
        if let Some(v) = ov.t_set {
            named.push((
                role(spec.parameter("T_set"), "t-set", "parameter T_set")?,
                v,
            ));
            fields.push(Field::Role(Role::TSet));
        }
        if let Some(v) = ov.phi {
            named.push((role(spec.slope, "phi", "slope (its floor is level)")?, v));
            fields.push(Field::Role(Role::Slope));
        }
        fields.extend(ov.set.iter().map(|(n, _)| Field::Parameter(n.clone())));
        // Each parameter once: a second value (by its role and by its name, or one name
        // twice) would silently replace the first.
        request::distinct_fields(&spec, &fields)?;
        named.extend(ov.set.iter().cloned());
        for (name, v) in named {
            self.set(&name, v)?;
        }
        Ok(())
    }

    /// Sets the parameter called `name` to `value`.
    ///
    /// # Errors
    /// An unknown parameter, or a value out of its range.
    pub fn set(&mut self, name: &str, value: f64) -> Result<(), SetupError> {
        self.params.set(name, value)?;
        Ok(())
    }

    /// Sets the start parameter `name` (the paper's `omega0`: a parameter of stage `start`,
    /// which only the model's `[start]` reads).
    ///
    /// # Errors
    /// The model has no start parameter `name`, or `value` is out of its range.
    pub fn set_start(&mut self, name: &str, value: f64) -> Result<(), SetupError> {
        let spec = self.walker.spec();
        let is_start = spec
            .parameter(name)
            .is_some_and(|i| spec.model.parameters[i].stage == walker_scene::model::Stage::Start);
        if !is_start {
            return Err(SetupError::NoStartParameter {
                model: spec.name().to_owned(),
                name: name.to_owned(),
            });
        }
        self.set(name, value)
    }

    /// The parameter whose values a sweep chains without a request: `T_set` where the model
    /// has one (the paper's active walker, Fig. 8), else its slope (the passive wheel, Fig. 10),
    /// with its value here; `None` for a level walker without `T_set`.
    #[must_use]
    pub fn default_chain(&self) -> Option<(String, f64)> {
        let spec = self.walker.spec();
        let name = spec
            .parameter("T_set")
            .or(spec.slope)
            .map(|i| spec.model.parameters[i].name.name.clone())?;
        let value = self.params.get(&name)?;
        Some((name, value))
    }

    /// The model to simulate, with the setup's parameters.
    ///
    /// # Errors
    /// The model does not list the friction law, or its kernels cannot be prepared.
    pub fn model(&self) -> Result<Model, NoKernels> {
        self.model_with(&self.params)
    }

    /// The model with the parameters `params` (of the same walker).
    ///
    /// # Errors
    /// As [`Setup::model`].
    pub fn model_with(&self, params: &Parameters) -> Result<Model, NoKernels> {
        self.walker.model(params, self.friction, self.impact)
    }

    /// The setup's parameters with `name` set to `value` (checked).
    ///
    /// # Errors
    /// As [`Setup::set`].
    pub fn with(&self, name: &str, value: f64) -> Result<Setup, SetupError> {
        let mut s = self.clone();
        s.set(name, value)?;
        Ok(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_built_in_scenes_load_with_their_values() {
        let a = Setup::active_level().expect("active-level");
        assert_eq!(a.params.get("mu0"), Some(0.4));
        assert_eq!(a.params.get("T_set"), Some(0.3));
        assert_eq!(a.friction, Friction::Tanh);
        let p = Setup::passive_slope().expect("passive-slope");
        assert_eq!(
            (p.params.get("phi"), p.params.get("mu0")),
            (Some(0.2), Some(0.2))
        );
        assert!(matches!(
            p.with("m1", -3.0),
            Err(SetupError::Param(ParamError::OutOfRange { ref name, .. })) if name == "m1"
        ));
    }

    #[test]
    fn a_file_that_is_not_a_regular_file_is_named_as_scene_or_model() {
        let dir = std::env::temp_dir();
        let e = Setup::from_model_file(&dir, &Overrides::default(), None).expect_err("a dir");
        assert!(matches!(e, SetupError::File { what: "model", .. }), "{e}");
        assert!(e.to_string().contains("is not a regular file"), "{e}");
        assert_eq!(e.param(), Some("model"));
        let missing = dir.join("no-such-scene-here.toml");
        let e = Setup::resolve(&missing.display().to_string(), &Overrides::default(), None)
            .expect_err("missing");
        assert!(matches!(e, SetupError::File { what: "scene", .. }), "{e}");
        assert!(e.to_string().contains("cannot be read"), "{e}");
    }

    #[test]
    fn only_a_start_parameter_is_set_as_one() {
        let mut a = Setup::active_level().expect("active-level");
        a.set_start("omega0", 0.9)
            .expect("paper-active's start parameter");
        assert_eq!(a.params.get("omega0"), Some(0.9));
        // mu0 is a parameter, but of the dynamics.
        let e = a.set_start("mu0", 0.5).expect_err("not a start parameter");
        assert!(matches!(e, SetupError::NoStartParameter { ref name, .. } if name == "mu0"));
        assert!(matches!(
            a.set_start("omega0", f64::INFINITY),
            Err(SetupError::Param(ParamError::OutOfRange { .. }))
        ));
    }

    #[test]
    fn a_sweep_chains_t_set_else_the_slope() {
        let a = Setup::active_level().expect("active-level");
        assert_eq!(a.default_chain(), Some(("T_set".to_owned(), 0.3)));
        let p = Setup::passive_slope().expect("passive-slope");
        assert_eq!(p.default_chain(), Some(("phi".to_owned(), 0.2)));
    }

    #[test]
    fn a_level_walker_has_no_slope_to_set() {
        let ov = Overrides {
            phi: Some(0.1),
            ..Overrides::default()
        };
        let e = Setup::resolve("active-level", &ov, None).expect_err("no slope");
        assert_eq!(e.param(), Some("phi"));
    }
}
