//! Per-hair colour randomisation of the hair system: brightness (`diffuseRand`) and hue,
//! saturation and value jitter (`hueRand`, `satRand`, `valRand`) in HSV space (Smith 1978,
//! "Color Gamut Transform Pairs").

use glam::Vec3;

/// One hair's colour jitter, drawn once per hair.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Jitter {
    /// Factor on the colour (diffuse randomisation).
    pub brightness: f32,
    /// Hue shift in turns.
    pub hue: f32,
    /// Factor on the saturation.
    pub saturation: f32,
    /// Factor on the value.
    pub value: f32,
}

impl Jitter {
    /// The jitter for four uniform numbers in [0, 1) and the randomisation amounts.
    pub fn new(u: [f32; 4], diffuse: f32, hue: f32, sat: f32, val: f32) -> Jitter {
        let signed = |x: f32| 2.0 * x - 1.0;
        Jitter {
            brightness: 1.0 + diffuse * signed(u[0]),
            hue: 0.5 * hue * signed(u[1]),
            saturation: 1.0 + sat * signed(u[2]),
            value: 1.0 + val * signed(u[3]),
        }
    }

    /// True when the jitter only scales the colour (no hue, saturation or value change).
    fn brightness_only(&self) -> bool {
        self.hue == 0.0 && self.saturation == 1.0 && self.value == 1.0
    }

    /// Applies the jitter to a linear RGB colour (components >= 0).
    pub fn apply(&self, c: Vec3) -> Vec3 {
        if self.brightness_only() {
            return c * self.brightness;
        }
        let (h, s, v) = rgb_to_hsv(c);
        let h = (h + self.hue).rem_euclid(1.0);
        let s = (s * self.saturation).clamp(0.0, 1.0);
        let v = (v * self.value).max(0.0);
        hsv_to_rgb(h, s, v) * self.brightness
    }
}

/// RGB to hue (turns, [0, 1)), saturation and value (Smith 1978).
fn rgb_to_hsv(c: Vec3) -> (f32, f32, f32) {
    let (max, min) = (c.max_element(), c.min_element());
    let delta = max - min;
    if max <= 0.0 || delta <= 0.0 {
        return (0.0, 0.0, max.max(0.0));
    }
    let sector = if max == c.x {
        ((c.y - c.z) / delta).rem_euclid(6.0)
    } else if max == c.y {
        (c.z - c.x) / delta + 2.0
    } else {
        (c.x - c.y) / delta + 4.0
    };
    (sector / 6.0, delta / max, max)
}

/// Hue (turns), saturation and value to RGB (Smith 1978).
fn hsv_to_rgb(h: f32, s: f32, v: f32) -> Vec3 {
    let sector = h.rem_euclid(1.0) * 6.0;
    let channel = |n: f32| {
        let k = (n + sector).rem_euclid(6.0);
        v - v * s * k.min(4.0 - k).clamp(0.0, 1.0)
    };
    Vec3::new(channel(5.0), channel(3.0), channel(1.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hsv_round_trips_and_knows_primaries() {
        assert_eq!(rgb_to_hsv(Vec3::new(1.0, 0.0, 0.0)), (0.0, 1.0, 1.0));
        let (h, s, v) = rgb_to_hsv(Vec3::new(0.0, 0.5, 0.0));
        assert!((h - 1.0 / 3.0).abs() < 1e-6 && s == 1.0 && v == 0.5);
        for c in [Vec3::new(0.3, 0.25, 0.15), Vec3::new(0.1, 0.7, 0.9), Vec3::new(0.8, 0.2, 0.6), Vec3::splat(0.4)] {
            let (h, s, v) = rgb_to_hsv(c);
            assert!((hsv_to_rgb(h, s, v) - c).abs().max_element() < 1e-6, "{c}");
        }
    }

    #[test]
    fn jitter_stays_within_its_amounts() {
        let c = Vec3::new(0.3, 0.25, 0.15);
        assert_eq!(Jitter::new([0.5; 4], 0.2, 0.0, 0.0, 0.0).apply(c), c);
        // Brightness at the extremes of the draw: exactly ± the amount.
        assert!((Jitter::new([0.0, 0.5, 0.5, 0.5], 0.2, 0.0, 0.0, 0.0).apply(c) - c * 0.8).length() < 1e-6);
        // A hue jitter keeps value and saturation.
        let j = Jitter::new([0.5, 1.0, 0.5, 0.5], 0.0, 0.4, 0.0, 0.0).apply(c);
        let (_, s0, v0) = rgb_to_hsv(c);
        let (h1, s1, v1) = rgb_to_hsv(j);
        assert!((s1 - s0).abs() < 1e-5 && (v1 - v0).abs() < 1e-6);
        let (h0, _, _) = rgb_to_hsv(c);
        assert!(((h1 - h0).rem_euclid(1.0) - 0.2).abs() < 1e-4, "{h0} {h1}");
    }
}
