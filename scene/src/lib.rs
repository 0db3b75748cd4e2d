//! `walker-scene`: the vocabulary that the slippery walker's build time and run time share.
//!
//! What a walker *is* — its structure (floor, friction law, torso, impact law), its parameters (name, unit,
//! doc, valid range, the paper's value), the kernels of `docs/kernels.md` and the structures
//! they belong to, and the scene files that fix some parameters for code generation — is
//! written here once. The generator (`walker-gen`, at build time) reads it to specialise and
//! name what it emits; the simulator (`walker`, at run time), its command line and the tests
//! read the same tables to build models and validate input. The crate is small on purpose (as
//! cranelift keeps what its meta generator and code generator share in
//! `cranelift-codegen-shared`): depending on it pulls in no computer algebra and no code
//! generation.
//!
//! Imports run one way: [`structure`] <- [`param`] <- [`catalog`] <- [`scene`] (with
//! [`error`] beside it).

pub mod catalog;
pub mod error;
pub mod floor;
pub mod limits;
pub mod model;
pub mod model_scene;
pub mod param;
pub mod read;
pub mod scene;
pub mod structure;

pub use catalog::KernelName;
pub use error::SceneError;
pub use floor::{
    Distribution, FloorFile, FloorFileError, FloorPatch, FloorPlan, FloorSpec, StepsError,
};
pub use model_scene::{ModelSceneError, ModelSceneFile, is_model_scene};
pub use param::Param;
pub use read::{ReadError, read_input};
pub use scene::Scene;
pub use structure::{Floor, Friction, ImpactLaw, Torso};
