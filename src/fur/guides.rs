//! Attraction of fur toward guide curves: Maya's FurCurveAttractors (specification
//! section 2.5), which the thesis left out (section 2.1.5, "Missing features").
//!
//! Guides are any strand set (a `.hair` file, a hair system's curves). A hair is
//! influenced by the `curves_per_fur` guides whose roots lie nearest its root within
//! `radius`; each pulls with weight `1 - d / radius`. Along the hair, at fraction `s`, the
//! hair point moves toward a target by
//! `w(s) = min(1, Attraction * influence * (1 - d_nearest / radius) * s^power)`:
//! - `local` model (Maya's default): the target is the guides' *shape* carried to the
//!   hair's root and scaled to its length, so fur is combed along the guides. (Maya's Local
//!   model copies a curve's change from its rest shape; a guide file has no rest shape, so
//!   its shape relative to its root stands for that change.)
//! - `global` model: the target is the guide curve itself, so fur grows toward it and
//!   gathers around it (a clumping look).
//! - [`AttractorModel::Interpolate`] (XGen's guides, no Maya Fur model): as `local`, but
//!   each guide's shape keeps its own length, times the hair's Length as a factor, so hairs
//!   among guides of different lengths take a length between theirs (Autodesk's XGen
//!   primitive attributes: under guide control, "Length scales primitive based on the guide
//!   length").
//!
//! `global_scale` multiplies radius, power, influence and the threshold length, as Maya's
//! attractor Global Scale does. Hairs shorter than `threshold_length * global_scale` are
//! not influenced. Maya's Start/End Length window is not modelled.

use crate::geometry::StrandSet;
use glam::Vec3;
use rstar::primitives::GeomWithData;
use rstar::RTree;

/// How fur follows its attractor curves.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum AttractorModel {
    /// Hairs copy the nearest guides' shape from their own root (Maya's default).
    #[default]
    Local,
    /// Hairs grow toward the nearest guides.
    Global,
    /// Hairs take the weighted mean of the nearest guides' shapes from their own root, each
    /// guide at its own length times the hair's Length (a factor here, not a length): XGen's
    /// guide interpolation.
    Interpolate,
}

/// Maya's FurCurveAttractors attributes, with its node defaults.
#[derive(Clone, Debug, PartialEq)]
pub struct Attractors {
    /// Attractor Model (`.camd`).
    pub model: AttractorModel,
    /// Curves Per Fur (`.caph`): how many nearest guides influence each hair, 1 to 3.
    pub curves_per_fur: u32,
    /// Global Scale (`.cgs`).
    pub global_scale: f32,
    /// Radius (`.dcr`): search radius around a hair's root, world units.
    pub radius: f32,
    /// Power (`.dcp`): exponent of the pull along the hair; 0 pulls the whole hair alike.
    pub power: f32,
    /// Influence (`.dci`): strength of the pull.
    pub influence: f32,
    /// Threshold Length (`.dctl`): hairs shorter than this are not influenced.
    pub threshold_length: f32,
}

impl Default for Attractors {
    fn default() -> Self {
        Attractors {
            model: AttractorModel::Local,
            curves_per_fur: 1,
            global_scale: 1.0,
            radius: 1.0,
            power: 1.0,
            influence: 1.0,
            threshold_length: 0.33,
        }
    }
}

impl Attractors {
    /// Checks the values; returns the first problem found.
    pub fn validate(&self) -> Result<(), String> {
        if !(1..=3).contains(&self.curves_per_fur) {
            return Err(format!("`curves_per_fur` = {} is out of range (1 to 3)", self.curves_per_fur));
        }
        for (name, v) in [
            ("global_scale", self.global_scale),
            ("radius", self.radius),
            ("power", self.power),
            ("influence", self.influence),
            ("threshold_length", self.threshold_length),
        ] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(format!("attractor `{name}` = {v} must be finite and >= 0"));
            }
        }
        Ok(())
    }
}

/// Samples per guide after resampling by arc length.
const GUIDE_SAMPLES: usize = 32;

/// Guides ready for lookups: roots in an R*-tree, each curve resampled to
/// [`GUIDE_SAMPLES`] points evenly spaced by arc length.
pub(crate) struct GuideField {
    tree: RTree<GeomWithData<[f32; 3], u32>>,
    samples: Vec<Vec3>,
    lengths: Vec<f32>,
    attractors: Attractors,
}

/// A guide resampled to `GUIDE_SAMPLES` points by arc length, and its length.
fn resample(points: &[Vec3]) -> Option<(Vec<Vec3>, f32)> {
    let mut cumulative = Vec::with_capacity(points.len());
    let mut total = 0.0;
    cumulative.push(0.0);
    for w in points.windows(2) {
        total += (w[1] - w[0]).length();
        cumulative.push(total);
    }
    if !(total > 0.0 && total.is_finite()) {
        return None;
    }
    let mut out = Vec::with_capacity(GUIDE_SAMPLES);
    let mut seg = 0;
    for m in 0..GUIDE_SAMPLES {
        let target = total * m as f32 / (GUIDE_SAMPLES - 1) as f32;
        while seg + 2 < cumulative.len() && cumulative[seg + 1] < target {
            seg += 1;
        }
        let span = cumulative[seg + 1] - cumulative[seg];
        let f = if span > 0.0 { ((target - cumulative[seg]) / span).clamp(0.0, 1.0) } else { 0.0 };
        out.push(points[seg].lerp(points[seg + 1], f));
    }
    Some((out, total))
}

impl GuideField {
    /// Prepares `guides` (strands with fewer than two points or no length are skipped).
    /// Fails when no strand is usable.
    pub fn new(guides: &StrandSet, attractors: &Attractors) -> Result<GuideField, String> {
        attractors.validate()?;
        let (mut roots, mut samples, mut lengths) = (Vec::new(), Vec::new(), Vec::new());
        for w in guides.offsets.windows(2) {
            let points: Vec<Vec3> = (w[0]..w[1]).map(|i| guides.position(i)).collect();
            if let Some((resampled, length)) = resample(&points) {
                roots.push(GeomWithData::new(resampled[0].to_array(), lengths.len() as u32));
                samples.extend(resampled);
                lengths.push(length);
            }
        }
        if lengths.is_empty() {
            return Err("the guides hold no strand with two distinct points".into());
        }
        Ok(GuideField { tree: RTree::bulk_load(roots), samples, lengths, attractors: attractors.clone() })
    }

    /// Guide `g` at fraction `s` of its length.
    fn at(&self, g: u32, s: f32) -> Vec3 {
        let x = s.clamp(0.0, 1.0) * (GUIDE_SAMPLES - 1) as f32;
        let i = (x as usize).min(GUIDE_SAMPLES - 2);
        let base = g as usize * GUIDE_SAMPLES;
        self.samples[base + i].lerp(self.samples[base + i + 1], x - i as f32)
    }

    /// Pulls the hair `points` (root first, `length` long) toward its nearest guides with
    /// strength `attraction`; returns the nearest guide when one is in range.
    pub fn attract(&self, points: &mut [Vec3], length: f32, attraction: f32) -> Option<u32> {
        let a = &self.attractors;
        let gs = a.global_scale;
        let radius = a.radius * gs;
        let root = points[0];
        let mut near = [(0u32, 0.0f32); 3];
        let mut count = 0;
        for g in self.tree.nearest_neighbor_iter(root.to_array()).take(a.curves_per_fur as usize) {
            let d = (Vec3::from(*g.geom()) - root).length();
            if d < radius {
                near[count] = (g.data, 1.0 - d / radius);
                count += 1;
            }
        }
        let near = &near[..count];
        let nearest = near.first()?.0;
        if length < a.threshold_length * gs || attraction <= 0.0 {
            return Some(nearest);
        }
        let weight_sum: f32 = near.iter().map(|n| n.1).sum();
        let strength = attraction * a.influence * gs * near[0].1;
        let power = a.power * gs;
        let last = (points.len() - 1).max(1) as f32;
        for (i, p) in points.iter_mut().enumerate() {
            let s = i as f32 / last;
            let w = (strength * s.powf(power)).min(1.0);
            if w <= 0.0 {
                continue;
            }
            let mut target = Vec3::ZERO;
            for &(g, weight) in near {
                let on_guide = self.at(g, s);
                target += weight
                    * match a.model {
                        AttractorModel::Global => on_guide,
                        AttractorModel::Local => {
                            root + (on_guide - self.at(g, 0.0)) * (length / self.lengths[g as usize])
                        }
                        AttractorModel::Interpolate => root + (on_guide - self.at(g, 0.0)) * length,
                    };
            }
            *p = p.lerp(target / weight_sum, w);
        }
        Some(nearest)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn guide(points: &[Vec3]) -> StrandSet {
        let mut s = StrandSet::new();
        s.push_strand(points.iter().map(|&p| (p, 0.01)));
        s
    }

    #[test]
    fn resampling_is_even_in_arc_length() {
        let (r, len) = resample(&[Vec3::ZERO, Vec3::X, Vec3::new(1.0, 3.0, 0.0)]).unwrap();
        assert!((len - 4.0).abs() < 1e-6);
        assert_eq!(r.len(), GUIDE_SAMPLES);
        let step = 4.0 / (GUIDE_SAMPLES - 1) as f32;
        for w in r.windows(2) {
            assert!(((w[1] - w[0]).length() - step).abs() < 1e-4 || (w[1] - w[0]).length() < step);
        }
        assert!((r[GUIDE_SAMPLES - 1] - Vec3::new(1.0, 3.0, 0.0)).length() < 1e-5);
        assert!(resample(&[Vec3::ONE, Vec3::ONE]).is_none());
    }

    #[test]
    fn local_model_combs_hairs_along_the_guide_and_global_pulls_to_it() {
        // A guide along +x from the origin; a hair standing up along +y from (0, 0, 0.1).
        let g = guide(&[Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0)]);
        let hair = |n: usize| -> Vec<Vec3> { (0..n).map(|i| Vec3::new(0.0, i as f32 / (n - 1) as f32, 0.1)).collect() };
        let at = Attractors { power: 0.0, threshold_length: 0.0, ..Default::default() };
        let field = GuideField::new(&g, &at).unwrap();
        let mut h = hair(5);
        assert_eq!(field.attract(&mut h, 1.0, 1.0), Some(0));
        // Weight 1 - 0.1 / 1 = 0.9 toward root + guide direction * s.
        let target = Vec3::new(1.0, 0.0, 0.1);
        let expected = Vec3::new(0.0, 1.0, 0.1).lerp(target, 0.9);
        assert!((h[4] - expected).length() < 1e-5, "{}", h[4]);
        assert_eq!(h[0], Vec3::new(0.0, 0.0, 0.1), "the root stays put");
        let global = GuideField::new(&g, &Attractors { model: AttractorModel::Global, ..at.clone() }).unwrap();
        let mut h = hair(5);
        global.attract(&mut h, 1.0, 1.0);
        let expected = Vec3::new(0.0, 1.0, 0.1).lerp(Vec3::new(2.0, 0.0, 0.0), 0.9);
        assert!((h[4] - expected).length() < 1e-5, "{}", h[4]);
        // Out of radius, or zero attraction: no change.
        let mut far: Vec<Vec3> = hair(5).into_iter().map(|p| p + Vec3::new(0.0, 0.0, 5.0)).collect();
        let before = far.clone();
        assert_eq!(field.attract(&mut far, 1.0, 1.0), None);
        assert_eq!(far, before);
        let mut h = hair(5);
        field.attract(&mut h, 1.0, 0.0);
        assert_eq!(h, hair(5));
    }

    #[test]
    fn interpolation_keeps_the_guides_lengths_times_the_hair_length() {
        // Guides 1 and 2 long along +x, at z = 0 and z = 1; a hair between them.
        let mut g = guide(&[Vec3::ZERO, Vec3::X]);
        g.push_strand([(Vec3::Z, 0.01), (Vec3::new(2.0, 0.0, 1.0), 0.01)]);
        let at = Attractors {
            model: AttractorModel::Interpolate,
            curves_per_fur: 2,
            radius: 2.0,
            power: 0.0,
            influence: 1e9,
            threshold_length: 0.0,
            ..Default::default()
        };
        let field = GuideField::new(&g, &at).unwrap();
        let root = Vec3::new(0.0, 0.0, 0.5);
        let mut h: Vec<Vec3> = (0..5).map(|i| root + Vec3::Y * (i as f32 / 4.0)).collect();
        field.attract(&mut h, 0.5, 1.0);
        // Equal weights: the mean of 1 and 2, times the hair's Length 0.5, and a straight
        // hair along the guides' direction.
        assert!((h[4] - (root + Vec3::new(0.75, 0.0, 0.0))).length() < 1e-5, "{}", h[4]);
        assert!((h[2] - (root + Vec3::new(0.375, 0.0, 0.0))).length() < 1e-5, "{}", h[2]);
    }

    #[test]
    fn power_spares_the_base_and_threshold_spares_short_hair() {
        let g = guide(&[Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0)]);
        let field = GuideField::new(&g, &Attractors { power: 2.0, ..Default::default() }).unwrap();
        let mut h: Vec<Vec3> = (0..5).map(|i| Vec3::new(0.0, i as f32 / 4.0, 0.0)).collect();
        let before = h.clone();
        field.attract(&mut h, 1.0, 1.0);
        let moved: Vec<f32> = h.iter().zip(&before).map(|(a, b)| (*a - *b).length()).collect();
        assert!(moved[0] == 0.0 && moved[1] < moved[2] && moved[2] < moved[4], "{moved:?}");
        // Default threshold 0.33: a 0.2-long hair is left alone.
        let mut short: Vec<Vec3> = (0..5).map(|i| Vec3::new(0.0, 0.05 * i as f32, 0.0)).collect();
        let before = short.clone();
        field.attract(&mut short, 0.2, 1.0);
        assert_eq!(short, before);
    }

    #[test]
    fn bad_guides_and_attractors_are_errors() {
        let empty = StrandSet::new();
        assert!(GuideField::new(&empty, &Attractors::default()).is_err());
        let g = guide(&[Vec3::ZERO, Vec3::X]);
        let e = GuideField::new(&g, &Attractors { curves_per_fur: 4, ..Default::default() }).err().unwrap();
        assert!(e.contains("curves_per_fur"), "{e}");
        let e = GuideField::new(&g, &Attractors { radius: f32::NAN, ..Default::default() }).err().unwrap();
        assert!(e.contains("radius"), "{e}");
    }
}
