//! Opening input files: the one way every reader gets at the bytes of a file it was named.
//!
//! A path in a scene can name anything the file system holds. Reading a FIFO blocks until
//! something writes to it, `/dev/zero` never ends, and a directory cannot be read at all,
//! so every reader opens its input through [`open`] or [`read`], which refuse what is not
//! a regular file before reading a byte, and read at most the [`Kind`]'s size cap. Standard
//! input is read only when the path is `-`, the explicit spelling of a pipe.
//!
//! Errors name the file and, for a cap, which cap and how to read the file anyway.

use crate::error::LoadError;
use std::fs::File;
use std::io::Read;
use std::path::Path;

const MIB: u64 = 1 << 20;
const GIB: u64 = 1 << 30;

/// What a file is read as, which decides the most bytes it may hold.
///
/// The caps are far above any real file of the kind and low enough that a file which is
/// not what it claims cannot take the machine's memory before it is refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A tress scene file (TOML): settings and references to geometry files, with at most
    /// a few inline strands or triangles.
    Scene,
    /// Another tool's scene as text or binary: Maya ASCII, pbrt-v4 (and its `Include`d
    /// files), USD layers. They can hold whole meshes and curves inline.
    ImportedScene,
    /// Geometry: `.hair`, OBJ and PLY files, and pbrt curve data.
    Geometry,
    /// tress's own EXR files read back: farm tiles and checkpoints.
    PartialImage,
    /// An image used as a map: fur maps, textures, environment maps (PNG, JPEG, EXR,
    /// HDR). Compressed images decode to far more than their size: decoders get the
    /// decoding limits on top of this cap.
    Map,
}

impl Kind {
    /// The most bytes a file of this kind may hold.
    pub fn cap(self) -> u64 {
        match self {
            Kind::Scene => 64 * MIB,
            Kind::ImportedScene => 2 * GIB,
            Kind::Geometry => 16 * GIB,
            Kind::PartialImage => 16 * GIB,
            Kind::Map => GIB,
        }
    }

    /// The kind in words, for messages.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Scene => "a scene file",
            Kind::ImportedScene => "an imported scene file",
            Kind::Geometry => "a geometry file",
            Kind::PartialImage => "a tile or checkpoint",
            Kind::Map => "an image map",
        }
    }
}

/// True for the path `-`, which means standard input.
pub fn is_stdin(path: &Path) -> bool {
    path.as_os_str() == "-"
}

/// Opens `path` for reading after checking, without blocking, that it is a regular file
/// (following symbolic links) of at most `kind`'s cap. A FIFO, a device, a socket or a
/// directory is refused with an error naming the file and what it is.
pub fn open(path: &Path, kind: Kind) -> Result<File, LoadError> {
    open_capped(path, kind, kind.cap())
}

fn too_large(path: &Path, kind: Kind, cap: u64) -> LoadError {
    LoadError::invalid(
        path,
        format!("is larger than the {} that {} may hold", crate::stats::human_bytes(cap), kind.name()),
    )
}

fn open_capped(path: &Path, kind: Kind, cap: u64) -> Result<File, LoadError> {
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    // Opening a FIFO for reading blocks until a writer opens it: ask for a non-blocking
    // open, so the check below runs at once. Regular files ignore the flag.
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    let file = options.open(path).map_err(|e| LoadError::io(path, "open the file", e))?;
    let file_type = file.metadata().map_err(|e| LoadError::io(path, "read the file's metadata", e))?.file_type();
    if !file_type.is_file() {
        return Err(LoadError::invalid(path, format!("is {}, not a regular file", describe(&file_type))));
    }
    #[cfg(unix)]
    {
        use std::os::fd::AsRawFd;
        // Reads of a regular file never block; clear the flag anyway so the descriptor
        // behaves as an ordinary one wherever it is handed.
        // SAFETY: fcntl on a descriptor this function owns, with integer arguments.
        unsafe {
            let fd = file.as_raw_fd();
            let flags = libc::fcntl(fd, libc::F_GETFL);
            if flags >= 0 {
                libc::fcntl(fd, libc::F_SETFL, flags & !libc::O_NONBLOCK);
            }
        }
    }
    if file.metadata().map_err(|e| LoadError::io(path, "read the file's metadata", e))?.len() > cap {
        return Err(too_large(path, kind, cap));
    }
    Ok(file)
}

/// What a non-regular file is, in words.
fn describe(kind: &std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if kind.is_fifo() {
            return "a FIFO (named pipe; give `-` to read a pipe from standard input)";
        }
        if kind.is_char_device() || kind.is_block_device() {
            return "a device";
        }
        if kind.is_socket() {
            return "a socket";
        }
    }
    if kind.is_dir() {
        "a directory"
    } else {
        "not a file"
    }
}

/// Reads the whole of `path` (standard input for `-`), refusing what is not a regular file
/// and anything larger than `kind`'s cap.
pub fn read(path: &Path, kind: Kind) -> Result<Vec<u8>, LoadError> {
    read_capped(path, kind, kind.cap())
}

/// Reads `path` like [`read`] as UTF-8 text; `path` names the file in the error.
pub fn read_text(path: &Path, kind: Kind) -> Result<String, LoadError> {
    String::from_utf8(read(path, kind)?).map_err(|e| {
        LoadError::format(path, format!("is not UTF-8 text (invalid byte at offset {})", e.utf8_error().valid_up_to()))
    })
}

/// [`read`] with an explicit cap (tests use small ones).
pub fn read_capped(path: &Path, kind: Kind, cap: u64) -> Result<Vec<u8>, LoadError> {
    let (reader, announced): (Box<dyn Read>, u64) = if is_stdin(path) {
        (Box::new(std::io::stdin().lock()), 0)
    } else {
        let file = open_capped(path, kind, cap)?;
        let len = file.metadata().map_err(|e| LoadError::io(path, "read the file's metadata", e))?.len();
        (Box::new(file), len)
    };
    let mut bytes = Vec::new();
    bytes.try_reserve_exact(announced as usize).map_err(|_| {
        LoadError::invalid(path, format!("no memory to read its {}", crate::stats::human_bytes(announced)))
    })?;
    // One byte more than the cap tells a file that grew past it (or a pipe) from one that
    // ends at it.
    reader.take(cap + 1).read_to_end(&mut bytes).map_err(|e| LoadError::io(path, "read the file", e))?;
    if bytes.len() as u64 > cap {
        return Err(too_large(path, kind, cap));
    }
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regular_files_are_read() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.toml");
        std::fs::write(&path, "x = 1\n").unwrap();
        assert_eq!(read_text(&path, Kind::Scene).unwrap(), "x = 1\n");
        // Through a symbolic link too: the target is what counts.
        #[cfg(unix)]
        {
            let link = dir.path().join("link.toml");
            std::os::unix::fs::symlink(&path, &link).unwrap();
            assert_eq!(read(&link, Kind::Scene).unwrap(), b"x = 1\n");
        }
    }

    #[test]
    fn directories_and_devices_are_refused_by_name() {
        let dir = tempfile::tempdir().unwrap();
        let e = read(dir.path(), Kind::Geometry).unwrap_err().to_string();
        assert!(e.starts_with(&dir.path().display().to_string()) && e.contains("a directory"), "{e}");
        #[cfg(unix)]
        {
            let e = read(Path::new("/dev/zero"), Kind::Scene).unwrap_err().to_string();
            assert_eq!(e, "/dev/zero: is a device, not a regular file");
        }
    }

    /// A FIFO with no writer would block a plain open forever.
    #[cfg(unix)]
    #[test]
    fn a_fifo_is_refused_without_blocking() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("pipe.hair");
        let c = std::ffi::CString::new(path.as_os_str().as_encoded_bytes()).unwrap();
        // SAFETY: a NUL-terminated path and a mode.
        assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
        let start = std::time::Instant::now();
        let e = read(&path, Kind::Geometry).unwrap_err().to_string();
        assert!(e.contains("is a FIFO") && e.contains("pipe.hair"), "{e}");
        assert!(start.elapsed().as_secs() < 2);
    }

    #[test]
    fn the_cap_is_named() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("big.ma");
        std::fs::write(&path, vec![b' '; 2048]).unwrap();
        let e = read_capped(&path, Kind::ImportedScene, 1024).unwrap_err().to_string();
        assert!(e.ends_with("big.ma: is larger than the 1.0 KiB that an imported scene file may hold"), "{e}");
        assert_eq!(read_capped(&path, Kind::ImportedScene, 2048).unwrap().len(), 2048);
    }

    #[test]
    fn text_must_be_utf8() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("s.toml");
        std::fs::write(&path, b"ab\xffcd").unwrap();
        let e = read_text(&path, Kind::Scene).unwrap_err().to_string();
        assert!(e.contains("s.toml: is not UTF-8 text (invalid byte at offset 2)"), "{e}");
    }
}
