//! Why a scene failed to load or validate.

/// A scene that failed to load or validate. Every variant names the field ([`SceneError::field`]).
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The scene file could not be read.
    #[error("cannot read scene file {path}: {source}")]
    Read {
        /// The path as given.
        path: String,
        /// The I/O error.
        source: std::io::Error,
    },
    /// The TOML is malformed, has an unknown key or a value of the wrong type.
    #[error("scene {origin}: field `{field}`: {message}")]
    Syntax {
        /// Where the scene came from (a file name or `<string>`).
        origin: String,
        /// The field at the error (dotted path), or `<file>` if it cannot be told.
        field: String,
        /// The parser's message, with the offending line.
        message: String,
    },
    /// The scene name is empty or has characters other than `a-z A-Z 0-9 - _`.
    #[error("field `name` = {value:?}: must be 1 to 64 characters from a-z, A-Z, 0-9, '-', '_'")]
    InvalidName {
        /// The rejected name.
        value: String,
    },
    /// A parameter value outside its valid range.
    #[error("field `{field}` = {value}: must be {range}")]
    OutOfRange {
        /// The field, for example `fixed.m1`.
        field: String,
        /// The rejected value.
        value: f64,
        /// The valid range, in words.
        range: &'static str,
    },
    /// Two settings contradict each other.
    #[error("field `{field}`: {reason}")]
    Contradiction {
        /// The field to change.
        field: String,
        /// What contradicts it and how to fix it.
        reason: String,
    },
    /// `kernels` names a kernel that does not exist.
    #[error("field `kernels`: unknown kernel `{name}`; valid names: {valid}")]
    UnknownKernel {
        /// The unknown name.
        name: String,
        /// The valid names, comma separated.
        valid: String,
    },
    /// `kernels` names a kernel that this structure does not have.
    #[error("field `kernels`: kernel `{name}` does not exist for {structure}; it has: {valid}")]
    KernelNotInStructure {
        /// The kernel.
        name: String,
        /// The structure, in words.
        structure: String,
        /// The kernels the structure has.
        valid: String,
    },
    /// `kernels` is empty or names a kernel twice.
    #[error("field `kernels`: {reason}")]
    BadKernelList {
        /// What is wrong.
        reason: String,
    },
}

impl SceneError {
    /// The field the error is about (dotted, for example `fixed.phi`), or `<file>` for I/O errors.
    #[must_use]
    pub fn field(&self) -> &str {
        match self {
            SceneError::Read { .. } => "<file>",
            SceneError::Syntax { field, .. }
            | SceneError::OutOfRange { field, .. }
            | SceneError::Contradiction { field, .. } => field,
            SceneError::InvalidName { .. } => "name",
            SceneError::UnknownKernel { .. }
            | SceneError::KernelNotInStructure { .. }
            | SceneError::BadKernelList { .. } => "kernels",
        }
    }
}
