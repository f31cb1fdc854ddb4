//! Whole scenes: a scene file and the files it names, in one input so mutations reach
//! both. The bytes are a bundle: `scene.toml`, then each further file after a line
//! `--- NAME` (NAME a plain file name). The bundle is written to a temporary directory, the
//! scene read, validated, estimated and, when the estimate is small, prepared (loaded,
//! fur grown, BVH built): an error or a world, never a panic.

/// Seed files.
pub const SEEDS: &[&str] = &["tests/data/scene_bundle.txt"];

/// Most estimated memory of a scene that is prepared: larger scenes stop after the estimate.
const PREPARE_BELOW: u64 = 64 << 20;

/// The files of a bundle: (name, bytes), the scene first. `None` for a name that is not a
/// plain file name.
fn unbundle(bytes: &[u8]) -> Option<Vec<(String, &[u8])>> {
    let mut files = Vec::new();
    let mut name = "scene.toml".to_string();
    let mut rest = bytes;
    loop {
        let split = rest.windows(5).position(|w| w == b"\n--- ");
        let (body, next) = match split {
            Some(at) => (&rest[..at], Some(&rest[at + 5..])),
            None => (rest, None),
        };
        files.push((name, body));
        let Some(next) = next else { break };
        let end = next.iter().position(|&b| b == b'\n').unwrap_or(next.len());
        name = String::from_utf8(next[..end].to_vec()).ok()?;
        let plain = !name.is_empty()
            && name.len() <= 64
            && name.bytes().all(|b| b.is_ascii_alphanumeric() || b"._-".contains(&b))
            && name != "."
            && name != ".."
            && !files.iter().any(|(n, _)| *n == name);
        if !plain {
            return None;
        }
        rest = &next[(end + 1).min(next.len())..];
    }
    Some(files)
}

/// Reads, validates, estimates and prepares the bundled scene; true when it prepared.
pub fn check(bytes: &[u8]) -> bool {
    let Some(files) = unbundle(bytes) else { return false };
    let dir = tempfile::tempdir().expect("a temporary directory");
    for (name, body) in &files {
        std::fs::write(dir.path().join(name), body).expect("writing a bundled file");
    }
    let scene = dir.path().join("scene.toml");
    let Ok((mut desc, _)) = tress::io::scene_file::read(&scene, Some(1)) else {
        return false;
    };
    if desc.validate().is_err() {
        return false;
    }
    desc.settings.threads = 1;
    match tress::prepare::estimate_memory(&desc) {
        Ok(e) if e.total() < PREPARE_BELOW => {}
        _ => return false,
    }
    tress::prepare::prepare(&desc).is_ok()
}

#[cfg(test)]
mod tests {
    #[test]
    fn bundles_split_into_files() {
        let files = super::unbundle(b"a = 1\n--- x.obj\nv 0 0 0\n--- y.hair\nHAIR").unwrap();
        let names: Vec<_> = files.iter().map(|(n, b)| (n.as_str(), *b)).collect();
        assert_eq!(names, [("scene.toml", &b"a = 1"[..]), ("x.obj", b"v 0 0 0"), ("y.hair", b"HAIR")]);
        assert!(super::unbundle(b"a\n--- ../x\n").is_none());
    }
}
