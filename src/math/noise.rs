//! Gradient noise: Perlin's improved noise (Perlin 2002, "Improving Noise") as FastNoise
//! Lite computes it, in 2-D (fur attributes and scraggle) and 3-D (hair-system noise).

/// FastNoise Lite's Perlin noise at unit frequency: signed, about [-1, 1].
pub type Perlin = fastnoise_lite::FastNoiseLite;

/// A Perlin noise field seeded by `seed`, one lattice cell per unit.
pub fn perlin(seed: u32) -> Perlin {
    let mut n = Perlin::with_seed(seed as i32);
    n.set_noise_type(Some(fastnoise_lite::NoiseType::Perlin));
    n.set_frequency(Some(1.0));
    n
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn noise_is_zero_on_the_lattice_bounded_smooth_and_seeded() {
        let (a, b) = (perlin(1), perlin(2));
        // Perlin noise vanishes at lattice points, in 2-D and 3-D.
        assert_eq!(a.get_noise_2d(3.0, -2.0), 0.0);
        assert_eq!(a.get_noise_3d(3.0, -2.0, 5.0), 0.0);
        let (mut lo, mut hi, mut max_step, mut differs) = (f32::MAX, f32::MIN, 0.0f32, false);
        for i in 0..2000 {
            let x = i as f32 * 0.0137;
            let v = a.get_noise_3d(x, 0.5 * x + 0.3, 0.7);
            let next = a.get_noise_3d(x + 1e-3, 0.5 * (x + 1e-3) + 0.3, 0.7);
            (lo, hi, max_step) = (lo.min(v), hi.max(v), max_step.max((next - v).abs()));
            differs |= v != b.get_noise_3d(x, 0.5 * x + 0.3, 0.7);
        }
        assert!(lo >= -1.0 && hi <= 1.0 && hi - lo > 0.5, "signed and bounded: {lo}..{hi}");
        assert!(max_step < 0.01, "smooth: {max_step}");
        assert!(differs, "another seed gives another field");
    }
}
