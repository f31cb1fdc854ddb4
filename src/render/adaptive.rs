//! Adaptive supersampling (thesis section 2.2.7: Turtle's "adaptive" anti-aliasing, after
//! Mitchell 1987, "Generating antialiased images at low sampling densities"): a pixel
//! takes more samples while the ones it has disagree, in colour by Mitchell's contrast
//! `(max - min) / (max + min)` per channel, or in what they hit (object or strand: thin
//! hairs a few samples straddle). The decision looks at the pixel's own samples only, so
//! it does not depend on the order tiles are rendered in.

use crate::math::Color;

/// What a pixel's samples have shown so far.
#[derive(Clone, Copy, Debug)]
pub struct Spread {
    min: Color,
    max: Color,
    /// (object, strand) of the first sample; `u32::MAX` marks a miss or no strand.
    first: Option<(u32, u32)>,
    mixed: bool,
}

impl Default for Spread {
    fn default() -> Self {
        Spread { min: Color::splat(f32::INFINITY), max: Color::splat(f32::NEG_INFINITY), first: None, mixed: false }
    }
}

impl Spread {
    /// Adds a sample of `color` whose camera ray hit `what` ((object, strand), `None` for
    /// a miss).
    pub fn add(&mut self, color: Color, what: Option<(u32, Option<u32>)>) {
        self.min = self.min.min(color);
        self.max = self.max.max(color);
        let id = what.map_or((u32::MAX, u32::MAX), |(o, s)| (o, s.unwrap_or(u32::MAX)));
        match self.first {
            None => self.first = Some(id),
            Some(f) => self.mixed |= f != id,
        }
    }

    /// True when the samples hit different things or a colour channel's contrast exceeds
    /// `threshold`.
    pub fn needs_more(&self, threshold: f32) -> bool {
        let sum = self.max + self.min;
        let diff = self.max - self.min;
        let contrast = |d: f32, s: f32| if s > 0.0 { d / s } else { 0.0 };
        self.mixed
            || contrast(diff.x, sum.x) > threshold
            || contrast(diff.y, sum.y) > threshold
            || contrast(diff.z, sum.z) > threshold
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refines_on_contrast_or_on_different_hits_only() {
        let mut s = Spread::default();
        s.add(Color::splat(0.5), Some((0, None)));
        s.add(Color::splat(0.52), Some((0, None)));
        assert!(!s.needs_more(0.05));
        assert!(s.needs_more(0.01));
        s.add(Color::splat(0.5), Some((0, Some(3))));
        assert!(s.needs_more(0.05), "a strand among surface samples");
        let mut s = Spread::default();
        s.add(Color::new(0.1, 0.5, 0.5), None);
        s.add(Color::new(0.2, 0.5, 0.5), None);
        assert!(s.needs_more(0.3), "contrast 1/3 in red");
    }
}
