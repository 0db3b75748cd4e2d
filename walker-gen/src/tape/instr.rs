//! The instruction set of the tape and its interpreter loop.
//!
//! An instruction reads registers of one flat `f64` register file and writes one (two for
//! [`Instr::SinCos`]). Each arithmetic instruction is one IEEE operation of the generated code,
//! rounded once, as the generated `f64` expression rounds it: Rust neither reassociates nor
//! contracts float expressions into fused multiply-adds, so the compiled kernel performs
//! exactly these operations. The float functions are the ones the generated code calls, chosen
//! when the tape is built ([`Func`], [`PairFunc`], [`PowiFunc`]).

use super::float;

/// A register: an index into the register file.
pub(crate) type Reg = u32;

/// A float function of one argument, as the generated code calls it.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Func {
    /// `x.sqrt()` (std).
    Sqrt,
    /// `x.sin()` (std; a sine whose cosine the block does not need).
    Sin,
    /// `x.cos()` (std).
    Cos,
    /// `x.tanh()` (std, [`FloatFunctions::Std`](crate::FloatFunctions::Std)).
    Tanh,
    /// The file's own `tanh` ([`FloatFunctions::Inline`](crate::FloatFunctions::Inline)).
    InlineTanh,
    /// `libm::sqrt` (no-std).
    LibmSqrt,
    /// `libm::sin` (no-std).
    LibmSin,
    /// `libm::cos` (no-std).
    LibmCos,
    /// `libm::tanh` (no-std).
    LibmTanh,
}

impl Func {
    /// `f(x)`.
    #[inline]
    fn apply(self, x: f64) -> f64 {
        match self {
            Func::Sqrt => x.sqrt(),
            Func::Sin => x.sin(),
            Func::Cos => x.cos(),
            Func::Tanh => x.tanh(),
            Func::InlineTanh => float::inline_tanh(x),
            Func::LibmSqrt => libm::sqrt(x),
            Func::LibmSin => libm::sin(x),
            Func::LibmCos => libm::cos(x),
            Func::LibmTanh => libm::tanh(x),
        }
    }
}

/// How a sine and a cosine of one argument are computed together.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum PairFunc {
    /// The file's own `sin_cos` ([`FloatFunctions::Inline`](crate::FloatFunctions::Inline)).
    Inline,
    /// `x.sin_cos()` (std).
    Std,
    /// `libm::sincos` (no-std).
    Libm,
}

impl PairFunc {
    /// `(sin x, cos x)`.
    #[inline]
    fn apply(self, x: f64) -> (f64, f64) {
        match self {
            PairFunc::Inline => float::inline_sin_cos(x),
            PairFunc::Std => x.sin_cos(),
            PairFunc::Libm => libm::sincos(x),
        }
    }
}

/// How an integer power is computed. The plan expands every power into multiplications before
/// a block is scheduled, so a tape built from a module never holds one; kept, as in the
/// emitter, so that every node has a translation.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum PowiFunc {
    /// `x.powi(n)` (std).
    Std,
    /// `libm::pow(x, n as f64)` (no-std).
    Libm,
}

/// One instruction: `d` the register written, `a`, `b` the registers read.
#[derive(Clone, Copy, PartialEq, Debug)]
pub(crate) enum Instr {
    /// `d = a + b`.
    Add { d: Reg, a: Reg, b: Reg },
    /// `d = a - b`.
    Sub { d: Reg, a: Reg, b: Reg },
    /// `d = a * b`.
    Mul { d: Reg, a: Reg, b: Reg },
    /// `d = a / b`.
    Div { d: Reg, a: Reg, b: Reg },
    /// `d = -a`.
    Neg { d: Reg, a: Reg },
    /// `d = |a|`.
    Abs { d: Reg, a: Reg },
    /// `d = f(a)`.
    Call { f: Func, d: Reg, a: Reg },
    /// `(sin, cos) = f(a)`.
    SinCos {
        f: PairFunc,
        sin: Reg,
        cos: Reg,
        a: Reg,
    },
    /// `d = a^n`.
    Powi { f: PowiFunc, d: Reg, a: Reg, n: i32 },
}

impl Instr {
    /// The registers the instruction reads.
    pub(crate) fn reads(&self) -> impl Iterator<Item = Reg> {
        let (a, b) = match *self {
            Instr::Add { a, b, .. }
            | Instr::Sub { a, b, .. }
            | Instr::Mul { a, b, .. }
            | Instr::Div { a, b, .. } => (a, Some(b)),
            Instr::Neg { a, .. }
            | Instr::Abs { a, .. }
            | Instr::Call { a, .. }
            | Instr::SinCos { a, .. }
            | Instr::Powi { a, .. } => (a, None),
        };
        std::iter::once(a).chain(b)
    }

    /// The registers the instruction writes.
    pub(crate) fn writes(&self) -> impl Iterator<Item = Reg> {
        let (d, e) = match *self {
            Instr::Add { d, .. }
            | Instr::Sub { d, .. }
            | Instr::Mul { d, .. }
            | Instr::Div { d, .. }
            | Instr::Neg { d, .. }
            | Instr::Abs { d, .. }
            | Instr::Call { d, .. }
            | Instr::Powi { d, .. } => (d, None),
            Instr::SinCos { sin, cos, .. } => (sin, Some(cos)),
        };
        std::iter::once(d).chain(e)
    }
}

/// Runs `code` on the register file `r`. Every register the code names is checked to be in
/// `r` when the program is built, so `None` (a register out of range) does not happen; it is
/// returned rather than a panic.
#[inline]
pub(crate) fn run(code: &[Instr], r: &mut [f64]) -> Option<()> {
    // `get` costs the same compare and branch as an index's bounds check, without a panic path.
    macro_rules! binary {
        ($r:ident, $d:expr, $a:expr, $b:expr, $op:tt) => {{
            let x = *$r.get($a as usize)? $op *$r.get($b as usize)?;
            *$r.get_mut($d as usize)? = x;
        }};
    }
    for instr in code {
        match *instr {
            Instr::Add { d, a, b } => binary!(r, d, a, b, +),
            Instr::Sub { d, a, b } => binary!(r, d, a, b, -),
            Instr::Mul { d, a, b } => binary!(r, d, a, b, *),
            Instr::Div { d, a, b } => binary!(r, d, a, b, /),
            Instr::Neg { d, a } => {
                let x = -*r.get(a as usize)?;
                *r.get_mut(d as usize)? = x;
            }
            Instr::Abs { d, a } => {
                let x = r.get(a as usize)?.abs();
                *r.get_mut(d as usize)? = x;
            }
            Instr::Call { f, d, a } => {
                let x = f.apply(*r.get(a as usize)?);
                *r.get_mut(d as usize)? = x;
            }
            Instr::SinCos { f, sin, cos, a } => {
                let (s, c) = f.apply(*r.get(a as usize)?);
                *r.get_mut(sin as usize)? = s;
                *r.get_mut(cos as usize)? = c;
            }
            Instr::Powi { f, d, a, n } => {
                let x = *r.get(a as usize)?;
                let y = match f {
                    PowiFunc::Std => x.powi(n),
                    PowiFunc::Libm => libm::pow(x, f64::from(n)),
                };
                *r.get_mut(d as usize)? = y;
            }
        }
    }
    Some(())
}
