//! `StrandSet`: hair strands as flat arrays (structure of arrays).
//!
//! A strand is a chain of control points; a segment joins point `i` to point `i + 1` of the
//! same strand and needs no record of its own: it is named by the index of its first point.
//! A point is 16 bytes (`x, y, z, radius`), against the thesis' 82 bytes per segment
//! (section 2.1.7). Tangents are derived at the points when shading (thesis fig. 2.2).
//!
//! A set may be stored in another order than its file's ([`StrandSet::reorder_spatially`]:
//! along a Morton curve, for the memory locality of BVH leaves). Whatever must not depend
//! on that order (per-strand random values, the `strandId` AOV, per-strand material
//! arrays) sees the file's strand index, [`StrandSet::file_strand`], which
//! [`StrandSet::strand_point`] reports.

use glam::Vec3;
use rayon::prelude::*;

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
    /// The file's index of each stored strand when the set is stored in another order
    /// ([`StrandSet::reorder_spatially`]); `None` in the file's order. Read it through
    /// [`StrandSet::file_strand`].
    pub file_order: Option<Vec<u32>>,
}

/// Per-strand data a generator knows and shading or AOVs may use; each array has one
/// entry per strand, in the set's storage order. A stable per-strand random value needs no
/// storage: hash the strand's file index ([`StrandSet::file_strand`]) with
/// [`crate::math::rng::hash_u32`].
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
    /// Strand index in its set as the file (or generator) numbers it, whatever order the
    /// set is stored in ([`StrandSet::file_strand`]).
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
        // A reordered set numbers a new strand after the file's last.
        if let Some(order) = &mut self.file_order {
            order.push(order.len() as u32);
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

    /// The strand that owns point `i` (its index in storage order).
    pub fn strand_of(&self, i: u32) -> u32 {
        (self.offsets.partition_point(|&o| o <= i) - 1) as u32
    }

    /// The file's index of stored strand `strand`: itself unless the set was reordered.
    #[inline]
    pub fn file_strand(&self, strand: u32) -> u32 {
        self.file_order.as_ref().map_or(strand, |order| order[strand as usize])
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
        self.tangent_on(i, s, self.strand_of(i) as usize)
    }

    /// [`StrandSet::tangent`] of point `i` of stored strand `strand`.
    fn tangent_on(&self, i: u32, s: f32, strand: usize) -> Vec3 {
        let t0 = self.tangent_in(i, strand);
        let t1 = self.tangent_in(i + 1, strand);
        t0.lerp(t1, s).try_normalize().unwrap_or(t0)
    }

    /// What is known at parameter `s` along the segment starting at point `i`.
    pub fn strand_point(&self, i: u32, s: f32) -> StrandPoint {
        self.strand_point_on(i, s, self.strand_of(i) as usize)
    }

    /// [`StrandSet::strand_point`] and [`StrandSet::tangent`] at once, with one search for
    /// the strand: what shading a hit needs.
    pub fn hit_point(&self, i: u32, s: f32) -> (StrandPoint, Vec3) {
        let strand = self.strand_of(i) as usize;
        (self.strand_point_on(i, s, strand), self.tangent_on(i, s, strand))
    }

    /// [`StrandSet::strand_point`] of point `i` of stored strand `strand`: per-strand
    /// arrays are read in storage order, the strand index and its random value are the
    /// file's.
    fn strand_point_on(&self, i: u32, s: f32, strand: usize) -> StrandPoint {
        let (first, end) = (self.offsets[strand], self.offsets[strand + 1]);
        let segments = end.saturating_sub(first + 1).max(1) as f32;
        let info = self.strand_info.as_ref();
        let file = self.file_strand(strand as u32);
        StrandPoint {
            strand: file,
            along: ((i - first) as f32 + s) / segments,
            root_uv: info.and_then(|n| n.root_uv.get(strand).copied()),
            clump: info.and_then(|n| n.clump.get(strand).copied()),
            random: crate::math::rng::unit_float(crate::math::rng::hash_u32(file)),
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
            + self.file_order.as_ref().map_or(0, |f| f.len() * 4)
    }

    /// Appends every strand of `other`. Colours, opacities and strand info are kept only
    /// when both sets have them (a set without them gets none).
    /// When either set is reordered, the file order of the result is this set's followed
    /// by `other`'s.
    pub fn append(&mut self, other: &StrandSet) {
        let base = self.points.len() as u32;
        let had_points = !self.points.is_empty();
        if self.file_order.is_some() || other.file_order.is_some() {
            let n = self.strand_count() as u32;
            let mut order = self.file_order.take().unwrap_or_else(|| (0..n).collect());
            order.extend((0..other.strand_count() as u32).map(|i| n + other.file_strand(i)));
            self.file_order = Some(order);
        }
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
    /// intersections. Returns how many. The kept strands of a reordered set are numbered as
    /// a file without the removed ones would number them.
    pub fn remove_unusable_strands(&mut self) -> usize {
        // Written so that NaN fails every comparison.
        let usable = |p: &[f32; 4]| {
            p[..3].iter().all(|c| c.abs() <= super::MAX_COORDINATE) && (0.0..=super::MAX_COORDINATE).contains(&p[3])
        };
        let keep: Vec<u32> =
            (0..self.strand_count() as u32).filter(|&i| self.points[self.point_range(i)].iter().all(usable)).collect();
        let removed = self.strand_count() - keep.len();
        if removed == 0 {
            return 0;
        }
        let mut out = self.select(&keep);
        out.file_order = self.file_order.as_ref().map(|_| {
            let files: Vec<u32> = keep.iter().map(|&i| self.file_strand(i)).collect();
            let mut sorted = files.clone();
            sorted.sort_unstable();
            // A kept strand's new file index: how many kept strands come before it in the file.
            files.iter().map(|f| sorted.partition_point(|x| x < f) as u32).collect()
        });
        *self = out;
        removed
    }

    /// Stores the strands along a Morton (Z-order) curve through the centres of their
    /// bounding boxes (Morton 1966; the order Karras 2012, "Maximizing Parallelism in the
    /// Construction of BVHs, Octrees, and k-d Trees", section 4, sorts BVH primitives in),
    /// so strands near in space lie near in memory: the points a BVH leaf or a bundle of
    /// rays reads share pages and prefetched lines (docs/performance.md, "Strands in
    /// spatial order"). Points, colours, opacities and strand info move with their strands;
    /// [`StrandSet::file_order`] keeps each strand's file index. The order depends on the
    /// strands alone (ties broken by file index): the same for any thread count, and a
    /// second reorder changes nothing.
    ///
    /// Point indices change: what hashes them (level of detail's segment jitter, the
    /// stochastic transparency draws of `accel::layers`) would draw other values, so only
    /// sets without those are reordered (`scene::prepare`).
    pub fn reorder_spatially(&mut self) {
        let n = self.strand_count();
        if n < 2 {
            return;
        }
        // In parallel: this runs inside the timed BVH build.
        let centres: Vec<Vec3> = (0..n as u32)
            .into_par_iter()
            .map(|i| {
                let (lo, hi) = self.points[self.point_range(i)].iter().fold(
                    (Vec3::INFINITY, Vec3::NEG_INFINITY),
                    |(lo, hi), p| {
                        let q = Vec3::new(p[0], p[1], p[2]);
                        (lo.min(q), hi.max(q))
                    },
                );
                (lo + hi) * 0.5
            })
            .collect();
        // The grid spans the finite centres (a strand without points has a NaN centre,
        // which the saturating casts below put in cell 0).
        let (lo, hi) = centres
            .iter()
            .filter(|c| c.is_finite())
            .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), &c| (lo.min(c), hi.max(c)));
        let cells = f32::from(u16::MAX);
        let scale = (hi - lo).map(|e| if e > 0.0 { cells / e } else { 0.0 });
        let code = |c: Vec3| {
            // Saturating float casts: every centre lands in the grid.
            let q = ((c - lo) * scale).to_array().map(|x| x as u16);
            zorder::index_of(q)
        };
        let mut order: Vec<(u64, u32, u32)> =
            centres.par_iter().enumerate().map(|(i, &c)| (code(c), self.file_strand(i as u32), i as u32)).collect();
        // The keys are distinct (file indices are), so an unstable sort is deterministic.
        order.par_sort_unstable();
        let stored: Vec<u32> = order.iter().map(|o| o.2).collect();
        let mut out = self.select(&stored);
        out.file_order = Some(order.iter().map(|o| o.1).collect());
        *self = out;
    }

    /// Points of stored strand `strand`.
    fn point_range(&self, strand: u32) -> std::ops::Range<usize> {
        self.offsets[strand as usize] as usize..self.offsets[strand as usize + 1] as usize
    }

    /// The stored strands `strands`, in that order, with their per-point and per-strand
    /// data (not their file order, which the caller sets).
    fn select(&self, strands: &[u32]) -> StrandSet {
        // In parallel (the spatial reorder runs inside the timed build); the collected
        // order is the strands' order.
        fn per_point<T: Copy + Send + Sync>(set: &StrandSet, strands: &[u32], all: &[T]) -> Vec<T> {
            strands.par_iter().flat_map_iter(|&i| all[set.point_range(i)].iter().copied()).collect()
        }
        // Per-strand arrays should have an entry per strand; a short one stays short.
        fn per_strand<T: Copy>(strands: &[u32], all: &[T]) -> Vec<T> {
            strands.iter().filter_map(|&i| all.get(i as usize).copied()).collect()
        }
        let mut out = StrandSet::new();
        out.points = per_point(self, strands, &self.points);
        out.offsets.extend(strands.iter().scan(0, |end, &i| {
            *end += self.point_range(i).len() as u32;
            Some(*end)
        }));
        out.colors = self.colors.as_ref().map(|c| per_point(self, strands, c));
        out.opacity = self.opacity.as_ref().map(|o| per_point(self, strands, o));
        out.strand_info = self.strand_info.as_ref().map(|info| StrandInfo {
            root_uv: per_strand(strands, &info.root_uv),
            clump: per_strand(strands, &info.clump),
        });
        out
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

    /// The box around the points (their centres, radii left out) placed by `m`.
    pub fn bounds_under(&self, m: &glam::Affine3A) -> crate::math::Aabb {
        (self.points.iter())
            .fold(crate::math::Aabb::EMPTY, |b, p| b.grow(m.transform_point3(Vec3::new(p[0], p[1], p[2])).into()))
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

    /// Strands of 0 to 5 points scattered in a box, in random file order, with every
    /// per-point and per-strand array.
    fn scattered(n: usize, seed: u64) -> StrandSet {
        use rand::{Rng, SeedableRng};
        let mut rng = crate::math::rng::GenRng::seed_from_u64(seed);
        let mut s = StrandSet::new();
        for _ in 0..n {
            let root = Vec3::new(rng.random(), rng.random(), rng.random()) * 10.0;
            let count = rng.random_range(0..6);
            s.push_strand((0..count).map(|i| (root + Vec3::Y * i as f32 * 0.1, 0.01 + i as f32 * 1e-3)));
        }
        let points = s.points.len();
        s.colors = Some((0..points).map(|i| [i as f32, 0.5, 0.25]).collect());
        s.opacity = Some((0..points).map(|i| i as f32 / points as f32).collect());
        s.strand_info =
            Some(StrandInfo { root_uv: (0..n).map(|i| [i as f32, 1.0]).collect(), clump: (0..n as u32).collect() });
        s
    }

    /// Each strand with its data, listed by file index: what must not depend on the order
    /// a set is stored in.
    #[allow(clippy::type_complexity)]
    fn by_file(s: &StrandSet) -> Vec<(Vec<[f32; 4]>, Vec<[f32; 3]>, Vec<f32>, [f32; 2], u32)> {
        let mut out = vec![Default::default(); s.strand_count()];
        for i in 0..s.strand_count() as u32 {
            let r = s.point_range(i);
            let info = s.strand_info.as_ref().unwrap();
            out[s.file_strand(i) as usize] = (
                s.points[r.clone()].to_vec(),
                s.colors.as_ref().unwrap()[r.clone()].to_vec(),
                s.opacity.as_ref().unwrap()[r].to_vec(),
                info.root_uv[i as usize],
                info.clump[i as usize],
            );
        }
        out
    }

    #[test]
    fn spatial_order_is_a_permutation_that_keeps_each_strand_with_its_data_and_file_index() {
        let file = scattered(500, 1);
        let mut s = file.clone();
        s.reorder_spatially();
        let order = s.file_order.clone().unwrap();
        let mut sorted = order.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..500).collect::<Vec<u32>>(), "a permutation");
        assert_ne!(order, sorted, "the order changed");
        assert_eq!(by_file(&s), by_file(&file));
        assert_eq!((s.points.len(), s.segment_count()), (file.points.len(), file.segment_count()));
        assert_eq!(s.memory_bytes(), file.memory_bytes() + 500 * 4);
        // What shading and the AOVs see at a hit: the file's strand index, its random value,
        // the place along it and the tangent, as on the set in file order.
        for k in 0..500 {
            let f = s.file_strand(k);
            let (stored, original) = (s.point_range(k), file.point_range(f));
            for (i, j) in stored.zip(original).take(s.point_range(k).len().saturating_sub(1)) {
                let (at, tangent) = s.hit_point(i as u32, 0.25);
                assert_eq!((at, tangent), file.hit_point(j as u32, 0.25));
                assert_eq!(at.strand, f);
                assert_eq!(s.color(i as u32, 0.5), file.color(j as u32, 0.5));
            }
        }
    }

    #[test]
    fn spatial_order_depends_on_positions_alone_and_brings_neighbours_together() {
        let mut a = scattered(400, 2);
        let centre = |s: &StrandSet, k: u32| s.points[s.point_range(k)].first().map(|p| Vec3::new(p[0], p[1], p[2]));
        let path = |s: &StrandSet| -> f32 {
            let c: Vec<Vec3> = (0..s.strand_count() as u32).filter_map(|k| centre(s, k)).collect();
            c.windows(2).map(|w| w[0].distance(w[1])).sum()
        };
        let before = path(&a);
        a.reorder_spatially();
        // A Morton path through 400 random points in a 10^3 box is several times shorter
        // than a random tour (mean step about 6.6).
        assert!(path(&a) < before / 3.0, "{} against {before}", path(&a));
        let again = {
            let mut b = a.clone();
            b.reorder_spatially();
            b
        };
        assert!(again == a, "a second reorder changes nothing");
        // The same strands listed in reverse file order are stored alike (their file
        // indices aside).
        let mut reversed = StrandSet::new();
        let file = scattered(400, 2);
        for k in (0..400).rev() {
            reversed.push_strand(file.points[file.point_range(k)].iter().map(|p| (Vec3::new(p[0], p[1], p[2]), p[3])));
        }
        reversed.reorder_spatially();
        // Strands without points sort first, in file order, and carry no position.
        assert_eq!(reversed.points, a.points);
    }

    #[test]
    fn reordered_sets_keep_file_indices_when_strands_are_added_or_removed() {
        let reordered = |mut s: StrandSet| {
            s.reorder_spatially();
            s
        };
        // Appending: the file order is this set's, then the other's.
        let (a, b) = (scattered(50, 3), scattered(30, 4));
        let mut joined = a.clone();
        joined.append(&b);
        let mut both = reordered(a.clone());
        both.append(&reordered(b.clone()));
        assert_eq!(by_file(&both), by_file(&joined));
        let mut first = a.clone();
        first.append(&reordered(b));
        assert_eq!(by_file(&first), by_file(&joined));
        // A pushed strand is numbered after the last.
        let mut pushed = reordered(a.clone());
        pushed.push_strand([(Vec3::ONE, 0.1), (Vec3::X, 0.1)]);
        assert_eq!(pushed.file_strand(50), 50);
        // Removing strands numbers the kept ones as the file without them would.
        let mut broken = a;
        for k in [3, 17, 40] {
            let r = broken.point_range(k);
            if let Some(p) = broken.points[r].first_mut() {
                p[0] = f32::NAN;
            }
        }
        let mut file_removed = broken.clone();
        let mut moved = reordered(broken);
        assert_eq!(moved.remove_unusable_strands(), file_removed.remove_unusable_strands());
        assert_eq!(by_file(&moved), by_file(&file_removed));
    }
}
