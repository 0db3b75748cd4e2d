//! The instruction set of the tape and its interpreter loop.
//!
//! An instruction ([`Instr`]) is an operation ([`Op`]) and four register indices into one flat
//! `f64` register file: `[d, a, b, _]` for `d = a op b`, `[d, a, _, _]` for `d = op a`,
//! `[d, a, b, c]` for the fused operations (`d = a * b + c`, ...), `[sin, cos, a, _]` for a sine
//! and cosine computed together. Each arithmetic operation is an IEEE operation of the
//! generated code, rounded once, as the generated `f64` expression rounds it: Rust neither
//! reassociates nor contracts float expressions into fused multiply-adds, so the compiled
//! kernel performs exactly these operations. A fused operation is two of them, each rounded:
//! `a * b + c` is `(a * b) + c`, a product used once, by a sum, in the generated code, never a
//! fused multiply-add. The float functions are the ones the generated
//! code calls, chosen when the tape is built ([`Func`], [`PairFunc`], [`PowiFunc`]).
//!
//! The code is stored as *runs* ([`Code`]): consecutive instructions of the same operation share
//! one dispatch, and the loop over a run's operands has no indirect branch. The schedule
//! (`compile.rs`) orders the instructions to make runs long; on the shipped models a run holds
//! from 1.7 (paper-active) to 4.6 (five-link) instructions on average.

use super::float;

/// A register: an index into the register file.
pub(crate) type Reg = u32;

/// A float function of one argument, as the generated code calls it.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
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
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
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
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub(crate) enum PowiFunc {
    /// `x.powi(n)` (std).
    Std,
    /// `libm::pow(x, n as f64)` (no-std).
    Libm,
}

/// The operation of an instruction.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub(crate) enum Op {
    /// `d = a + b`.
    Add,
    /// `d = a - b`.
    Sub,
    /// `d = a * b`.
    Mul,
    /// `d = a / b`.
    Div,
    /// `d = -a`.
    Neg,
    /// `d = |a|`.
    Abs,
    /// `d = (a * b) + c`, two roundings.
    MulAdd,
    /// `d = (a * b) - c`, two roundings.
    MulSub,
    /// `d = c - (a * b)`, two roundings.
    SubMul,
    /// `d = (a * b) * c`, two roundings.
    MulMul,
    /// `d = f(a)`.
    Call(Func),
    /// `(sin, cos) = f(a)`: registers `[sin, cos, a]`.
    SinCos(PairFunc),
    /// `d = a^n`.
    Powi(PowiFunc, i32),
}

/// One instruction: an operation and its registers (see the module docs for their order).
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) struct Instr {
    /// The operation.
    pub(crate) op: Op,
    /// `[d, a, b, _]`, `[d, a, _, _]`, `[d, a, b, c]` or `[sin, cos, a, _]`.
    pub(crate) regs: [Reg; 4],
}

impl Instr {
    /// The registers the instruction reads.
    pub(crate) fn reads(&self) -> &[Reg] {
        let range = match self.op {
            Op::Add | Op::Sub | Op::Mul | Op::Div => 1..3,
            Op::MulAdd | Op::MulSub | Op::SubMul | Op::MulMul => 1..4,
            Op::SinCos(_) => 2..3,
            Op::Neg | Op::Abs | Op::Call(_) | Op::Powi(..) => 1..2,
        };
        self.regs.get(range).unwrap_or(&[])
    }

    /// The registers the instruction writes.
    pub(crate) fn writes(&self) -> &[Reg] {
        match self.op {
            Op::SinCos(_) => self.regs.get(..2).unwrap_or(&[]),
            _ => self.regs.get(..1).unwrap_or(&[]),
        }
    }
}

/// A run of consecutive instructions with the same operation: `regs[start..end]` of [`Code`].
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) struct Run {
    pub(crate) op: Op,
    pub(crate) start: u32,
    pub(crate) end: u32,
}

/// Straight-line code as runs of one operation each.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Code {
    /// The runs, in order.
    pub(crate) runs: Vec<Run>,
    /// The registers of every instruction, in order.
    pub(crate) regs: Vec<[Reg; 4]>,
}

impl Code {
    /// `instrs` as runs.
    pub(crate) fn new(instrs: &[Instr]) -> Option<Code> {
        let mut code = Code::default();
        for i in instrs {
            let at = u32::try_from(code.regs.len()).ok()?;
            match code.runs.last_mut() {
                Some(run) if run.op == i.op => run.end = at + 1,
                _ => code.runs.push(Run {
                    op: i.op,
                    start: at,
                    end: at + 1,
                }),
            }
            code.regs.push(i.regs);
        }
        Some(code)
    }

    /// The number of instructions.
    pub(crate) fn len(&self) -> usize {
        self.regs.len()
    }

    /// The instructions, in order.
    pub(crate) fn instrs(&self) -> impl Iterator<Item = Instr> + '_ {
        self.runs.iter().flat_map(|run| {
            let regs = self
                .regs
                .get(run.start as usize..run.end as usize)
                .unwrap_or(&[]);
            regs.iter().map(|&regs| Instr { op: run.op, regs })
        })
    }
}

/// Runs `code` on the register file `r`. Every register the code names is checked to be in
/// `r` when the program is built, so `None` (a register out of range) does not happen; it is
/// returned rather than a panic.
#[inline]
pub(crate) fn run(code: &Code, r: &mut [f64]) -> Option<()> {
    // `get` costs the same compare and branch as an index's bounds check, without a panic path.
    macro_rules! each {
        ($regs:ident, |$d:ident, $a:ident, $b:ident, $c:ident| $value:expr) => {
            for &[$d, $a, $b, $c] in $regs {
                let v = $value;
                *r.get_mut($d as usize)? = v;
            }
        };
    }
    macro_rules! get {
        ($x:expr) => {
            *r.get($x as usize)?
        };
    }
    for run in &code.runs {
        let regs = code.regs.get(run.start as usize..run.end as usize)?;
        match run.op {
            Op::Add => each!(regs, |d, a, b, _c| get!(a) + get!(b)),
            Op::Sub => each!(regs, |d, a, b, _c| get!(a) - get!(b)),
            Op::Mul => each!(regs, |d, a, b, _c| get!(a) * get!(b)),
            Op::Div => each!(regs, |d, a, b, _c| get!(a) / get!(b)),
            Op::Neg => each!(regs, |d, a, _b, _c| -get!(a)),
            Op::Abs => each!(regs, |d, a, _b, _c| get!(a).abs()),
            Op::MulAdd => each!(regs, |d, a, b, c| get!(a) * get!(b) + get!(c)),
            Op::MulSub => each!(regs, |d, a, b, c| get!(a) * get!(b) - get!(c)),
            Op::SubMul => each!(regs, |d, a, b, c| get!(c) - get!(a) * get!(b)),
            Op::MulMul => each!(regs, |d, a, b, c| get!(a) * get!(b) * get!(c)),
            Op::Call(f) => each!(regs, |d, a, _b, _c| f.apply(get!(a))),
            Op::SinCos(f) => {
                for &[sin, cos, a, _] in regs {
                    let (s, c) = f.apply(get!(a));
                    *r.get_mut(sin as usize)? = s;
                    *r.get_mut(cos as usize)? = c;
                }
            }
            Op::Powi(f, n) => each!(regs, |d, a, _b, _c| {
                let x = get!(a);
                match f {
                    PowiFunc::Std => x.powi(n),
                    PowiFunc::Libm => libm::pow(x, f64::from(n)),
                }
            }),
        }
    }
    Some(())
}
