//! The errors of reading files and preparing scenes: [`LoadError`], shared by every file
//! loader and writer in [`crate::io`], and [`PrepareError`], why a description cannot
//! become a world.
//!
//! Each error carries the path of the file involved, so a message printed on its own (for
//! example at the top of a failed render) still tells the user which of the scene's many
//! files to look at. Messages are lowercase fragments in the usual Rust style, e.g.
//! `hair/curly.hair: header says 1000 points but the file holds only 812`.

use crate::camera::CameraError;
use std::path::{Path, PathBuf};

/// Why a geometry file could not be read (or written).
#[derive(Debug, thiserror::Error)]
pub enum LoadError {
    /// The operating system refused an operation on the file (missing file, permissions,
    /// disk full, ...).
    #[error("{}: could not {action}: {source}", path.display())]
    Io {
        /// The file involved.
        path: PathBuf,
        /// What was being attempted, as a verb phrase ("read the file", "write the file").
        action: &'static str,
        /// The underlying error.
        #[source]
        source: std::io::Error,
    },
    /// The file does not follow its format: bad signature, truncated data, a header that
    /// contradicts the data, unparsable text.
    #[error("{}: {message}", path.display())]
    Format {
        /// The file involved.
        path: PathBuf,
        /// What is wrong, in words a user can act on.
        message: String,
    },
    /// The file is well formed but its contents are unusable: non-finite coordinates,
    /// negative thickness, indices past the vertex array, nothing to render.
    #[error("{}: {message}", path.display())]
    Invalid {
        /// The file involved.
        path: PathBuf,
        /// What is wrong, in words a user can act on.
        message: String,
    },
}

impl LoadError {
    /// An [`LoadError::Io`] error for `path`; `action` completes "could not ...".
    pub fn io(path: &Path, action: &'static str, source: std::io::Error) -> LoadError {
        LoadError::Io { path: path.to_path_buf(), action, source }
    }

    /// A [`LoadError::Format`] error for `path`.
    pub fn format(path: &Path, message: impl Into<String>) -> LoadError {
        LoadError::Format { path: path.to_path_buf(), message: message.into() }
    }

    /// An [`LoadError::Invalid`] error for `path`.
    pub fn invalid(path: &Path, message: impl Into<String>) -> LoadError {
        LoadError::Invalid { path: path.to_path_buf(), message: message.into() }
    }

    /// The file the error is about.
    pub fn path(&self) -> &Path {
        match self {
            LoadError::Io { path, .. } | LoadError::Format { path, .. } | LoadError::Invalid { path, .. } => path,
        }
    }
}

/// Why a description cannot be prepared.
#[derive(Debug, thiserror::Error)]
pub enum PrepareError {
    /// A geometry file could not be loaded.
    #[error(transparent)]
    Load(#[from] LoadError),
    /// The camera is ill-defined.
    #[error("camera: {0}")]
    Camera(#[from] CameraError),
    /// A setting is out of range.
    #[error("{0}")]
    Invalid(String),
}

/// The error and its causes, joined by `: `, leaving out a cause whose text the message
/// already holds (errors that name their file often include their source's text): what
/// the command line prints after `error: ` and what the Python package raises.
pub fn message(e: &(dyn std::error::Error + 'static)) -> String {
    let mut text = String::new();
    let mut cause = Some(e);
    while let Some(c) = cause {
        let part = c.to_string();
        if !text.contains(&part) {
            if !text.is_empty() {
                text.push_str(": ");
            }
            text.push_str(&part);
        }
        cause = c.source();
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_start_with_the_path() {
        let p = Path::new("dir/fur.hair");
        let e = LoadError::format(p, "header says 1000 points but the file holds only 812");
        assert_eq!(e.to_string(), "dir/fur.hair: header says 1000 points but the file holds only 812");
        assert_eq!(e.path(), p);
        let e = LoadError::io(p, "read the file", std::io::Error::from(std::io::ErrorKind::NotFound));
        let msg = e.to_string();
        assert!(msg.starts_with("dir/fur.hair: could not read the file: "), "{msg}");
        assert!(std::error::Error::source(&e).is_some());
        // The OS error is in the message once, though it is also the source.
        let e = LoadError::io(p, "open the file", std::io::Error::from_raw_os_error(2));
        assert_eq!(message(&e).matches("(os error 2)").count(), 1, "{}", message(&e));
    }
}
