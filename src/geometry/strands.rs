//! `StrandSet`: hair strands as flat arrays (structure of arrays).
//!
//! A strand is a chain of control points; a segment joins point `i` to point `i + 1` of the
//! same strand and needs no record of its own: it is named by the index of its first point.
//! A point is 16 bytes (`x, y, z, radius`), against the thesis' 82 bytes per segment
//! (section 2.1.7). Tangents are derived at the points when shading (thesis fig. 2.2).

use glam::Vec3;

/// A set of hair strands sharing one material.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct StrandSet {
    /// Control points: position and radius (half the thickness).
    pub points: Vec<[f32; 4]>,
    /// Strand `i` owns `points[offsets[i]..offsets[i + 1]]`; `offsets.len()` is strands + 1.
    pub offsets: Vec<u32>,
    /// Optional linear RGB colour per point.
    pub colors: Option<Vec<[f32; 3]>>,
    /// Optional opacity per point (1 = opaque).
    pub opacity: Option<Vec<f32>>,
    /// Optional per-strand data from the generator (fur, hair systems).
    pub strand_info: Option<StrandInfo>,
}

/// Per-strand data a generator knows and shading or AOVs may use; each array has one
/// entry per strand. A stable per-strand random value needs no storage: hash the strand
/// index with [`crate::math::rng::hash_u32`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct StrandInfo {
    /// UV of the strand's root on the surface it grows from.
    pub root_uv: Vec<[f32; 2]>,
    /// Clump (or guide) each strand belongs to.
    pub clump: Vec<u32>,
}

/// What is known about a point on a strand, for shading and the AOVs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StrandPoint {
    /// Strand index in its set.
    pub strand: u32,
    /// Position along the strand: 0 at the root, 1 at the tip, by point index (arc length
    /// for evenly spaced points).
    pub along: f32,
    /// Root UV on the surface the strand grows from, when its generator knows it.
    pub root_uv: Option<[f32; 2]>,
    /// Clump (guide) index, when its generator knows it.
    pub clump: Option<u32>,
    /// A stable random value in [0, 1) per strand: `unit_float(hash_u32(strand))`.
    pub random: f32,
}

impl StrandSet {
    /// An empty set.
    pub fn new() -> StrandSet {
        StrandSet { offsets: vec![0], ..Default::default() }
    }

    /// Appends a strand given as (position, radius) points.
    pub fn push_strand(&mut self, points: impl IntoIterator<Item = (Vec3, f32)>) {
        if self.offsets.is_empty() {
            self.offsets.push(0);
        }
        self.points.extend(points.into_iter().map(|(p, r)| [p.x, p.y, p.z, r]));
        self.offsets.push(self.points.len() as u32);
    }

    /// Number of strands.
    pub fn strand_count(&self) -> usize {
        self.offsets.len().saturating_sub(1)
    }

    /// Number of segments (points minus one, per strand with at least two points).
    pub fn segment_count(&self) -> usize {
        self.offsets.windows(2).map(|w| (w[1] - w[0]).saturating_sub(1) as usize).sum()
    }

    /// The first-point index of every segment, in strand order.
    pub fn segment_starts(&self) -> Vec<u32> {
        let mut out = Vec::with_capacity(self.segment_count());
        for w in self.offsets.windows(2) {
            if w[1] > w[0] + 1 {
                out.extend(w[0]..w[1] - 1);
            }
        }
        out
    }

    /// Position of point `i`.
    #[inline]
    pub fn position(&self, i: u32) -> Vec3 {
        let p = self.points[i as usize];
        Vec3::new(p[0], p[1], p[2])
    }

    /// The strand that owns point `i`.
    pub fn strand_of(&self, i: u32) -> u32 {
        (self.offsets.partition_point(|&o| o <= i) - 1) as u32
    }

    /// Unit tangent at point `i` by central differences inside the strand, one-sided at
    /// its ends (thesis fig. 2.2). Falls back to the nearest non-degenerate difference.
    pub fn point_tangent(&self, i: u32) -> Vec3 {
        self.tangent_in(i, self.strand_of(i) as usize)
    }

    /// [`StrandSet::point_tangent`] of point `i` of strand `strand`.
    fn tangent_in(&self, i: u32, strand: usize) -> Vec3 {
        let (first, last) = (self.offsets[strand], self.offsets[strand + 1] - 1);
        let prev = self.position(i.saturating_sub(1).max(first));
        let next = self.position((i + 1).min(last));
        (next - prev).try_normalize().unwrap_or(Vec3::Y)
    }

    /// Shading tangent at parameter `s` in [0, 1] along the segment starting at point `i`:
    /// the point tangents interpolated, so shading is smooth across segment joints.
    pub fn tangent(&self, i: u32, s: f32) -> Vec3 {
        self.tangent_on(i, s, self.strand_of(i))
    }

    /// [`StrandSet::tangent`] when the caller knows the strand that owns point `i` (from
    /// [`StrandSet::strand_point`]), sparing the search for it.
    pub fn tangent_on(&self, i: u32, s: f32, strand: u32) -> Vec3 {
        let strand = strand as usize;
        let t0 = self.tangent_in(i, strand);
        let t1 = self.tangent_in(i + 1, strand);
        t0.lerp(t1, s).try_normalize().unwrap_or(t0)
    }

    /// What is known at parameter `s` along the segment starting at point `i`.
    pub fn strand_point(&self, i: u32, s: f32) -> StrandPoint {
        let strand = self.strand_of(i);
        let (first, end) = (self.offsets[strand as usize], self.offsets[strand as usize + 1]);
        let segments = end.saturating_sub(first + 1).max(1) as f32;
        let info = self.strand_info.as_ref();
        StrandPoint {
            strand,
            along: ((i - first) as f32 + s) / segments,
            root_uv: info.and_then(|n| n.root_uv.get(strand as usize).copied()),
            clump: info.and_then(|n| n.clump.get(strand as usize).copied()),
            random: crate::math::rng::unit_float(crate::math::rng::hash_u32(strand)),
        }
    }

    /// Colour at parameter `s` along segment `i`, if the set has colours.
    pub fn color(&self, i: u32, s: f32) -> Option<Vec3> {
        self.colors.as_ref().map(|c| Vec3::from(c[i as usize]).lerp(Vec3::from(c[i as usize + 1]), s))
    }

    /// Opacity at parameter `s` along segment `i` (1 when the set has none).
    pub fn opacity_at(&self, i: u32, s: f32) -> f32 {
        self.opacity.as_ref().map_or(1.0, |o| o[i as usize] + (o[i as usize + 1] - o[i as usize]) * s)
    }

    /// Bytes held by the arrays of this set.
    pub fn memory_bytes(&self) -> usize {
        self.points.len() * 16
            + self.offsets.len() * 4
            + self.colors.as_ref().map_or(0, |c| c.len() * 12)
            + self.opacity.as_ref().map_or(0, |o| o.len() * 4)
            + self.strand_info.as_ref().map_or(0, |i| i.root_uv.len() * 8 + i.clump.len() * 4)
    }

    /// Appends every strand of `other`. Colours, opacities and strand info are kept only
    /// when both sets have them (a set without them gets none).
    pub fn append(&mut self, other: &StrandSet) {
        let base = self.points.len() as u32;
        let had_points = !self.points.is_empty();
        self.colors = match (self.colors.take(), &other.colors) {
            (Some(mut a), Some(b)) => {
                a.extend_from_slice(b);
                Some(a)
            }
            (None, Some(b)) if !had_points => Some(b.clone()),
            _ => None,
        };
        self.opacity = match (self.opacity.take(), &other.opacity) {
            (Some(mut a), Some(b)) => {
                a.extend_from_slice(b);
                Some(a)
            }
            (None, Some(b)) if !had_points => Some(b.clone()),
            _ => None,
        };
        self.strand_info = match (self.strand_info.take(), &other.strand_info) {
            (Some(mut a), Some(b)) => {
                a.root_uv.extend_from_slice(&b.root_uv);
                a.clump.extend_from_slice(&b.clump);
                Some(a)
            }
            (None, Some(b)) if !had_points => Some(b.clone()),
            _ => None,
        };
        self.points.extend_from_slice(&other.points);
        if self.offsets.is_empty() {
            self.offsets.push(0);
        }
        self.offsets.extend(other.offsets.iter().skip(1).map(|o| o + base));
    }

    /// Removes the strands that cannot be rendered: a coordinate or radius that is not
    /// finite or beyond [`super::MAX_COORDINATE`], or a negative radius (from a transform
    /// past the float range, or a generator's NaN); such numbers would poison BVH bounds and
    /// intersections. Returns how many.
    pub fn remove_unusable_strands(&mut self) -> usize {
        // Written so that NaN fails every comparison.
        let usable = |p: &[f32; 4]| {
            p[..3].iter().all(|c| c.abs() <= super::MAX_COORDINATE) && (0.0..=super::MAX_COORDINATE).contains(&p[3])
        };
        let keep: Vec<bool> =
            self.offsets.windows(2).map(|w| self.points[w[0] as usize..w[1] as usize].iter().all(usable)).collect();
        let removed = keep.iter().filter(|k| !**k).count();
        if removed == 0 {
            return 0;
        }
        let mut out = StrandSet::new();
        for (w, _) in self.offsets.windows(2).zip(&keep).filter(|(_, k)| **k) {
            out.points.extend_from_slice(&self.points[w[0] as usize..w[1] as usize]);
            out.offsets.push(out.points.len() as u32);
        }
        // Per-point arrays keep the points of kept strands; per-strand arrays the kept strands.
        fn kept_points<T: Copy>(offsets: &[u32], keep: &[bool], all: &[T]) -> Vec<T> {
            offsets
                .windows(2)
                .zip(keep)
                .filter(|(_, k)| **k)
                .flat_map(|(w, _)| all[w[0] as usize..w[1] as usize].iter().copied())
                .collect()
        }
        fn kept<T: Copy>(keep: &[bool], all: &[T]) -> Vec<T> {
            all.iter().zip(keep).filter(|(_, k)| **k).map(|(x, _)| *x).collect()
        }
        out.colors = self.colors.as_ref().map(|c| kept_points(&self.offsets, &keep, c));
        out.opacity = self.opacity.as_ref().map(|o| kept_points(&self.offsets, &keep, o));
        out.strand_info = self
            .strand_info
            .as_ref()
            .map(|info| StrandInfo { root_uv: kept(&keep, &info.root_uv), clump: kept(&keep, &info.clump) });
        *self = out;
        removed
    }

    /// Applies an affine transform to positions; radii scale by the cube root of the
    /// determinant (the mean scale), so a uniformly scaled strand keeps its proportions.
    pub fn transform(&mut self, m: &glam::Affine3A) {
        let scale = m.matrix3.determinant().abs().cbrt();
        for p in &mut self.points {
            let q = m.transform_point3(Vec3::new(p[0], p[1], p[2]));
            *p = [q.x, q.y, q.z, p[3] * scale];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn set(n: usize, color: Option<[f32; 3]>) -> StrandSet {
        let mut s = StrandSet::new();
        for k in 0..n {
            s.push_strand((0..3).map(|i| (Vec3::new(k as f32, i as f32, 0.0), 0.1)));
        }
        s.colors = color.map(|c| vec![c; s.points.len()]);
        s
    }

    #[test]
    fn counts_segments_and_finds_strands() {
        let mut s = set(2, None);
        s.push_strand([(Vec3::ZERO, 0.1)]); // a single point: a strand without segments
        assert_eq!((s.strand_count(), s.segment_count()), (3, 4));
        assert_eq!(s.segment_starts(), vec![0, 1, 3, 4]);
        assert_eq!((s.strand_of(2), s.strand_of(3), s.strand_of(6)), (0, 1, 2));
    }

    #[test]
    fn along_counts_segments_from_root_to_tip() {
        let mut s = set(1, None); // 3 points: 2 segments
        s.push_strand((0..5).map(|i| (Vec3::new(0.0, i as f32, 0.0), 0.1)));
        let at = |i, t| {
            let p = s.strand_point(i, t);
            (p.strand, p.along)
        };
        assert_eq!(at(0, 0.0), (0, 0.0));
        assert_eq!(at(1, 1.0), (0, 1.0));
        assert_eq!(at(4, 0.5), (1, 0.375));
    }

    #[test]
    fn tangents_are_central_differences_and_one_sided_at_ends() {
        let mut s = StrandSet::new();
        s.push_strand([(Vec3::ZERO, 0.1), (Vec3::X, 0.1), (Vec3::new(1.0, 1.0, 0.0), 0.1)]);
        assert!((s.point_tangent(0) - Vec3::X).length() < 1e-6);
        assert!((s.point_tangent(1) - Vec3::new(1.0, 1.0, 0.0).normalize()).length() < 1e-6);
        assert!((s.point_tangent(2) - Vec3::Y).length() < 1e-6);
        // Interpolated along a segment, normalised.
        let mid = s.tangent(0, 0.5);
        assert!((mid.length() - 1.0).abs() < 1e-6 && mid.x > mid.y && mid.y > 0.0);
    }

    #[test]
    fn strand_points_know_position_along_and_generator_data() {
        let mut s = set(3, None);
        let p = s.strand_point(4, 0.5);
        assert_eq!((p.strand, p.along, p.root_uv, p.clump), (1, 0.75, None, None));
        assert_eq!(p.random, crate::math::rng::unit_float(crate::math::rng::hash_u32(1)));
        assert!((0.0..1.0).contains(&p.random) && p.random != s.strand_point(0, 0.0).random);
        s.strand_info = Some(StrandInfo { root_uv: vec![[0.1, 0.2], [0.3, 0.4], [0.5, 0.6]], clump: vec![0, 0, 1] });
        let p = s.strand_point(6, 0.0);
        assert_eq!((p.strand, p.along, p.root_uv, p.clump), (2, 0.0, Some([0.5, 0.6]), Some(1)));
    }

    #[test]
    fn unusable_strands_are_removed_with_their_data() {
        let mut s = set(4, Some([0.5; 3]));
        s.opacity = Some((0..12).map(|i| i as f32 / 12.0).collect());
        s.strand_info =
            Some(StrandInfo { root_uv: (0..4).map(|i| [i as f32, 0.0]).collect(), clump: vec![0, 1, 2, 3] });
        s.points[4][1] = f32::NAN; // strand 1
        s.points[9][3] = -1.0; // strand 3
        assert_eq!(s.remove_unusable_strands(), 2);
        assert_eq!(s.offsets, vec![0, 3, 6]);
        assert_eq!(s.points[3][0], 2.0, "strand 2 moved into second place");
        assert_eq!(s.opacity.as_ref().unwrap()[3], 6.0 / 12.0);
        assert_eq!(s.colors.as_ref().unwrap().len(), 6);
        assert_eq!(s.strand_info.as_ref().unwrap().clump, vec![0, 2]);
        assert_eq!(s.remove_unusable_strands(), 0);
    }

    #[test]
    fn append_keeps_offsets_and_drops_colours_missing_on_one_side() {
        let mut a = set(2, Some([1.0, 0.0, 0.0]));
        a.append(&set(1, Some([0.0, 1.0, 0.0])));
        assert_eq!(a.offsets, vec![0, 3, 6, 9]);
        assert_eq!(a.colors.as_ref().unwrap()[8], [0.0, 1.0, 0.0]);
        a.append(&set(1, None));
        assert_eq!((a.strand_count(), a.colors), (4, None));
        let mut empty = StrandSet::new();
        empty.append(&set(1, Some([0.5; 3])));
        assert!(empty.colors.is_some());
    }
}
