#![doc = include_str!("../README.md")]

pub mod bind;
pub mod catalog;
mod config;
pub mod emit;
pub mod error;
pub mod ir;
pub mod lower;
mod plan;
pub mod scene;
pub mod stats;

pub use bind::ParamNodes;
pub use catalog::KernelName;
pub use config::{Config, GenerateReport};
pub use emit::{EmitOptions, Float, FloatFunctions, emit};
pub use error::{EmitError, Error};
pub use ir::{Graph, Kernel, Module, Node, NodeId, ParamDecl, ParamId, Shape};
pub use plan::Division;
pub use scene::{Floor, Friction, Param, Scene, SceneError, Torso};
pub use stats::{OpCounts, Stats, stats};
