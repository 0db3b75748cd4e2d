//! The float functions the generated code calls that are not std's or `libm`'s: the private
//! `sin_cos` and `tanh` that [`FloatFunctions::Inline`](crate::FloatFunctions::Inline) appends
//! to a generated file. The tape includes the very source files the emitter appends
//! (`src/fastmath/*.rs`), so that both compile the same operations. Which function a node
//! calls is `select.rs`'s choice.

mod fastmath {
    include!("../fastmath/sin_cos.rs");
    include!("../fastmath/tanh.rs");

    /// The generated file's `sin_cos`.
    pub(super) fn sin_cos_of(x: f64) -> (f64, f64) {
        sin_cos(x)
    }

    /// The generated file's `tanh`.
    pub(super) fn tanh_of(x: f64) -> f64 {
        tanh(x)
    }
}

/// The generated file's `sin_cos` (fdlibm's kernels, one shared argument reduction).
#[inline]
pub(crate) fn inline_sin_cos(x: f64) -> (f64, f64) {
    fastmath::sin_cos_of(x)
}

/// The generated file's `tanh` (Cephes' rational below 0.625, `exp` above).
#[inline]
pub(crate) fn inline_tanh(x: f64) -> f64 {
    fastmath::tanh_of(x)
}
