//! Ramps ("scale along the hair" graphs) as Maya stores them: keys of (position, value,
//! interpolation), with `position` 0 at the root and 1 at the tip.
//!
//! Maya writes a ramp key as three numbers, `position value interp`, with the
//! interpolation enum 0 None, 1 Linear, 2 Smooth, 3 Spline (docs/maya-fur-hair.md
//! section 5.3, observed in `.ma` files). How each interpolation curves is not documented;
//! this module's reading of it, applied to the interval from a key to the next one:
//!
//! - **None**: the key's value holds until the next key (a step).
//! - **Linear**: straight line to the next key's value.
//! - **Smooth**: cubic ease with zero slope at both keys, `3t² − 2t³` (a Hermite curve with
//!   flat tangents), so the ramp has no corners at keys.
//! - **Spline**: cubic Hermite with Catmull-Rom slopes (Catmull and Rom 1974): the slope at
//!   a key is the slope of the chord between its two neighbours, one-sided at the first and
//!   last keys; the curve passes through every key.
//!
//! Before the first key the ramp holds the first key's value, after the last key the last
//! value, as Maya's graph editor shows it. Values may be numbers or colours.

use glam::Vec3;
use std::ops::{Add, Mul, Sub};

/// How a ramp goes from a key to the next one (Maya's enum 0 to 3).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interp {
    /// Hold the key's value (0).
    None,
    /// Straight line (1).
    Linear,
    /// Cubic ease with flat ends (2).
    Smooth,
    /// Catmull-Rom cubic through the neighbouring keys (3).
    Spline,
}

impl Interp {
    /// The interpolation named `name` (`none`, `linear`, `smooth` or `spline`).
    pub fn from_name(name: &str) -> Option<Interp> {
        match name {
            "none" => Some(Interp::None),
            "linear" => Some(Interp::Linear),
            "smooth" => Some(Interp::Smooth),
            "spline" => Some(Interp::Spline),
            _ => None,
        }
    }
}

/// What a ramp can hold: numbers and colours.
pub trait RampValue: Copy + Add<Output = Self> + Sub<Output = Self> + Mul<f32, Output = Self> {
    /// True when every component is finite.
    fn is_finite_value(&self) -> bool;
}

impl RampValue for f32 {
    fn is_finite_value(&self) -> bool {
        self.is_finite()
    }
}

impl RampValue for Vec3 {
    fn is_finite_value(&self) -> bool {
        self.is_finite()
    }
}

/// One key of a ramp.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RampKey<T> {
    /// Where along the hair, 0 (root) to 1 (tip).
    pub position: f32,
    /// The value there.
    pub value: T,
    /// How the ramp goes on to the next key.
    pub interp: Interp,
}

/// A ramp: keys sorted by position (at least one).
#[derive(Clone, Debug, PartialEq)]
pub struct Ramp<T> {
    keys: Vec<RampKey<T>>,
}

impl<T: RampValue> Ramp<T> {
    /// A ramp with one value everywhere.
    pub fn constant(value: T) -> Ramp<T> {
        Ramp { keys: vec![RampKey { position: 0.0, value, interp: Interp::Linear }] }
    }

    /// A ramp from keys in any order; sorted by position, keys at equal positions keep
    /// their given order (the later one wins from that position on, as in Maya). Errors
    /// name the bad key (1-based, in the given order).
    pub fn new(mut keys: Vec<RampKey<T>>) -> Result<Ramp<T>, String> {
        if keys.is_empty() {
            return Err("a ramp needs at least one key".into());
        }
        for (i, k) in keys.iter().enumerate() {
            if !(k.position.is_finite() && (0.0..=1.0).contains(&k.position)) {
                return Err(format!("key {}: position {} is not in [0, 1]", i + 1, k.position));
            }
            if !k.value.is_finite_value() {
                return Err(format!("key {}: value is not a finite number", i + 1));
            }
        }
        keys.sort_by(|a, b| a.position.total_cmp(&b.position));
        Ok(Ramp { keys })
    }

    /// The keys, sorted by position.
    pub fn keys(&self) -> &[RampKey<T>] {
        &self.keys
    }

    /// The ramp's value at `x` (clamped to the keys' range).
    pub fn eval(&self, x: f32) -> T {
        let keys = &self.keys;
        // Index of the last key at or before x.
        let i = keys.partition_point(|k| k.position <= x);
        if i == 0 {
            return keys[0].value;
        }
        let i = i - 1;
        if i + 1 == keys.len() {
            return keys[i].value;
        }
        let (k0, k1) = (&keys[i], &keys[i + 1]);
        let span = k1.position - k0.position;
        let t = if span > 0.0 { ((x - k0.position) / span).clamp(0.0, 1.0) } else { 1.0 };
        match k0.interp {
            Interp::None => k0.value,
            Interp::Linear => k0.value + (k1.value - k0.value) * t,
            Interp::Smooth => k0.value + (k1.value - k0.value) * (t * t * (3.0 - 2.0 * t)),
            Interp::Spline => {
                // Catmull-Rom slopes per unit position, scaled to the interval (Hermite form).
                let slope = |j: usize| -> T {
                    let (a, b) = (&keys[j.saturating_sub(1)], &keys[(j + 1).min(keys.len() - 1)]);
                    let dx = b.position - a.position;
                    if dx > 0.0 {
                        (b.value - a.value) * (1.0 / dx)
                    } else {
                        (b.value - a.value) * 0.0
                    }
                };
                let (m0, m1) = (slope(i) * span, slope(i + 1) * span);
                let (t2, t3) = (t * t, t * t * t);
                k0.value * (2.0 * t3 - 3.0 * t2 + 1.0)
                    + m0 * (t3 - 2.0 * t2 + t)
                    + k1.value * (3.0 * t2 - 2.0 * t3)
                    + m1 * (t3 - t2)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn key(position: f32, value: f32, interp: Interp) -> RampKey<f32> {
        RampKey { position, value, interp }
    }

    #[test]
    fn holds_end_values_outside_the_keys() {
        let r = Ramp::new(vec![key(0.8, 1.0, Interp::Linear), key(0.2, 3.0, Interp::Linear)]).unwrap();
        assert_eq!((r.eval(0.0), r.eval(0.2), r.eval(0.8), r.eval(1.0)), (3.0, 3.0, 1.0, 1.0));
        assert_eq!(Ramp::constant(0.5f32).eval(0.7), 0.5);
    }

    #[test]
    fn linear_and_none_interpolate_as_documented() {
        let r = Ramp::new(vec![key(0.0, 1.0, Interp::Linear), key(1.0, 0.2, Interp::Linear)]).unwrap();
        assert!((r.eval(0.25) - 0.8).abs() < 1e-6);
        let r = Ramp::new(vec![key(0.0, 1.0, Interp::None), key(0.5, 0.0, Interp::None)]).unwrap();
        assert_eq!((r.eval(0.49), r.eval(0.5), r.eval(0.9)), (1.0, 0.0, 0.0));
    }

    #[test]
    fn smooth_has_flat_ends_and_passes_the_midpoint() {
        let r = Ramp::new(vec![key(0.0, 0.0, Interp::Smooth), key(1.0, 1.0, Interp::Linear)]).unwrap();
        assert!((r.eval(0.5) - 0.5).abs() < 1e-6);
        // 3t² − 2t³ at t = 0.25: 0.15625.
        assert!((r.eval(0.25) - 0.15625).abs() < 1e-6);
        // Flat at both keys: tiny steps change the value by O(h²).
        assert!(r.eval(1e-3) < 1e-5 && 1.0 - r.eval(1.0 - 1e-3) < 1e-5);
    }

    #[test]
    fn spline_passes_through_keys_and_reproduces_a_line() {
        // Catmull-Rom reproduces linear data exactly, also between unevenly spaced keys.
        let keys = [0.0, 0.3, 0.45, 1.0].map(|x| key(x, 2.0 * x + 1.0, Interp::Spline));
        let r = Ramp::new(keys.to_vec()).unwrap();
        for i in 0..=100 {
            let x = i as f32 / 100.0;
            assert!((r.eval(x) - (2.0 * x + 1.0)).abs() < 1e-5, "{x}: {}", r.eval(x));
        }
        // Through the keys of a curved ramp, and curved (not linear) between them.
        let r = Ramp::new(vec![
            key(0.0, 0.0, Interp::Spline),
            key(0.5, 1.0, Interp::Spline),
            key(1.0, 0.0, Interp::Spline),
        ])
        .unwrap();
        assert_eq!((r.eval(0.0), r.eval(0.5), r.eval(1.0)), (0.0, 1.0, 0.0));
        assert!(r.eval(0.25) > 0.5 + 1e-3, "{}", r.eval(0.25));
    }

    #[test]
    fn colour_ramps_interpolate_per_channel() {
        let r = Ramp::new(vec![
            RampKey { position: 0.0, value: Vec3::new(0.5, 0.0, 1.0), interp: Interp::Linear },
            RampKey { position: 1.0, value: Vec3::new(1.0, 1.0, 0.0), interp: Interp::Linear },
        ])
        .unwrap();
        assert!((r.eval(0.5) - Vec3::new(0.75, 0.5, 0.5)).length() < 1e-6);
    }

    #[test]
    fn bad_keys_are_errors_naming_the_key() {
        assert!(Ramp::<f32>::new(vec![]).is_err());
        let e = Ramp::new(vec![key(0.0, 1.0, Interp::Linear), key(1.5, 1.0, Interp::Linear)]).unwrap_err();
        assert!(e.contains("key 2") && e.contains("1.5"), "{e}");
        let e = Ramp::new(vec![key(f32::NAN, 1.0, Interp::Linear)]).unwrap_err();
        assert!(e.contains("key 1"), "{e}");
        let e = Ramp::new(vec![key(0.0, f32::INFINITY, Interp::Linear)]).unwrap_err();
        assert!(e.contains("finite"), "{e}");
    }
}
