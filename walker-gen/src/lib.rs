#![doc = include_str!("../README.md")]

#[cfg(feature = "emit")]
pub mod adapter;
pub mod bind;
#[cfg(feature = "emit")]
mod config;
#[cfg(feature = "emit")]
pub mod emit;
pub mod error;
pub mod ir;
pub mod lower;
pub mod model;
#[cfg(feature = "emit")]
mod model_scene;
mod options;
mod plan;
pub mod stats;
pub mod tape;

/// The shared vocabulary (structures, parameters, kernel names, scene files), re-exported from
/// `walker-scene` so that `walker_gen::scene::Scene` and `walker_gen::Param` keep working.
pub use walker_scene::{self as scene, catalog};

#[cfg(feature = "emit")]
pub use adapter::{Compile, CompileReport, VariantSpec};
pub use bind::ParamNodes;
pub use catalog::KernelName;
#[cfg(feature = "emit")]
pub use config::{Config, GenerateReport};
#[cfg(feature = "emit")]
pub use emit::emit;
pub use error::{EmitError, Error};
pub use ir::{Graph, Kernel, Module, Node, NodeId, ParamDecl, ParamId, Shape};
pub use model::{ModelScene, derive_model, lower_model};
pub use options::Division;
pub use options::{EmitOptions, Float, FloatFunctions};
pub use scene::{Floor, Friction, Param, Scene, SceneError, Torso};
pub use stats::{OpCounts, Stats, stats};
