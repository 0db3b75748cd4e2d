//! Why a tape could not be built or run ([`TapeError`]).

use crate::error::EmitError;

/// Why [`TapeModule::new`](super::TapeModule::new) refused a module, or why a call on a
/// [`TapeModule`](super::TapeModule) was given the wrong inputs.
///
/// Every call of the tape checks its slices' lengths and returns this instead of panicking: the
/// numbers come from a user's model file at run time.
#[derive(Debug, thiserror::Error)]
pub enum TapeError {
    /// The module cannot be planned: the emitter would refuse it too.
    #[error(transparent)]
    Plan(#[from] EmitError),
    /// The options ask for code the tape does not evaluate (`f32`).
    #[error("the tape does not evaluate {what}")]
    Unsupported {
        /// What was asked for.
        what: &'static str,
    },
    /// [`TapeModule::prepare`](super::TapeModule::prepare) was given the wrong number of
    /// parameters.
    #[error("the module has {expected} runtime parameters, {got} were given")]
    ParamCount {
        /// The number of runtime parameters ([`TapeModule::params`](super::TapeModule::params)).
        expected: usize,
        /// The length of the slice given.
        got: usize,
    },
    /// A [`KernelIndex`](super::KernelIndex) that is not one of this module's kernels.
    #[error("kernel #{index} does not exist: the module has {count} kernels")]
    UnknownKernel {
        /// The index given.
        index: usize,
        /// The number of kernels.
        count: usize,
    },
    /// A kernel was given the wrong number of arguments.
    #[error("kernel `{kernel}` takes {expected} arguments, {got} were given")]
    ArgumentCount {
        /// The kernel.
        kernel: String,
        /// Its number of arguments.
        expected: usize,
        /// The length of the slice given.
        got: usize,
    },
    /// A kernel was given an output slice of the wrong length.
    #[error("kernel `{kernel}` has {expected} outputs, the output slice holds {got}")]
    OutputCount {
        /// The kernel.
        kernel: String,
        /// Its number of outputs.
        expected: usize,
        /// The length of the slice given.
        got: usize,
    },
    /// The [`Prepared`](super::Prepared) values were made by another
    /// [`TapeModule`](super::TapeModule).
    #[error("these prepared values belong to another tape module")]
    ForeignPrepared,
    /// The plan holds something the tape cannot translate (a walker-gen bug, never the user's).
    #[error("walker-gen bug: {message}")]
    Internal {
        /// What was found.
        message: String,
    },
}
