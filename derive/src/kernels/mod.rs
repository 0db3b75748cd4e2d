//! The derived quantities as named kernels: inputs and output expressions, in the order fixed
//! by `docs/kernels.md`, for the code generator and the tests.
//!
//! `kernel` holds the kernel as data ([`Kernel`], [`Shape`], [`Staged`]); `derivation` builds
//! the named kernels ([`Derivation`]) and uses `kernel`, not the other way round.

mod derivation;
mod kernel;

pub use derivation::Derivation;
pub use kernel::{Kernel, Shape, Staged, find_kernel};
