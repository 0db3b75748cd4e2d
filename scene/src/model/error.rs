//! Why a model file failed to load: every error names the file, the line and column (1-based)
//! and what was expected there.

use std::fmt;

/// A place in a model file: line and column, both 1-based, the column counted in characters.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub struct Location {
    /// The line, from 1.
    pub line: usize,
    /// The column, from 1, in characters.
    pub column: usize,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}", self.line, self.column)
    }
}

/// The class of a model error, for callers that react to some of them.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub enum ModelErrorKind {
    /// The TOML does not parse, or a field is unknown, missing or of the wrong type.
    Toml,
    /// `format` is not 1.
    Format,
    /// A name that is not an identifier (or not `[a-z][a-z0-9-]*` where that is asked).
    BadName,
    /// A name declared twice.
    Duplicate,
    /// A reserved name (`t`, `mu`, `sin`, `cos`, a velocity or acceleration) declared.
    Reserved,
    /// An expression that does not parse.
    Syntax,
    /// A symbol that is not declared.
    UnknownSymbol,
    /// A declared symbol where it may not appear (a velocity in a position, say).
    SymbolNotAllowed,
    /// `sin` or `cos` of something that is not an angle combination, or a body angle that is
    /// not one.
    NotAnAngleCombination,
    /// An angle outside `sin`/`cos` in a position.
    AngleAsLength,
    /// Division by a constant that is zero.
    DivisionByZero,
    /// A parameter range that does not parse or is empty, or a default outside it.
    Range,
    /// A reference to a point, parameter or coordinate that is not declared or not of the
    /// right kind.
    UnknownReference,
    /// A list of the wrong length or a section with the wrong number of entries.
    Count,
    /// Two sections that contradict each other, or a field required by another one missing.
    Inconsistent,
    /// A model, list, name or number past one of the [`limits`](crate::limits).
    Limit,
    /// A value without physical sense: a mass or an inertia that is not positive over the
    /// parameters' ranges, a start off the floor, a guard that is zero everywhere, an
    /// expression that is not finite at the defaults, a duration that is not positive.
    Physics,
}

/// A model file that could not be read or is not a valid model.
#[derive(Debug, thiserror::Error)]
pub enum ModelError {
    /// The file could not be read, is not a regular file, or is longer than
    /// [`MAX_FILE_BYTES`](crate::limits::MAX_FILE_BYTES).
    #[error("{path}: cannot read the model file: {source}")]
    Read {
        /// The path as given.
        path: String,
        /// The I/O error (kind `InvalidInput` for a file that is not regular or too long; see
        /// [`read_input`](crate::read::read_input)).
        #[source]
        source: std::io::Error,
    },
    /// The file is not a valid model.
    #[error("{path}:{line}:{column}: {message}")]
    Invalid {
        /// The path as given (or the origin passed to the string loader).
        path: String,
        /// The line, from 1.
        line: usize,
        /// The column, from 1, in characters.
        column: usize,
        /// The class of the error.
        kind: ModelErrorKind,
        /// What is wrong and what was expected.
        message: String,
    },
}

impl ModelError {
    /// An [`ModelError::Invalid`] at `at` in the file `path`.
    #[must_use]
    pub fn invalid(path: &str, at: Location, kind: ModelErrorKind, message: String) -> ModelError {
        ModelError::Invalid {
            path: path.to_owned(),
            line: at.line,
            column: at.column,
            kind,
            message,
        }
    }

    /// The file the error is in.
    #[must_use]
    pub fn path(&self) -> &str {
        match self {
            ModelError::Read { path, .. } | ModelError::Invalid { path, .. } => path,
        }
    }

    /// The line and column, if the file was read.
    #[must_use]
    pub fn location(&self) -> Option<Location> {
        match self {
            ModelError::Read { .. } => None,
            ModelError::Invalid { line, column, .. } => Some(Location {
                line: *line,
                column: *column,
            }),
        }
    }

    /// The class of the error (`None` for a read failure).
    #[must_use]
    pub fn kind(&self) -> Option<ModelErrorKind> {
        match self {
            ModelError::Read { .. } => None,
            ModelError::Invalid { kind, .. } => Some(*kind),
        }
    }

    /// The message without the location.
    #[must_use]
    pub fn message(&self) -> String {
        match self {
            ModelError::Read { source, .. } => source.to_string(),
            ModelError::Invalid { message, .. } => message.clone(),
        }
    }
}
