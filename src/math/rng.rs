//! Random numbers that depend only on *what* they are for, never on which thread asks:
//! camera and light samples come from an Owen-scrambled Sobol sequence indexed by
//! (pixel, sample, dimension), so an image is bit-identical whatever the thread count.
//! Scene generation (strands, fur roots) uses a seeded PCG stream per object.

/// A seeded PCG stream for deterministic scene generation.
pub type GenRng = rand_pcg::Pcg32;

/// A 32-bit integer hash (the "lowbias32" finaliser by C. Wellons, hash-prospector),
/// used to derive independent seeds from indices.
#[inline]
pub fn hash_u32(mut x: u32) -> u32 {
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^= x >> 16;
    x
}

/// A hash mapped to [0, 1) (its top 24 bits, exact in an f32).
#[inline]
pub fn unit_float(hash: u32) -> f32 {
    (hash >> 8) as f32 * (1.0 / 16_777_216.0)
}

/// Combines several values into one seed.
#[inline]
pub fn hash_combine(values: &[u32]) -> u32 {
    values.iter().fold(0x9e37_79b9, |h, &v| hash_u32(h ^ v.wrapping_add(0x9e37_79b9)))
}

/// Sample values for one camera sample of one pixel: dimension by dimension, each an
/// Owen-scrambled Sobol value (Burley 2020, "Practical Hash-based Owen Scrambling").
#[derive(Clone, Debug)]
pub struct PixelSampler {
    seed: u32,
    index: u32,
    dimension: u32,
    /// Dimensions `4k..4k + 4` around the current one: they are computed together.
    block: [f32; 4],
}

impl PixelSampler {
    /// The sampler for sample `index` of pixel (`x`, `y`) under the render `seed`.
    pub fn new(seed: u32, x: u32, y: u32, index: u32) -> PixelSampler {
        PixelSampler { seed: hash_combine(&[seed, x, y]), index, dimension: 0, block: [0.0; 4] }
    }

    /// Next value in [0, 1).
    #[inline]
    pub fn next_1d(&mut self) -> f32 {
        let d = self.dimension;
        self.dimension += 1;
        if d.is_multiple_of(4) {
            // The table has 256 dimensions; beyond them, re-seed per block of 256 so deep
            // paths still get independent values. Four dimensions cost about what one does
            // (`sample_4d` gives the values of `sample`, four lanes at once).
            let block = d / sobol_burley::NUM_DIMENSIONS;
            let seed = if block == 0 { self.seed } else { hash_combine(&[self.seed, block]) };
            self.block = sobol_burley::sample_4d(self.index, (d % sobol_burley::NUM_DIMENSIONS) / 4, seed);
        }
        self.block[(d % 4) as usize]
    }

    /// A hash of the sample and its current dimension, without advancing: a seed for
    /// random decisions that need no stratification (stochastic shadow rays), so taking
    /// one leaves the values of the following dimensions as they were.
    #[inline]
    pub fn hash(&self) -> u32 {
        hash_combine(&[self.seed, self.index, self.dimension])
    }

    /// Next two values in [0, 1)^2.
    #[inline]
    pub fn next_2d(&mut self) -> (f32, f32) {
        (self.next_1d(), self.next_1d())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pixel_sampler_gives_the_owen_scrambled_sobol_value_of_each_dimension() {
        // Values come four dimensions at a time; each must still be the scalar sample of
        // its own dimension, past the 256 of the table too (re-seeded per block).
        for (x, y, index) in [(0, 0, 0), (17, 3, 5), (639, 479, 15)] {
            let mut sampler = PixelSampler::new(9, x, y, index);
            let seed = hash_combine(&[9, x, y]);
            for d in 0..600u32 {
                let block = d / sobol_burley::NUM_DIMENSIONS;
                let s = if block == 0 { seed } else { hash_combine(&[seed, block]) };
                let want = sobol_burley::sample(index, d % sobol_burley::NUM_DIMENSIONS, s);
                assert_eq!(sampler.next_1d(), want, "pixel ({x}, {y}), sample {index}, dimension {d}");
            }
        }
    }
}
