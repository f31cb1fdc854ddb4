//! gzip-compressed input files, recognised by their magic bytes rather than their name
//! (`geometry/hair.pbrt.gz`, a `.ply` written through gzip), decompressed in memory with
//! the cap of the file's [`Kind`] on the decompressed size too, so a small forged file
//! cannot expand without bound.

use crate::error::LoadError;
use crate::input_file::Kind;
use std::io::Read;
use std::path::Path;

/// The two bytes every gzip member starts with (RFC 1952 §2.3.1).
const MAGIC: [u8; 2] = [0x1f, 0x8b];

/// True when `bytes` start like a gzip file.
pub fn is_gzip(bytes: &[u8]) -> bool {
    bytes.starts_with(&MAGIC)
}

/// `bytes` as they are, or decompressed when they are gzip data (all members of a
/// multi-member file, as `gzip` writes them when files are concatenated), refused when they
/// expand past `cap` bytes; `path` names the file in messages.
pub fn decompress_capped(bytes: Vec<u8>, path: &Path, cap: u64) -> Result<Vec<u8>, LoadError> {
    if !is_gzip(&bytes) {
        return Ok(bytes);
    }
    let mut out = Vec::new();
    // One byte past the cap tells a file of exactly `cap` bytes from a larger one.
    flate2::read::MultiGzDecoder::new(bytes.as_slice())
        .take(cap.saturating_add(1))
        .read_to_end(&mut out)
        .map_err(|e| LoadError::format(path, format!("gzip data is damaged or truncated: {e}")))?;
    if out.len() as u64 > cap {
        return Err(LoadError::invalid(
            path,
            format!("gzip data expands to more than {} bytes, the most tress decompresses", cap),
        ));
    }
    Ok(out)
}

/// Reads the file at `path` as a file of `kind` (through [`crate::input_file::read`]),
/// decompressing it when it is gzip data, to at most `kind`'s cap.
pub fn read_file(path: &Path, kind: Kind) -> Result<Vec<u8>, LoadError> {
    let bytes = crate::input_file::read(path, kind)?;
    decompress_capped(bytes, path, kind.cap())
}

#[cfg(test)]
mod tests {
    use super::*;
    use flate2::write::GzEncoder;
    use flate2::Compression;
    use std::io::Write;

    fn gz(data: &[u8]) -> Vec<u8> {
        let mut e = GzEncoder::new(Vec::new(), Compression::fast());
        e.write_all(data).unwrap();
        e.finish().unwrap()
    }

    #[test]
    fn plain_bytes_pass_through_and_gzip_is_decompressed() {
        let p = Path::new("a.pbrt");
        assert_eq!(decompress_capped(b"Shape \"curve\"".to_vec(), p, 100).unwrap(), b"Shape \"curve\"");
        let text = b"WorldBegin\n".repeat(1000);
        let packed = gz(&text);
        assert!(is_gzip(&packed) && packed.len() < text.len() / 10);
        assert_eq!(decompress_capped(packed, p, 1 << 20).unwrap(), text);
    }

    #[test]
    fn concatenated_members_are_all_read() {
        let mut two = gz(b"first ");
        two.extend(gz(b"second"));
        assert_eq!(decompress_capped(two, Path::new("x.gz"), 100).unwrap(), b"first second");
    }

    #[test]
    fn damaged_truncated_and_oversized_data_are_errors_naming_the_file() {
        let p = Path::new("geometry/hair.pbrt.gz");
        let packed = gz(&b"0123456789".repeat(100));
        let cut = packed[..packed.len() / 2].to_vec();
        let e = decompress_capped(cut, p, 1 << 20).unwrap_err().to_string();
        assert!(e.starts_with("geometry/hair.pbrt.gz: gzip data is damaged"), "{e}");
        let mut bad = packed.clone();
        let n = bad.len();
        bad[n - 6] ^= 0xff; // the CRC
        assert!(decompress_capped(bad, p, 1 << 20).is_err());
        // Exactly at the cap is fine; one byte over is refused.
        assert_eq!(decompress_capped(packed.clone(), p, 1000).unwrap().len(), 1000);
        let e = decompress_capped(packed, p, 999).unwrap_err().to_string();
        assert!(e.contains("more than 999 bytes"), "{e}");
    }
}
