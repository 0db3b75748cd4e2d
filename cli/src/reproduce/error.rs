//! Why `walker reproduce` could not write its output: the file or directory, and the cause.

use std::io;
use std::path::PathBuf;

/// A file or directory of the output could not be written (exit code 1).
#[derive(Debug, thiserror::Error)]
pub enum WriteError {
    /// Creating the directory or writing a file failed.
    #[error("cannot write {}: {source}", path.display())]
    File {
        /// The directory or file.
        path: PathBuf,
        /// The operating system's reason.
        #[source]
        source: io::Error,
    },
    /// A built-in scene or one of its models could not be made (a defect of the shipped
    /// files, which a test loads).
    #[error("cannot set up the paper's walkers: {0}")]
    Setup(String),
    /// Drawing or writing a figure failed.
    #[error("cannot write the figure {}: {message}", path.display())]
    Figure {
        /// The figure's file stem (without `.png` or `.svg`).
        path: PathBuf,
        /// The plotting library's message.
        message: String,
    },
}

impl WriteError {
    /// An I/O error at `path`.
    pub fn file(path: impl Into<PathBuf>) -> impl FnOnce(io::Error) -> WriteError {
        let path = path.into();
        move |source| WriteError::File { path, source }
    }
}
