//! Rust source from a [`Module`](crate::Module): tokens with `quote`, checked by `syn`, formatted by
//! `prettyplease`, stamped with the `@generated` line.
//!
//! Layout of a generated file (see the crate docs for an example):
//!
//! 1. the `@generated` line and a header comment (scene structure, fixed values, options);
//! 2. `pub type F = f64;` (or `f32`);
//! 3. `pub struct Params` (the runtime parameters), `pub struct Prepared` (what `prepare`
//!    computes from them) and `pub fn prepare(p: &Params) -> Prepared`;
//! 4. one `pub fn` per kernel taking `p: &Prepared` and its arguments (the unchecked fast
//!    path), followed, when [`EmitOptions::checked`] is set, by `pub fn <kernel>_checked`
//!    returning `Result<_, KernelError>`, and once per file the `KernelError` enum.
//!
//! The output depends only on the module and the options: no paths, no time, no hash-map
//! order. Floating-point functions are inherent methods (`x.sin()`, `x.sqrt()`) in std
//! mode and `libm` calls (`libm::sin`, `libm::sincos`; `libm::sinf`... for `f32`) in no-std
//! mode; `abs` is `core`'s inherent method in both modes (an exact bit operation). In std mode
//! with `f64`, `sin_cos` and `tanh` are by default ([`FloatFunctions::Inline`]) private
//! functions written into the file when a kernel uses them, `fn sin_cos` (fdlibm's kernels with
//! one shared argument reduction) and `fn tanh` (Cephes' rational below 0.625, `exp` above):
//! their source is `src/fastmath/{sin_cos,tanh}.rs`, appended verbatim (comments, licence notice
//! and measured accuracy included) and tested as such by `tests/it/fastmath_accuracy.rs`. Constants are
//! written with the shortest digits that round-trip (`{:?}`), suffixed with the float type;
//! a constant equal to one of `core::f64::consts` is written by that name.

mod calls;
mod checked;
mod doc;
mod file;
mod kernel;
mod params;
mod writer;

pub use crate::options::{EmitOptions, Float, FloatFunctions};
pub use file::emit;
pub(crate) use file::emit_plan;
