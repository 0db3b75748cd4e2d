//! Reading an input file with a bound on what it costs: only a regular file, and at most a
//! given number of bytes. A device (`/dev/zero`) or a pipe could be read without end, and
//! opening a FIFO for reading blocks until a writer comes, so the file's kind is checked from
//! its metadata (following symbolic links) before it is opened; a file longer than the bound is
//! refused after reading one byte past it, whatever its metadata said.

use std::io::Read;
use std::path::{Path, PathBuf};

/// Why an input file was not read. Every variant names the file.
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    /// The file cannot be opened or read (it does not exist, permission, an I/O error).
    #[error("{}: cannot be read: {source}", path.display())]
    Io {
        /// The file, as given.
        path: PathBuf,
        /// The I/O error.
        #[source]
        source: std::io::Error,
    },
    /// Not a regular file: a directory, a device, a FIFO or a socket.
    #[error("{}: {}", path.display(), not_regular(what))]
    NotRegular {
        /// The file, as given.
        path: PathBuf,
        /// What it is instead: "a directory", "a FIFO", "a device", ...
        what: &'static str,
    },
    /// Longer than the bound.
    #[error("{}: {}", path.display(), too_large(*max))]
    TooLarge {
        /// The file, as given.
        path: PathBuf,
        /// The bound, in bytes.
        max: u64,
    },
    /// Not UTF-8 text.
    #[error("{}: is not UTF-8 text", path.display())]
    NotText {
        /// The file, as given.
        path: PathBuf,
    },
}

fn not_regular(what: &str) -> String {
    format!("is not a regular file (it is {what}); expected a regular file")
}

fn too_large(max: u64) -> String {
    format!("has more than {max} bytes; at most {max}")
}

impl ReadError {
    /// The file.
    #[must_use]
    pub fn path(&self) -> &Path {
        match self {
            ReadError::Io { path, .. }
            | ReadError::NotRegular { path, .. }
            | ReadError::TooLarge { path, .. }
            | ReadError::NotText { path } => path,
        }
    }

    /// What is wrong, without the file's name (for an error that names the file itself).
    #[must_use]
    pub fn reason(&self) -> String {
        match self {
            ReadError::Io { source, .. } => format!("cannot be read: {source}"),
            ReadError::NotRegular { what, .. } => not_regular(what),
            ReadError::TooLarge { max, .. } => too_large(*max),
            ReadError::NotText { .. } => "is not UTF-8 text".to_owned(),
        }
    }
}

impl From<ReadError> for std::io::Error {
    /// The I/O error itself, or an error of kind `InvalidInput` (not a regular file, too long)
    /// or `InvalidData` (not text) whose message is [`ReadError::reason`].
    fn from(e: ReadError) -> std::io::Error {
        use std::io::ErrorKind;
        let kind = match &e {
            ReadError::Io { .. } => ErrorKind::Other,
            ReadError::NotRegular { .. } | ReadError::TooLarge { .. } => ErrorKind::InvalidInput,
            ReadError::NotText { .. } => ErrorKind::InvalidData,
        };
        match e {
            ReadError::Io { source, .. } => source,
            other => std::io::Error::new(kind, other.reason()),
        }
    }
}

/// What a file that is not a regular one is, for messages.
fn kind_of(t: std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a FIFO";
        }
        if t.is_char_device() || t.is_block_device() {
            return "a device";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    if t.is_dir() {
        "a directory"
    } else {
        "not a file"
    }
}

/// The text of the regular file at `path`, of at most `max_bytes` bytes.
///
/// The file's kind is checked before it is opened (so that a FIFO does not block), and at most
/// `max_bytes + 1` bytes are read (so that a file that grows, or a kind that metadata did not
/// show, costs no more than that).
///
/// # Errors
/// [`ReadError`] naming `path`: it cannot be read, is not a regular file, has more than
/// `max_bytes` bytes, or is not UTF-8.
pub fn read_input(path: &Path, max_bytes: u64) -> Result<String, ReadError> {
    let io = |source| ReadError::Io {
        path: path.to_path_buf(),
        source,
    };
    let meta = std::fs::metadata(path).map_err(io)?;
    if !meta.file_type().is_file() {
        return Err(ReadError::NotRegular {
            path: path.to_path_buf(),
            what: kind_of(meta.file_type()),
        });
    }
    let too_large = || ReadError::TooLarge {
        path: path.to_path_buf(),
        max: max_bytes,
    };
    if meta.len() > max_bytes {
        return Err(too_large());
    }
    let file = std::fs::File::open(path).map_err(io)?;
    let mut bytes = Vec::new();
    file.take(max_bytes.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > max_bytes {
        return Err(too_large());
    }
    String::from_utf8(bytes).map_err(|_| ReadError::NotText {
        path: path.to_path_buf(),
    })
}
