//! The kernel contract between the code walker-gen generates and the walker simulator, the
//! small vocabulary both sides share (as cranelift's `codegen-shared` crate is for its meta
//! generator and its code generator):
//!
//! - the kernel identities ([`KernelId`]) and what a call is given ([`Args`], [`Tracking`],
//!   the desired trajectories of the output-following control, [`Desired`]);
//! - the argument binding ([`Binding`]): which number of a call each generated argument is;
//! - the interface the simulator calls ([`Kernels`]);
//! - the compiled-variant registry ([`Compiled`], [`Variant`]) a crate hands to the simulator.
//!
//! walker-gen emits against it (the adapter of each compiled variant implements [`Kernels`]),
//! walker, `walker-load`'s run-time tape and the tests consume it. A user's crate that compiles
//! its own model depends on this crate (the generated adapter names it as `::walker_contract`)
//! and on `walker`, and never rebuilds either.
//!
//! Files, imports one way: `kernel_id.rs`, `desired.rs`, `args.rs`, `binding.rs`, `kernels.rs`,
//! `registry.rs`.

mod args;
mod binding;
mod desired;
mod kernel_id;
mod kernels;
mod registry;

pub use args::{Args, Tracking};
pub use binding::{BindError, Binding, SIGMA};
pub use desired::{Bezier, Desired, Ramp, aux_input};
pub use kernel_id::KernelId;
pub use kernels::{Kernels, power};
pub use registry::{Compiled, Prepare, Variant};
pub use walker_scene::Friction;

/// The most coordinates a model has (`walker_scene::limits`): the provided methods of
/// [`Kernels`] hold a state in arrays of this size.
pub const MAX_COORDINATES: usize = walker_scene::limits::MAX_COORDINATES;
