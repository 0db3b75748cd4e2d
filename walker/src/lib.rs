//! `walker`: hybrid simulation and analysis of the underactuated rimless wheel with torso on
//! slippery ground, and of the passive wheel on a slope (Asano, Kikuchi, Shibata), built on
//! kernels generated from the symbolic derivation.
//!
//! This is the library: it computes and returns typed results. It parses no arguments, formats
//! no text and draws nothing; the `walker` command line (package `walker-cli`) does that. The
//! code generator runs only at build time (`build.rs`), so depending on `walker` links no
//! computer algebra.
//!
//! Imports run one way, from the analyses down to the integrators:
//! [`continuation`] -> [`poincare`]; [`sweep`], [`poincare`] -> [`sim`] -> [`model`] ([`setup`], [`params`], [`jacobian`],
//! [`control`], [`kernels`]) -> [`ode`].

pub mod continuation;
pub mod control;
pub mod jacobian;
pub mod kernels;
pub mod model;
pub mod ode;
pub mod params;
pub mod poincare;
pub mod setup;
pub mod sim;
pub mod sweep;
