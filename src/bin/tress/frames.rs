//! Frame ranges on the command line: `12`, `1-24`, `1-24x2` (every second frame), as
//! animation renderers take them.

/// Frames to render: `first` to `last` (inclusive) every `step`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Frames {
    first: u32,
    last: u32,
    step: u32,
}

/// Most frames one command renders: a range is a list of jobs, not a loop without end.
const MAX_FRAMES: u32 = 1_000_000;

impl Frames {
    /// The frame numbers, in order.
    pub fn list(&self) -> Vec<u32> {
        (self.first..=self.last).step_by(self.step as usize).collect()
    }
}

/// Parses `N`, `FIRST-LAST` or `FIRST-LASTxSTEP`.
pub fn parse_frames(s: &str) -> Result<Frames, String> {
    let bad = || format!("`{s}` is not a frame (12) or a frame range (1-24, or 1-24x2 for every second frame)");
    let number = |t: &str| t.trim().parse::<u32>().map_err(|_| bad());
    let (range, step) = match s.split_once(['x', 'X']) {
        Some((r, st)) => (r, number(st)?),
        None => (s, 1),
    };
    let (first, last) = match range.split_once('-') {
        Some((a, b)) => (number(a)?, number(b)?),
        None => (number(range)?, number(range)?),
    };
    if step == 0 {
        return Err(format!("`{s}`: the step of a frame range must be at least 1"));
    }
    if last < first {
        return Err(format!("`{s}`: the last frame comes before the first"));
    }
    if (last - first) / step >= MAX_FRAMES {
        return Err(format!("`{s}` holds more than {MAX_FRAMES} frames"));
    }
    Ok(Frames { first, last, step })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_parse_and_list_their_frames() {
        assert_eq!(parse_frames("7").unwrap().list(), [7]);
        assert_eq!(parse_frames("1-4").unwrap().list(), [1, 2, 3, 4]);
        assert_eq!(parse_frames("1-24x10").unwrap().list(), [1, 11, 21]);
        assert_eq!(parse_frames("0-0").unwrap().list(), [0]);
        for bad in ["", "-", "a", "3-1", "1-4x0", "1-", "x2", "1-4x", "-3", "0-4000000000"] {
            assert!(parse_frames(bad).is_err(), "{bad}");
        }
    }
}
