//! Animation: a scene file read at one frame. Camera keys are interpolated linearly and
//! every run of `#` in a file name becomes the frame number.

use super::schema::{CameraKeyToml, CameraToml, V3};
use std::path::{Path, PathBuf};

/// Why rendering `frame` of a scene may not be what was meant: a frame outside the camera
/// keys holds the camera still, and a scene with neither keys nor frame patterns renders the
/// same image at every frame.
pub(super) fn frame_warning(c: &CameraToml, animated: bool, frame: u32) -> Option<String> {
    match (c.key.first(), c.key.last()) {
        (Some(first), Some(last)) if frame < first.frame || frame > last.frame => Some(format!(
            "frame {frame} is outside the camera keys (frames {} to {}): the camera holds at the nearest key",
            first.frame, last.frame
        )),
        _ if !animated => {
            Some("the scene has no camera keys or `#` frame patterns: every frame renders the same image".into())
        }
        _ => None,
    }
}

/// Eye, target and field of view at `frame`: the fixed camera, or the keys interpolated
/// linearly (held before the first key and after the last).
pub(super) fn camera_at(c: &CameraToml, frame: u32) -> Result<(V3, V3, f32), String> {
    let (first, last) = match (c.key.first(), c.key.last()) {
        (None, _) | (_, None) => {
            return match (c.eye, c.target) {
                (Some(eye), Some(target)) => Ok((eye, target, c.vfov)),
                _ => Err("give `eye` and `target`, or camera keys".into()),
            }
        }
        (Some(first), Some(last)) => (first, last),
    };
    if c.eye.is_some() || c.target.is_some() {
        return Err("give either `eye` and `target` or camera keys, not both".into());
    }
    if let Some(w) = c.key.windows(2).find(|w| w[0].frame >= w[1].frame) {
        return Err(format!("key frames must increase: frame {} comes after frame {}", w[1].frame, w[0].frame));
    }
    let vfov = |k: &CameraKeyToml| k.vfov.unwrap_or(c.vfov);
    let key = |k: &CameraKeyToml| (k.eye, k.target, vfov(k));
    if frame <= first.frame {
        return Ok(key(first));
    }
    if frame >= last.frame {
        return Ok(key(last));
    }
    let after = c.key.partition_point(|k| k.frame <= frame);
    let (a, b) = (&c.key[after - 1], &c.key[after]);
    let t = (frame - a.frame) as f32 / (b.frame - a.frame) as f32;
    let lerp3 = |p: V3, q: V3| std::array::from_fn(|i| p[i] + (q[i] - p[i]) * t);
    Ok((lerp3(a.eye, b.eye), lerp3(a.target, b.target), vfov(a) + (vfov(b) - vfov(a)) * t))
}

/// True when a file name holds a `#` frame pattern.
pub fn has_pattern(file: &Path) -> bool {
    file.file_name().is_some_and(|n| n.to_string_lossy().contains('#'))
}

/// The file name with every run of `#` replaced by `frame`, zero-padded to the run's length
/// (`hair.####.hair` at frame 7 is `hair.0007.hair`): scene files' frame patterns and the
/// command line's output names alike.
pub fn at_frame(file: &Path, frame: u32) -> PathBuf {
    let Some(name) = file.file_name().map(|n| n.to_string_lossy().into_owned()) else { return file.to_owned() };
    if !name.contains('#') {
        return file.to_owned();
    }
    let mut out = String::new();
    let mut chars = name.chars().peekable();
    while let Some(ch) = chars.next() {
        if ch != '#' {
            out.push(ch);
            continue;
        }
        let mut width = 1;
        while chars.next_if_eq(&'#').is_some() {
            width += 1;
        }
        out.push_str(&format!("{frame:0width$}"));
    }
    file.with_file_name(out)
}
