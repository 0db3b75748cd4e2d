//! A tape (register-machine) interpreter of a lowered [`Module`](crate::Module)'s kernels, for
//! model files read at run time, where no compiler is available to build the generated Rust.
//!
//! [`TapeModule::new`] plans the module with the emitter's own plan (`src/plan/`: powers
//! expanded, divisions by the [`Division`](crate::Division) strategy, parameter-only values
//! hoisted into `prepare`, common subexpressions, `sin_cos` pairs) and compiles each block to
//! straight-line instructions over one flat `f64` register file, grouped into runs of one
//! operation (one dispatch per run). [`TapeModule::prepare`] runs `prepare`'s block on a
//! parameter set, and [`TapeModule::eval`] runs a kernel's block on its arguments, with no
//! allocation per call once the caller's [`Scratch`] has grown:
//!
//! ```text
//! let tape = TapeModule::new(&module, &options)?;      // once per model file
//! let prepared = tape.prepare(&params)?;                // once per parameter set
//! let accel = tape.kernel_index("accel").ok_or(..)?;    // once
//! let mut scratch = tape.scratch();                     // once per thread
//! tape.eval(accel, &prepared, &args, &mut out, &mut scratch)?;   // per call
//! ```
//!
//! # Bit for bit the generated code
//!
//! The emitted function evaluates every operation node of its block exactly once, rounded once
//! as IEEE `f64` arithmetic (Rust does not reassociate float expressions nor contract them into
//! fused multiply-adds), and the emitter's only reorderings swap the operands of `+` and `*`,
//! which commute exactly. The tape evaluates the same nodes, each once, with the same
//! operation on the same operands, and calls the same float functions the writer picks for the
//! options: the file's own `sin_cos` and `tanh` for
//! [`FloatFunctions::Inline`](crate::FloatFunctions::Inline) (the tape includes the same source
//! files the emitter appends), std's `sin`, `cos`, `sqrt` (and `sin_cos`, `tanh` for
//! [`FloatFunctions::Std`](crate::FloatFunctions::Std)), `libm`'s in no-std mode. So each value,
//! and each output, is the same bits, including the sign of zero. What the tape does
//! differently changes no value: it evaluates the nodes in another order that also computes
//! operands first (a node's value depends on its operands' values only), and computes a product
//! used once together with its user (`a * b + c` as two operations, each rounded, never a fused
//! multiply-add).
//!
//! Only NaNs may differ in sign and payload: Rust does not specify the bits of a NaN an
//! operation returns (x86's `addsd` returns the first operand's payload, and the compiler may
//! swap the operands of a commutative operation), so equality is of the value, NaN matching
//! NaN. The tests (`tests/tests/it/tape_vs_compiled.rs` in the workspace) check all this against
//! the compiled kernels of every model file and of the simulator's scenes, at ordinary points
//! and at zeros, subnormals, infinities, NaN and the branch points of the inline functions.
//!
//! Where the bits can come apart, outside these tests: std's `sin`, `cos`, `exp` (inside the
//! inline `tanh`) and, with `FloatFunctions::Std`, `sin_cos` and `tanh` are the platform's
//! `libm`, so the tape and a compiled kernel agree when they run on the same platform (LLVM
//! may also fold such a call of a constant at compile time, with the compiling machine's
//! `libm`); in no-std mode the tape calls walker-gen's `libm` crate (0.2), and a compiled
//! kernel the `libm` its own build resolves. `f32` code ([`Float::F32`](crate::Float::F32)) is
//! not evaluated ([`TapeError::Unsupported`]).
//!
//! # Why by hand
//!
//! No crate evaluates this IR: expression evaluators (`meval`, `evalexpr`, `fasteval`) parse
//! text into their own trees, with their own float functions and their own evaluation order,
//! and JIT compilers (Cranelift) would bring a code generator into the simulator for what is a
//! loop over a few hundred straight-line instructions, and would still need the planning done
//! here. The planner's output is already a register program in all but name.
//!
//! # Layout
//!
//! `float.rs` (the generated file's own `sin_cos` and `tanh`), `instr.rs` (instruction set and
//! interpreter loop), `select.rs` (which float function a node calls), `program.rs` (a compiled
//! block, its register layout, running it), `compile.rs` (block to program, register reuse),
//! `kernel.rs` ([`TapeKernel`], [`KernelIndex`]), `values.rs` ([`Prepared`], [`Scratch`]),
//! `module.rs` ([`TapeModule`]), `error.rs` ([`TapeError`]).

mod compile;
mod error;
mod float;
mod instr;
mod kernel;
mod module;
mod program;
mod select;
#[cfg(test)]
mod tests;
mod values;

pub use error::TapeError;
pub use kernel::{KernelIndex, TapeKernel};
pub use module::TapeModule;
pub use values::{Prepared, Scratch};
