//! Which float function a node calls, decided once, when the tape is built ([`Funcs`]), exactly
//! as the emitter's writer decides it: the file's own function where the options inline it
//! (`float.rs`), else `libm` in no-std mode, else std's inherent method.

use super::instr::{Func, PairFunc, PowiFunc};
use crate::options::EmitOptions;

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
