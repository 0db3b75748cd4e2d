//! Walker models: a model file's [`Spec`], its kernels behind one interface ([`Kernels`]), a
//! [`Walker`] (the file and where its kernels come from) and a [`Model`] (its kernels prepared
//! for one set of [`Parameters`]), with the contact and impact laws the simulator applies.
//!
//! Every physical quantity comes from a kernel or from the model file; nothing here knows a
//! particular walker. The paper's two walkers are the model files `models/paper-active.toml`
//! and `models/paper-passive.toml`.
//!
//! Files, imports one way: `spec.rs` (what the simulator reads from a model file),
//! `parameters.rs` (values by name, checked against their ranges), `contact.rs` (the
//! contact vocabulary), `friction_impact.rs` (the plastic impact with Coulomb friction at the
//! striking foot), `impact.rs` (the impact's results), `prepared.rs` ([`Model`]), `walker.rs`
//! ([`Walker`], [`KernelSource`], compiled variants).

mod contact;
mod friction_impact;
mod impact;
mod parameters;
mod prepared;
mod spec;
mod walker;

pub use contact::{Contact, FrictionLaw, Reaction, Slide};
pub use friction_impact::{
    ImpactJam, ImpactRegime, Ingredients, in_regime, plastic_coulomb, rear_test,
};
pub use impact::{ImpactResult, PostImpact};
pub use parameters::{ParamError, Parameters};
pub use prepared::{Model, StanceRhs};
pub use spec::{InitError, Spec, SpecError};
pub use walker::{KernelSource, NoKernels, Walker};
/// The kernel contract ([`walker_contract`]), re-exported where the simulator's code names it.
pub use walker_contract::{
    Args, Compiled, Desired, KernelId, Kernels, Prepare, Ramp, Tracking, Variant, aux_input, power,
};
pub use walker_scene::{Friction, ImpactLaw};
