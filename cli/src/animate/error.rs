//! Why `walker animate` could not write its picture: bad input (exit code 2), or the file could
//! not be drawn or written (exit code 1).

use std::io;
use std::path::PathBuf;

use crate::input::InputError;

/// Why an animation or stick diagram was not written.
#[derive(Debug, thiserror::Error)]
pub enum AnimateError {
    /// A flag out of its range, or a request too large to serve (exit code 2).
    #[error(transparent)]
    Input(#[from] InputError),
    /// Writing the file failed (exit code 1).
    #[error("cannot write {}: {source}", path.display())]
    Write {
        /// The file.
        path: PathBuf,
        /// The operating system's reason.
        #[source]
        source: io::Error,
    },
    /// Drawing or encoding the picture failed (exit code 1).
    #[error("cannot draw {}: {message}", path.display())]
    Draw {
        /// The file.
        path: PathBuf,
        /// The drawing or encoding library's message.
        message: String,
    },
}

impl AnimateError {
    /// The exit code: 2 for bad input, 1 otherwise.
    #[must_use]
    pub fn exit_code(&self) -> u8 {
        match self {
            AnimateError::Input(_) => 2,
            AnimateError::Write { .. } | AnimateError::Draw { .. } => 1,
        }
    }
}
