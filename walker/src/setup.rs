//! From a scene to a model: the built-in scenes (`active-level`, `passive-slope`), scene
//! files, parameter overrides, and their validation against the parameter table of
//! `walker-scene` (each parameter's valid range is written there once).

use walker_scene::{Floor, Friction, ImpactLaw, Param, Scene, SceneError, Torso};

use crate::model::{FrictionLaw, Kind, Model};
use crate::params::{Physical, Runtime};

/// Why a scene or a parameter set cannot be simulated.
#[derive(Debug, thiserror::Error)]
pub enum SetupError {
    /// The scene is neither a built-in name nor a `.toml` file.
    #[error("unknown scene {0:?}; use active-level, passive-slope or a FILE.toml")]
    UnknownScene(String),
    /// The scene file could not be read or is invalid.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// The scene's structure has no simulator (only level/actuated and slope/passive do).
    #[error(
        "floor = {floor} with torso = {torso} is not simulated (level/actuated or slope/passive)"
    )]
    Unsupported {
        /// The scene's floor.
        floor: Floor,
        /// The scene's torso.
        torso: Torso,
    },
    /// A parameter outside its valid range (from the parameter table).
    #[error("{value} is outside the valid range of {param}: {}", param.valid_range())]
    OutOfRange {
        /// The parameter.
        param: Param,
        /// The rejected value.
        value: f64,
    },
    /// A slope angle for the active walker, which walks on level ground.
    #[error("the active walker walks on level ground: phi must be 0")]
    SlopeForLevelWalker,
}

impl SetupError {
    /// The parameter the error is about, if it is about one.
    #[must_use]
    pub fn param(&self) -> Option<Param> {
        match self {
            SetupError::OutOfRange { param, .. } => Some(*param),
            SetupError::SlopeForLevelWalker => Some(Param::Phi),
            _ => None,
        }
    }
}

/// Optional overrides of the runtime parameters (from flags or a caller).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Overrides {
    /// `mu0`.
    pub mu0: Option<f64>,
    /// `c`.
    pub c: Option<f64>,
    /// `T_set`.
    pub t_set: Option<f64>,
    /// `phi`.
    pub phi: Option<f64>,
    /// The friction law.
    pub friction: Option<FrictionLaw>,
    /// The impact law.
    pub impact: Option<ImpactLaw>,
}

/// A resolved scene: how to build the model for given runtime parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct Setup {
    /// Level/active or slope/passive.
    pub kind: Kind,
    /// Whether the fast kernels with Table 1 compiled in are used (tanh friction only).
    pub fast: bool,
    /// The friction law.
    pub friction: FrictionLaw,
    /// The impact law at heel strike.
    pub impact: ImpactLaw,
    /// Physical parameters.
    pub physical: Physical,
    /// Runtime parameters (defaults, scene values, then overrides).
    pub runtime: Runtime,
}

impl Setup {
    /// The paper's active walker on level ground (Table 1, `mu0 = 0.4`, `T_set = 0.3`).
    #[must_use]
    pub fn active_level() -> Setup {
        Setup {
            kind: Kind::ActiveLevel,
            fast: true,
            friction: FrictionLaw::Tanh,
            impact: ImpactLaw::Frictionless,
            physical: Physical::TABLE1,
            runtime: Runtime::default(),
        }
    }

    /// The paper's passive wheel on a slope (Table 1, `phi = 0.2`, `mu0 = 0.2`).
    #[must_use]
    pub fn passive_slope() -> Setup {
        Setup {
            kind: Kind::PassiveSlope,
            fast: true,
            friction: FrictionLaw::Tanh,
            impact: ImpactLaw::Frictionless,
            physical: Physical::TABLE1,
            runtime: Runtime {
                phi: 0.2,
                mu0: 0.2,
                ..Runtime::default()
            },
        }
    }

    /// Resolve `scene` (`active-level`, `passive-slope` or the path of a scene file) with the
    /// overrides, and validate every parameter against its range.
    ///
    /// # Errors
    /// An unknown scene, an invalid scene file, an unsupported structure, or a parameter out
    /// of its range.
    pub fn resolve(scene: &str, ov: &Overrides) -> Result<Setup, SetupError> {
        let mut setup = match scene {
            "active-level" => Setup::active_level(),
            "passive-slope" => Setup::passive_slope(),
            path if path.ends_with(".toml") => Setup::from_scene(&Scene::from_file(path)?)?,
            other => return Err(SetupError::UnknownScene(other.to_owned())),
        };
        if let Some(f) = ov.friction {
            setup.friction = f;
        }
        if let Some(law) = ov.impact {
            setup.impact = law;
        }
        let r = &mut setup.runtime;
        for (param, v) in [
            (Param::Mu0, ov.mu0),
            (Param::C, ov.c),
            (Param::TSet, ov.t_set),
        ] {
            if let Some(v) = v {
                r.set(param, v);
            }
        }
        if let Some(v) = ov.phi {
            if setup.kind == Kind::ActiveLevel && v != 0.0 {
                return Err(SetupError::SlopeForLevelWalker);
            }
            r.phi = v;
        }
        setup.validate()?;
        Ok(setup)
    }

    /// The setup of a scene (not validated: see [`Setup::validate`]): its structure, its fixed
    /// values, and the paper's values for the rest (`phi = 0.2` on a slope).
    ///
    /// # Errors
    /// The structure has no simulator.
    pub fn from_scene(scene: &Scene) -> Result<Setup, SetupError> {
        let kind = match (scene.floor, scene.torso) {
            (Floor::Level, Torso::Actuated) => Kind::ActiveLevel,
            (Floor::Slope, Torso::Passive) => Kind::PassiveSlope,
            (floor, torso) => return Err(SetupError::Unsupported { floor, torso }),
        };
        let mut physical = Physical::TABLE1;
        let mut runtime = Runtime {
            phi: if kind == Kind::PassiveSlope { 0.2 } else { 0.0 },
            ..Runtime::default()
        };
        for (&param, &v) in &scene.fixed {
            let _ = physical.set(param, v) || runtime.set(param, v);
        }
        let friction = match scene.friction {
            Friction::Tanh => FrictionLaw::Tanh,
            Friction::None => {
                runtime.mu0 = 0.0;
                FrictionLaw::Tanh
            }
            Friction::Coulomb => FrictionLaw::Coulomb,
        };
        Ok(Setup {
            kind,
            fast: false,
            friction,
            impact: scene.impact,
            physical,
            runtime,
        })
    }

    /// Check every parameter against its valid range ([`Param::accepts`]).
    ///
    /// # Errors
    /// The first parameter out of range, in the table's order.
    pub fn validate(&self) -> Result<(), SetupError> {
        validate(&self.physical, &self.runtime)
    }

    /// Build the model with the runtime parameters `runtime`.
    #[must_use]
    pub fn model_with(&self, runtime: Runtime) -> Model {
        let model = match (self.kind, self.friction, self.fast) {
            (Kind::ActiveLevel, FrictionLaw::Coulomb, _) => {
                Model::coulomb_level(self.physical, runtime)
            }
            (Kind::PassiveSlope, FrictionLaw::Coulomb, _) => {
                Model::coulomb_slope(self.physical, runtime)
            }
            (Kind::ActiveLevel, FrictionLaw::Tanh, true) => Model::active_level(runtime),
            (Kind::PassiveSlope, FrictionLaw::Tanh, true) => Model::passive_slope(runtime),
            (Kind::ActiveLevel, FrictionLaw::Tanh, false) => {
                Model::general_level(self.physical, runtime)
            }
            (Kind::PassiveSlope, FrictionLaw::Tanh, false) => {
                Model::general_slope(self.physical, runtime)
            }
        };
        model.with_impact_law(self.impact)
    }

    /// Build the model with the resolved runtime parameters.
    #[must_use]
    pub fn model(&self) -> Model {
        self.model_with(self.runtime)
    }
}

/// Check every parameter of `physical` and `runtime` against its valid range, in the order of
/// the parameter table.
///
/// # Errors
/// The first parameter out of range.
pub fn validate(physical: &Physical, runtime: &Runtime) -> Result<(), SetupError> {
    for param in Param::ALL {
        let value = crate::params::value(physical, runtime, param);
        if !param.accepts(value) {
            return Err(SetupError::OutOfRange { param, value });
        }
    }
    Ok(())
}
