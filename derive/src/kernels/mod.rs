//! The kernel as data: a named function of some symbols with its output expressions, in the
//! order fixed by `docs/kernels.md`, for the code generator and the tests ([`Kernel`],
//! [`Shape`], [`Staged`]). The model derivation ([`crate::model::ModelDerivation`]) and the
//! paper's catalogue ([`crate::paper::Derivation`]) build them.

mod kernel;

pub use kernel::{Kernel, Shape, Staged, find_kernel};
