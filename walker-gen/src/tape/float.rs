//! The float functions the generated code calls that are not std's or `libm`'s: the private
//! `sin_cos` and `tanh` that [`FloatFunctions::Inline`](crate::FloatFunctions::Inline) appends
//! to a generated file. The tape includes the very source files the emitter appends
//! (`src/fastmath/*.rs`), so that both compile the same operations.
//!
//! Which function a node calls is decided once, when the tape is built ([`Funcs`]), exactly as
//! the emitter's writer decides it: the file's own function where the options inline it, else
//! `libm` in no-std mode, else std's inherent method.

use super::instr::{Func, PairFunc, PowiFunc};
use crate::options::EmitOptions;

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

/// The functions one set of [`EmitOptions`] calls (only `f64` is evaluated by the tape).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Funcs {
    /// `sin_cos` and `tanh` are the file's own.
    inline: bool,
    /// `libm` instead of std's methods.
    no_std: bool,
}

impl Funcs {
    /// The functions of `options`, which must be `f64`.
    pub(crate) fn new(options: &EmitOptions) -> Funcs {
        Funcs {
            inline: options.inline_float_functions(),
            no_std: options.no_std,
        }
    }

    /// `sqrt`, a lone `sin` or `cos`, or `tanh` (as `emit::writer`'s `call`: the file's own
    /// function if it is one of the inline helpers, else `libm` in no-std mode, else the
    /// inherent method).
    pub(crate) fn sqrt(self) -> Func {
        if self.no_std {
            Func::LibmSqrt
        } else {
            Func::Sqrt
        }
    }

    /// See [`Funcs::sqrt`].
    pub(crate) fn sin(self) -> Func {
        if self.no_std {
            Func::LibmSin
        } else {
            Func::Sin
        }
    }

    /// See [`Funcs::sqrt`].
    pub(crate) fn cos(self) -> Func {
        if self.no_std {
            Func::LibmCos
        } else {
            Func::Cos
        }
    }

    /// See [`Funcs::sqrt`].
    pub(crate) fn tanh(self) -> Func {
        if self.inline {
            Func::InlineTanh
        } else if self.no_std {
            Func::LibmTanh
        } else {
            Func::Tanh
        }
    }

    /// A sine and a cosine of one argument (`emit::writer`'s `lets`).
    pub(crate) fn sin_cos(self) -> PairFunc {
        if self.inline {
            PairFunc::Inline
        } else if self.no_std {
            PairFunc::Libm
        } else {
            PairFunc::Std
        }
    }

    /// An integer power (never planned; see [`PowiFunc`]).
    pub(crate) fn powi(self) -> PowiFunc {
        if self.no_std {
            PowiFunc::Libm
        } else {
            PowiFunc::Std
        }
    }
}
