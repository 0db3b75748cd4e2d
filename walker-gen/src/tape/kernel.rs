//! One kernel of a tape: its signature ([`TapeKernel`]) and its handle ([`KernelIndex`]).

use super::program::Program;
use crate::ir::Shape;

/// A kernel of a [`TapeModule`](super::TapeModule), by its position in the module (the order of
/// the generated file). Get one from [`TapeModule::kernel_index`](super::TapeModule::kernel_index)
/// or [`TapeModule::kernel_indices`](super::TapeModule::kernel_indices).
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub struct KernelIndex(pub(crate) usize);

impl KernelIndex {
    /// The position of the kernel in its module.
    #[must_use]
    pub fn index(self) -> usize {
        self.0
    }
}

/// One compiled kernel: what the generated `pub fn <name>(p: &Prepared, args..) -> Out` takes
/// and returns, and its instructions.
#[derive(Clone, Debug)]
pub struct TapeKernel {
    pub(crate) name: String,
    pub(crate) args: Vec<String>,
    pub(crate) outputs: Vec<String>,
    pub(crate) shape: Shape,
    pub(crate) program: Program,
}

impl TapeKernel {
    /// The kernel's name, the generated function's (`accel`, `closed_loop`).
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The argument names in the generated function's order (after `p`); the `args` of
    /// [`TapeModule::eval`](super::TapeModule::eval) are in this order. Arguments the kernel
    /// does not read are kept, as in the generated signature.
    #[must_use]
    pub fn args(&self) -> &[String] {
        &self.args
    }

    /// The output names, row-major for a matrix (the order
    /// [`TapeModule::eval`](super::TapeModule::eval) writes them in).
    #[must_use]
    pub fn output_names(&self) -> &[String] {
        &self.outputs
    }

    /// How the generated function returns the outputs (`F`, `[F; n]`, `[[F; c]; r]`).
    #[must_use]
    pub fn shape(&self) -> Shape {
        self.shape
    }

    /// The number of outputs ([`Shape::len`]).
    #[must_use]
    pub fn output_len(&self) -> usize {
        self.outputs.len()
    }

    /// The number of instructions one call runs: one per operation of the generated function
    /// (a `sin_cos` is one), except that a product used once by a sum, difference or product
    /// is computed by its user's instruction (each operation still rounded on its own).
    #[must_use]
    pub fn instructions(&self) -> usize {
        self.program.code.len()
    }

    /// The number of dispatches one call makes: runs of consecutive instructions with the same
    /// operation, which the interpreter loop runs without a branch between them.
    #[must_use]
    pub fn dispatches(&self) -> usize {
        self.program.code.runs.len()
    }

    /// The size of the register file one call needs (arguments, constants, `Prepared` values
    /// read, live temporaries).
    #[must_use]
    pub fn registers(&self) -> usize {
        self.program.n_regs
    }
}
