//! `walker`: hybrid simulation and analysis of limit-cycle walkers on slippery ground, any
//! planar walker of a model file (`docs/model-format.md`), built on kernels generated from the
//! symbolic derivation: the underactuated rimless wheel with torso and the passive wheel on a
//! slope of Asano, Kikuchi and Shibata are the model files `models/paper-active.toml` and
//! `models/paper-passive.toml`.
//!
//! This is the library: it computes and returns typed results. It parses no arguments, formats
//! no text and draws nothing; the `walker` command line (package `walker-cli`) does that. The
//! code generator runs only at build time (`build.rs`), so depending on `walker` links no
//! computer algebra; a model file that is not compiled in is derived at run time by the
//! `walker-load` crate, which implements [`model::KernelSource`].
//!
//! What a request may ask (ranges, limits, each parameter once) is checked by [`request`],
//! for every front end.
//!
//! Imports run one way, from the analyses down to the integrators:
//! [`design`] -> [`poincare`], [`sim`]; [`continuation`] -> [`poincare`]; [`sweep`], [`poincare`], [`floor`] -> [`sim`] -> [`setup`] ->
//! [`model`] ([`jacobian`], [`compiled`]) -> [`ode`], [`vector`].

pub mod compiled;
pub mod continuation;
pub mod design;
pub mod floor;
pub mod jacobian;
pub mod model;
pub mod ode;
pub mod poincare;
pub mod request;
pub mod sensitivity;
pub mod setup;
pub mod sim;
pub mod sweep;
pub mod vector;

pub use vector::Vector;
/// The kernel contract a compiled model implements (the `walker-contract` crate).
pub use walker_contract as contract;
