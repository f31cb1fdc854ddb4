//! Level of detail for strand sets: stochastic pruning (Cook, Halstead, Planck and Ryu 2007,
//! "Stochastic Simplification of Aggregate Detail"; thesis section 2.2) with the level chosen
//! per ray from its cone at the distance where it meets the hair.
//!
//! The thesis built eight grids, one per level, and re-shot each ray level by level; it
//! could handle one hair thickness per scene (section 2.2.2). Here the level is found
//! during the one traversal, so several hair thicknesses share a scene:
//! - each strand gets a random pruning rank; level `l` keeps the `ceil(N / d^l)` strands of
//!   lowest rank, so the levels are nested;
//! - the nested sets split into disjoint groups: group `k` holds the strands whose last
//!   level is exactly `k`. All segments stay in ONE BVH, each item id carrying its group in
//!   its low bits ([`StrandLod::item_id`]), each bounded with the radius it takes at its
//!   group's level. There is no copy of the geometry and a ray traverses once;
//! - a ray's level at distance `t` on a segment is `floor(log_d(footprint(t) / width) +
//!   jitter)` ([`StrandLod::level_at`]), the jitter being the segment's own
//!   ([`StrandLod::segment_jitter`]), so a segment of group `k` is visible only before the
//!   distance `t_k` where that level passes `k`. A leaf drops the segments that lie wholly
//!   beyond their `t_k` before the exact segment test, and a hit beyond `t_k` does not count;
//!   no ray is re-shot;
//! - a segment met at distance `t` is intersected with its radius widened for the level at
//!   `t` ([`LodParams::radius_scale`]);
//! - given the camera ([`LodCamera`]), no segment is drawn coarser than the camera sees
//!   it, so its box is widened only that far: near fur keeps tight boxes, where bounding
//!   every segment for its coarsest level made near rays 2 times slower than without LOD;
//! - optionally, coarse levels skip every other point of a strand ([`LodParams::simplify`]).
//!
//! Each strand set measures its own width, so several hair thicknesses in one scene each
//! pick their own level. The jitter belongs to the segment, not to the ray: transitions
//! dither from segment to segment instead of showing a seam, and a segment changes level
//! only when its footprint crosses its own threshold, so a moving camera does not re-draw
//! every ray's level each frame (a per-ray jitter made the far fur flicker: measured with
//! `examples/lod_quality.rs`, 3.7 times the reference flicker against 3.0 with this one).

use super::bvh::{self, BuildItem};
use crate::geometry::{segment, StrandSet};
use crate::math::rng::{hash_u32, GenRng};
use crate::math::{Aabb, RayCone};
use glam::Vec3;
use rand::seq::SliceRandom;
use rand::SeedableRng;

/// Most pruning levels a strand set may have.
pub const MAX_LEVELS: usize = 16;

/// How many times wider than its box a smooth strand's tent profile is
/// ([`LodParams::smooth`]): the box convolved with itself spans twice its width.
const TENT_WIDTH: f32 = 2.0;

/// Distinct jitter values segments draw theirs from: fine enough that level transitions
/// dither smoothly, and a table of `d^jitter` spares an `exp` per segment test.
const JITTER_STEPS: usize = 32;

/// How a strand set is pruned (thesis section 2.2.3).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LodParams {
    /// Decimation coefficient `d`: each level keeps `1 / d` of the strands of the previous
    /// one (thesis default 1.5).
    pub decimation: f32,
    /// Number of levels, the full set (level 0) included.
    pub levels: u32,
    /// Thickness compensation `c` in (0, 1]: kept strands overlap less than the ones they
    /// stand for, so they widen by less than `d^l` (thesis: about 80 %).
    pub compensation: f32,
    /// Reduce the contrast of strand colours toward their mean at coarser levels (Cook et
    /// al. 2007): fewer strands per pixel would otherwise make the colour noisier.
    pub contrast: bool,
    /// Footprint, in strand widths, at which pruning starts: level `l` is used where the
    /// footprint is about `start * d^l` widths, so kept strands stay `start` times thinner
    /// than the footprint. A pixel then averages several pruned strands and the pruned
    /// look differs from the full one by about `1 / start` of the coverage's variance
    /// (the thesis' rule, switching when the ray grows as thick as a hair, is `start = 1`).
    pub start: f32,
    /// How many times wider than [`LodParams::radius_scale`] strands are drawn at levels
    /// above 0, with opacity divided as much, so they cover the same expected area as the
    /// strands they stand for but fractionally: a pixel sees several semi-transparent kept
    /// strands instead of a frozen hit-or-miss pattern of a few opaque ones. Capped so a
    /// strand never grows wider than the level's footprint. 1 draws them opaque.
    pub spread: f32,
    /// The level from which strands skip every other point (thesis section 2.2: coarser
    /// levels may also use fewer segments per strand): each pair of segments from an even
    /// point is drawn as the one segment between its ends, so a strand keeps its end points
    /// and departs from its curve by at most the skipped points' distance to those chords.
    /// 0 never simplifies.
    pub simplify: u32,
    /// For animation: draw the semi-transparent strands of [`LodParams::spread`] with a
    /// tent opacity profile twice as wide (the box convolved with itself: the same peak
    /// opacity and expected coverage), and have the renderer blend and shadow their
    /// layers deterministically ([`crate::accel::Accel::smooth_layers`]), so a sample's
    /// value changes continuously as strands slide under it instead of toggling.
    pub smooth: bool,
}

impl Default for LodParams {
    fn default() -> Self {
        LodParams {
            decimation: 1.5,
            levels: 8,
            compensation: 0.8,
            contrast: false,
            start: 1.0,
            spread: 1.0,
            simplify: 0,
            smooth: false,
        }
    }
}

impl LodParams {
    /// Checks the values, naming the wrong one.
    pub fn validate(&self) -> Result<(), String> {
        if !(self.decimation.is_finite() && self.decimation > 1.0 && self.decimation <= 16.0) {
            return Err(format!("lod `decimation` {} must be above 1 and at most 16", self.decimation));
        }
        if !(1..=MAX_LEVELS as u32).contains(&self.levels) {
            return Err(format!("lod `levels` {} must be between 1 and {MAX_LEVELS}", self.levels));
        }
        if !(self.start.is_finite() && (1.0..=1000.0).contains(&self.start)) {
            return Err(format!("lod `start` {} must be between 1 and 1000", self.start));
        }
        if !(self.spread.is_finite() && (1.0..=1000.0).contains(&self.spread)) {
            return Err(format!("lod `spread` {} must be between 1 and 1000", self.spread));
        }
        if self.simplify > MAX_LEVELS as u32 {
            return Err(format!("lod `simplify` {} must be between 0 (off) and {MAX_LEVELS}", self.simplify));
        }
        if !(self.compensation.is_finite() && self.compensation > 0.0 && self.compensation <= 1.0) {
            return Err(format!("lod `compensation` {} must be above 0 and at most 1", self.compensation));
        }
        Ok(())
    }

    /// Strands level `level` keeps out of `n`: `ceil(n / d^level)`, at least one.
    pub fn kept(&self, n: usize, level: u32) -> usize {
        let kept = (n as f64 / (self.decimation as f64).powi(level as i32)).ceil() as usize;
        kept.clamp(n.min(1), n)
    }

    /// Factor on the radius of the strands at `level`: `1 + c (d^l - 1)`. It is 1 at level
    /// 0, and tends to the thesis' `c d^l` (its example: 80 % gives a 4 times wider hair
    /// for 5 removed) as the level grows; `c = 1` preserves the projected area exactly.
    pub fn radius_scale(&self, level: u32) -> f32 {
        1.0 + self.compensation * (self.decimation.powi(level as i32) - 1.0)
    }

    /// Extra widening of the strands at `level` beyond [`LodParams::radius_scale`]: 1 at
    /// level 0, else `spread`, at most the level's footprint `start * d^level` over the
    /// compensated width. The strand's opacity there is its inverse.
    pub fn spread_at(&self, level: u32) -> f32 {
        if level == 0 {
            return 1.0;
        }
        let footprint = self.start * self.decimation.powi(level as i32);
        self.spread.min(footprint / self.radius_scale(level)).max(1.0)
    }

    /// The last level of each of `n` strands (its group): strands are ranked by a random
    /// permutation drawn from `seed`, and the strand of rank `r` lives up to the coarsest
    /// level that still keeps more than `r` strands.
    pub fn strand_groups(&self, n: usize, seed: u32) -> Vec<u8> {
        let mut order: Vec<u32> = (0..n as u32).collect();
        order.shuffle(&mut GenRng::seed_from_u64(seed as u64));
        let kept: Vec<usize> = (0..self.levels).map(|l| self.kept(n, l)).collect();
        let mut groups = vec![0u8; n];
        for (rank, &strand) in order.iter().enumerate() {
            groups[strand as usize] = (kept.iter().rposition(|&k| rank < k).unwrap_or(0)) as u8;
        }
        groups
    }
}

/// The camera a scene is rendered from, as level of detail sees it. A segment's BVH box
/// must hold the segment at the widest it is ever drawn: without a camera that is its
/// group's (coarsest) level, so near rays cross boxes widened for far away. With a camera,
/// a ray sees each segment at the finer of its own level and the camera's there (the
/// level a camera ray takes at the distance of the segment's midpoint from the eye, with
/// the segment's jitter), and the box is widened only as far as the camera sees it.
/// Camera rays see no change, but on segments that straddle a level change; shadow and
/// gathered rays, whose cones start from the camera ray's and only widen, may ask for a
/// coarser level and then see the segment as the camera does: finer, covering alike on
/// average, at some more cost for those rays.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LodCamera {
    /// The eye: the pinhole, or the centre of an orthographic camera's window.
    pub eye: Vec3,
    /// The camera ray cones at the eye: a pinhole's start 0 wide and spread by the angle a
    /// pixel subtends, an orthographic camera's are a pixel wide and do not spread.
    pub cone: RayCone,
}

/// A strand set's pruning levels: the group of each strand, and per level the widening
/// and the footprint where it starts. The segments' BVH is the object's own
/// ([`super::Object`]), built from [`StrandLod::items`].
#[derive(Clone, Debug)]
pub struct StrandLod {
    params: LodParams,
    /// Mean strand diameter: the width the footprint is compared with.
    width: f32,
    /// `start * width`: the footprint at which pruning starts.
    start_width: f32,
    /// Low bits of a BVH item id that hold the segment's group.
    group_bits: u32,
    /// Strands in each group.
    group_strands: Vec<u32>,
    /// The last level (group) of each strand.
    groups_of: Vec<u8>,
    /// `start * width * d^(k + 1)`: the footprint at which the level passes `k` (without
    /// jitter).
    thresholds: [f32; MAX_LEVELS],
    /// Radius factor per level, spread included.
    scales: [f32; MAX_LEVELS],
    /// The largest of `scales` up to each level.
    widest: [f32; MAX_LEVELS],
    /// Opacity factor per level: `1 / spread_at(level)`.
    opacities: [f32; MAX_LEVELS],
    /// `d^jitter` for each of the [`JITTER_STEPS`] jitter values: a footprint times it
    /// compares with the thresholds as `log_d(footprint) + jitter` with their exponents.
    jitter_factors: [f32; JITTER_STEPS],
    /// Mean strand colour, when contrast reduction is on and the strands have colours.
    mean_color: Option<Vec3>,
    /// With [`LodParams::simplify`]: one bit per point, set where the segment from that
    /// point stands for its pair at simplified levels (an even point of its strand with two
    /// more after it); the segment after it is then hidden there. Empty otherwise.
    pairs: Vec<u64>,
    /// The camera that bounds each segment's level ([`LodCamera`]), when known.
    camera: Option<LodCamera>,
}

/// A ray as level of detail sees it: where it starts and goes, and its cone.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LodRay {
    origin: Vec3,
    dir: Vec3,
    cone: RayCone,
}

impl LodRay {
    /// The ray from `origin` along unit `dir` with footprint `cone`.
    #[inline]
    pub(crate) fn new(origin: Vec3, dir: Vec3, cone: RayCone) -> LodRay {
        LodRay { origin, dir, cone }
    }
}

/// A strand set as one ray sees it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LodView<'a> {
    lod: &'a StrandLod,
    ray: LodRay,
}

impl LodView<'_> {
    /// The segment's first point and group, from its BVH item id.
    #[inline(always)]
    pub(crate) fn decode(&self, id: u32) -> (u32, usize) {
        (id >> self.lod.group_bits, (id & ((1 << self.lod.group_bits) - 1)) as usize)
    }

    /// How the ray sees the segment from point `first`, between points `a` and `b`, of
    /// group `group`: its radius factor, its level and the distance from which its group
    /// is hidden for it (a hit from there on does not count); `None` when the whole
    /// widened segment lies beyond that distance, so it is skipped without the exact test.
    /// The level is read at the distance of the segment's midpoint: segments are short
    /// next to the distances where levels change.
    #[inline(always)]
    pub(crate) fn segment(&self, first: u32, a: [f32; 4], b: [f32; 4], group: usize) -> Option<(f32, u32, f32)> {
        let LodRay { origin, dir, cone } = self.ray;
        let ta = (Vec3::new(a[0], a[1], a[2]) - origin).dot(dir);
        let tb = (Vec3::new(b[0], b[1], b[2]) - origin).dot(dir);
        // level <= k while footprint * d^jitter < thresholds[k] (see `level_at`).
        let jitter = self.lod.jitter_factors[jitter_step(first)];
        let thresholds = &self.lod.thresholds;
        // The common case, near fur: level 0 up to the segment's far end, where every
        // group is visible at its own width.
        if cone.width_at(ta.max(tb) + a[3].max(b[3])) * jitter < thresholds[0] {
            return Some((1.0, 0, f32::INFINITY));
        }
        let footprint = cone.width_at(0.5 * (ta + tb)) * jitter;
        let mut level = thresholds[..group].iter().take_while(|&&c| footprint >= c).count();
        let ceiling = self.lod.camera_level(a, b, jitter, |a, b| a.midpoint(b).distance(self.lod.camera_eye()));
        let scale = self.lod.scales[level.min(ceiling)];
        let hidden = thresholds[group] / jitter;
        let cut = if ceiling <= group {
            // Never coarser than the group's level: always visible.
            f32::INFINITY
        } else if cone.spread > 0.0 {
            (hidden - cone.width) / cone.spread
        } else if cone.width.abs() < hidden {
            f32::INFINITY
        } else {
            f32::NEG_INFINITY
        };
        // A point of the surface lies at most one radius before its axis point.
        if ta.min(tb) - a[3].max(b[3]) * scale >= cut {
            return None;
        }
        level = level.min(ceiling);
        Some((scale, level as u32, cut))
    }

    /// The BVH leaf with tag `tag` ([`StrandLod::items`]) as the ray sees it.
    #[inline(always)]
    pub(crate) fn leaf(&self, tag: u8) -> LodLeaf<'_> {
        let widest = self.lod.pairs.is_empty().then(|| self.lod.widest[tag as usize % MAX_LEVELS]);
        LodLeaf { view: self, widest }
    }

    /// The point the segment from `first`, of group `group`, is drawn to: `first + 1`, or
    /// `first + 2` where the ray sees its pair at a simplified level
    /// ([`LodParams::simplify`]); `None` where the pair's first segment stands for it. Both
    /// segments of a pair decide alike: from the level at their shared point with the
    /// jitter of the first, so a pair is never drawn both ways at once.
    #[inline(always)]
    pub(crate) fn segment_end(&self, points: &[[f32; 4]], first: u32, group: usize) -> Option<u32> {
        let simplify = self.lod.params.simplify as usize;
        if self.lod.pairs.is_empty() || group < simplify || simplify == 0 {
            return Some(first + 1);
        }
        let pairs = |p: u32| self.lod.pairs[p as usize / 64] >> (p % 64) & 1 == 1;
        let (pair, second) = if pairs(first) {
            (first, false)
        } else if first > 0 && pairs(first - 1) {
            (first - 1, true)
        } else {
            return Some(first + 1);
        };
        let LodRay { origin, dir, cone } = self.ray;
        let m = points[pair as usize + 1];
        let t = (Vec3::new(m[0], m[1], m[2]) - origin).dot(dir);
        // Level at least `simplify` (see `segment`): the footprint reaches its threshold,
        // the camera's too.
        let jitter = self.lod.jitter_factors[jitter_step(pair)];
        let simplified = cone.width_at(t) * jitter >= self.lod.thresholds[simplify - 1]
            && self.lod.camera_level(m, m, jitter, |m, _| m.distance(self.lod.camera_eye())) >= simplify;
        match (simplified, second) {
            (false, _) => Some(first + 1),
            (true, false) => Some(first + 2),
            (true, true) => None,
        }
    }
}

/// Where a hit at parameter `s` along the chord from point `first` to `first + 2` lies on
/// the two segments the chord stands for: the segment and its parameter, at the same
/// fraction of their summed length (how far along the strand shading happens).
#[inline]
pub(crate) fn unsimplify(points: &[[f32; 4]], first: u32, s: f32) -> (u32, f32) {
    let p = |i: u32| Vec3::from_slice(&points[i as usize][..3]);
    let (l1, l2) = (p(first).distance(p(first + 1)), p(first + 1).distance(p(first + 2)));
    let along = s * (l1 + l2);
    if along <= l1 {
        (first, if l1 > 0.0 { along / l1 } else { 0.0 })
    } else {
        (first + 1, if l2 > 0.0 { ((along - l1) / l2).min(1.0) } else { 1.0 })
    }
}

/// A BVH leaf of a strand set as one ray sees it with level of detail.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LodLeaf<'a> {
    /// The strand set as the ray sees it.
    pub(crate) view: &'a LodView<'a>,
    /// The widest radius factor any of the leaf's segments is drawn with (from the leaf's
    /// BVH tag, [`StrandLod::items`]), for the cheap 8-wide cull
    /// ([`segment::near8`]); `None` where coarse levels draw chords of segment pairs, which
    /// that cull does not bound.
    pub(crate) widest: Option<f32>,
}

/// How a leaf's segments are seen for a ray's level of detail: `None` at full detail.
pub(crate) type Widen<'a> = Option<&'a LodLeaf<'a>>;

/// The jitter step of the segment from point `first`: a hash, so neighbouring segments
/// and strands switch levels at different distances.
#[inline(always)]
fn jitter_step(first: u32) -> usize {
    hash_u32(first ^ 0x10d_5eed) as usize % JITTER_STEPS
}

impl StrandLod {
    /// Prunes `strands` with `params` (ranks drawn from `seed`). `None` when there is
    /// nothing to prune (no strands, or strands without width), or when the set has too
    /// many points for their index and group to share a BVH item id ([`StrandLod::fits`]).
    pub fn build(strands: &StrandSet, params: LodParams, seed: u32) -> Option<StrandLod> {
        let n = strands.strand_count();
        let (sum, count) = strands.points.iter().fold((0.0f64, 0usize), |(s, c), p| (s + 2.0 * p[3] as f64, c + 1));
        let width = (sum / count.max(1) as f64) as f32;
        if n == 0 || !(width.is_finite() && width > 0.0) || !StrandLod::fits(strands.points.len(), params) {
            return None;
        }
        let levels = params.levels as usize;
        let groups_of = params.strand_groups(n, seed);
        let mut group_strands = vec![0u32; levels];
        groups_of.iter().for_each(|&g| group_strands[g as usize] += 1);
        let mut thresholds = [f32::INFINITY; MAX_LEVELS];
        let (mut scales, mut opacities) = ([1.0; MAX_LEVELS], [1.0; MAX_LEVELS]);
        let jitter_factors = std::array::from_fn(|q| params.decimation.powf(step_jitter(q)));
        for l in 0..levels {
            // The coarsest level never ends.
            if l + 1 < levels {
                thresholds[l] = params.start * width * params.decimation.powi(l as i32 + 1);
            }
            let spread = params.spread_at(l as u32);
            let tent = if params.smooth && spread > 1.0 { TENT_WIDTH } else { 1.0 };
            scales[l] = params.radius_scale(l as u32) * spread * tent;
            opacities[l] = 1.0 / spread;
        }
        let mut widest = scales;
        for l in 1..MAX_LEVELS {
            widest[l] = widest[l].max(widest[l - 1]);
        }
        let mut pairs = Vec::new();
        if params.simplify > 0 && params.simplify < params.levels {
            pairs = vec![0u64; strands.points.len().div_ceil(64)];
            for w in strands.offsets.windows(2) {
                // Even points with two more after them: the last point is always kept.
                for i in (w[0]..w[1].saturating_sub(2)).step_by(2) {
                    pairs[i as usize / 64] |= 1 << (i % 64);
                }
            }
        }
        let mean_color = strands.colors.as_ref().filter(|c| params.contrast && !c.is_empty()).map(|c| {
            let sum = c.iter().fold([0.0f64; 3], |a, x| [a[0] + x[0] as f64, a[1] + x[1] as f64, a[2] + x[2] as f64]);
            Vec3::new(sum[0] as f32, sum[1] as f32, sum[2] as f32) / c.len() as f32
        });
        Some(StrandLod {
            params,
            width,
            start_width: params.start * width,
            group_bits: group_bits(params.levels),
            group_strands,
            groups_of,
            thresholds,
            scales,
            widest,
            opacities,
            jitter_factors,
            mean_color,
            pairs,
            camera: None,
        })
    }

    /// True when a strand set of `points` points can be pruned with `params`: every
    /// segment's first point, shifted past the group bits, stays a valid BVH item id.
    pub fn fits(points: usize, params: LodParams) -> bool {
        (points as u64) << group_bits(params.levels) < bvh::MAX_ITEMS as u64
    }

    /// The BVH item id of the segment starting at point `first` in group `group`.
    pub fn item_id(&self, first: u32, group: u8) -> u32 {
        (first << self.group_bits) | group as u32
    }

    /// The BVH items of `strands` (the set this was built for): every segment, its id
    /// carrying its group, bounded at the radius its group's level gives it (and, for the
    /// first segment of a pair that can be simplified, around its pair's chord too), tagged
    /// with the level of that radius (`LodView::leaf`).
    pub fn items(&self, strands: &StrandSet) -> Vec<BuildItem> {
        let mut items = Vec::with_capacity(strands.segment_count());
        let eye = self.camera_eye();
        let farthest = |a: Vec3, b: Vec3| a.distance(eye).max(b.distance(eye));
        for (strand, w) in strands.offsets.windows(2).enumerate() {
            let group = self.groups_of[strand] as usize;
            let simplified = self.params.simplify > 0 && group as u32 >= self.params.simplify;
            for i in w[0]..w[1].saturating_sub(1) {
                let points = &strands.points;
                let end = if simplified { (i + 2).min(w[1] - 1) } else { i + 1 };
                // The widest the segment gets: at its group's level, or the camera's there
                // (over the chord it may stand for, too), with the camera's rounding margin.
                let jitter = self.jitter_factors[jitter_step(i)];
                let ceiling = self.camera_level(points[i as usize], points[end as usize], jitter, farthest);
                let ceiling =
                    ceiling.max(self.camera_level(points[i as usize], points[i as usize + 1], jitter, farthest));
                // The level of that radius: the item's tag (`LodView::leaf`).
                let tag = group.min(ceiling);
                let scale = self.scales[tag];
                let widen = |i: u32| {
                    let p = points[i as usize];
                    [p[0], p[1], p[2], p[3] * scale * (1.0 + 1e-5)]
                };
                let (min, max) = segment::bounds(widen(i), widen(i + 1));
                let mut bounds = Aabb::new(min, max);
                if simplified && self.pairs[i as usize / 64] >> (i % 64) & 1 == 1 {
                    let (min, max) = segment::bounds(widen(i), widen(i + 2));
                    bounds = bounds.union(Aabb::new(min, max));
                }
                items.push(BuildItem { bounds, id: self.item_id(i, group as u8), tag: tag as u8 });
            }
        }
        items
    }

    /// The same levels, each segment's bounded by what `camera` sees of it ([`LodCamera`]).
    pub fn for_camera(self, camera: LodCamera) -> StrandLod {
        StrandLod { camera: Some(camera), ..self }
    }

    /// The eye of the camera, or the origin without one.
    #[inline(always)]
    fn camera_eye(&self) -> Vec3 {
        self.camera.map_or(Vec3::ZERO, |c| c.eye)
    }

    /// The finest level a ray may need for the segment between points `a` and `b`, whose
    /// jitter factor is `jitter` ([`LodCamera`]): the camera's level at the distance
    /// `distance(a, b)` gives (the midpoint's when tracing, the farthest point's to bound);
    /// the coarsest level without a camera.
    #[inline(always)]
    fn camera_level(&self, a: [f32; 4], b: [f32; 4], jitter: f32, distance: impl Fn(Vec3, Vec3) -> f32) -> usize {
        let Some(camera) = self.camera else { return MAX_LEVELS - 1 };
        let (a, b) = (Vec3::new(a[0], a[1], a[2]), Vec3::new(b[0], b[1], b[2]));
        let footprint = (camera.cone.width + camera.cone.spread * distance(a, b)) * jitter;
        self.thresholds.iter().take_while(|&&c| footprint >= c).count()
    }

    /// The pruning parameters.
    pub fn params(&self) -> &LodParams {
        &self.params
    }

    /// Mean strand diameter, the width footprints are compared with.
    pub fn width(&self) -> f32 {
        self.width
    }

    /// Strands in each group (group `k`: strands whose last level is `k`).
    pub fn group_strands(&self) -> &[u32] {
        &self.group_strands
    }

    /// Bytes of the LOD's own bookkeeping (parameters, thresholds, group sizes and each
    /// strand's group), beyond the BVH every strand set has.
    pub fn bookkeeping_bytes(&self) -> usize {
        std::mem::size_of::<StrandLod>() + self.group_strands.len() * 4 + self.groups_of.len() + self.pairs.len() * 8
    }

    /// The level a ray with `cone` uses at distance `t`:
    /// `floor(log_d(footprint(t) / (start * width)) + jitter)`, clamped to the levels there
    /// are. A footprint thinner than the hair gives level 0 whatever the jitter.
    pub fn level_at(&self, cone: RayCone, t: f32, jitter: f32) -> u32 {
        let ratio = cone.width_at(t) / self.start_width;
        // A zero, negative or NaN ratio (no footprint): full detail.
        if ratio.is_nan() || ratio <= 0.0 {
            return 0;
        }
        let level = (ratio.ln() / self.params.decimation.ln() + jitter).floor();
        level.clamp(0.0, (self.params.levels - 1) as f32) as u32
    }

    /// The jitter in [0, 1) of the segment from point `first` in [`StrandLod::level_at`]:
    /// one of `JITTER_STEPS` values, drawn by a hash of the point.
    pub fn segment_jitter(&self, first: u32) -> f32 {
        step_jitter(jitter_step(first))
    }

    /// The strand set as `ray` sees it.
    #[inline]
    pub(crate) fn view(&self, ray: &LodRay) -> LodView<'_> {
        LodView { lod: self, ray: *ray }
    }

    /// A strand colour seen at `level`, its contrast to the set's mean reduced by
    /// `d^(-level / 2)` when contrast reduction is on. After Cook et al. 2007: a pixel that
    /// averages `n` strands has a colour deviation of `sigma / sqrt(n)`; pruning to `n / d^l`
    /// strands raises it by `d^(l / 2)`, which this scaling takes back.
    pub fn color(&self, level: u32, color: Option<Vec3>) -> Option<Vec3> {
        match (self.mean_color, color) {
            (Some(mean), Some(c)) if level > 0 => {
                Some(mean + (c - mean) * self.params.decimation.powf(-0.5 * level as f32))
            }
            _ => color,
        }
    }

    /// Radius factor of the strands at `level`, spread included.
    pub fn radius_scale(&self, level: u32) -> f32 {
        self.scales[(level as usize).min(MAX_LEVELS - 1)]
    }

    /// Factor on the opacity of the strands at `level`: the inverse of their spread, so
    /// width times opacity stays the compensated width (1 at level 0).
    pub fn opacity(&self, level: u32) -> f32 {
        self.opacities[(level as usize).min(MAX_LEVELS - 1)]
    }

    /// Opacity factor of a strand hit at `level` by a ray passing at `offset` from its
    /// axis, in drawn radii (0 on the axis, 1 at the edge): [`StrandLod::opacity`], times
    /// the tent profile `1 - offset` for the semi-transparent levels of a smooth set
    /// ([`LodParams::smooth`]). The offset is asked for only then.
    #[inline]
    pub fn opacity_at(&self, level: u32, offset: impl FnOnce() -> f32) -> f32 {
        let peak = self.opacity(level);
        if peak >= 1.0 || !self.params.smooth {
            return peak;
        }
        peak * (1.0 - offset()).clamp(0.0, 1.0)
    }

    /// True when some level draws strands semi-transparent.
    pub fn has_transparency(&self) -> bool {
        self.opacities[..self.params.levels as usize].iter().any(|&a| a < 1.0)
    }
}

/// The jitter of step `q`: the middle of the `q`-th of [`JITTER_STEPS`] equal intervals.
fn step_jitter(q: usize) -> f32 {
    (q as f32 + 0.5) / JITTER_STEPS as f32
}

/// Bits of an item id that hold the group of a set with `levels` levels.
fn group_bits(levels: u32) -> u32 {
    32 - levels.saturating_sub(1).leading_zeros()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accel::{Accel, HitKind, Shape};
    use crate::math::Ray;
    use rand::Rng;

    /// `n` straight vertical strands of radius `r` at random x in [0, 1], in the plane z = 0,
    /// with 2 to 5 segments each.
    fn curtain(n: usize, r: f32, seed: u64) -> StrandSet {
        let mut rng = GenRng::seed_from_u64(seed);
        let mut s = StrandSet::new();
        for _ in 0..n {
            let x = rng.random::<f32>();
            let k = rng.random_range(3..7);
            s.push_strand((0..k).map(|i| (Vec3::new(x, i as f32 / (k - 1) as f32, 0.0), r)));
        }
        s
    }

    #[test]
    fn levels_are_nested_and_keep_one_in_d_per_level() {
        for d in [1.5f32, 2.0] {
            let p = LodParams { decimation: d, levels: 8, ..Default::default() };
            let n = 10_000;
            let groups = p.strand_groups(n, 3);
            for l in 0..8 {
                // Level l keeps the strands whose last level is at least l.
                let kept = groups.iter().filter(|&&g| g as u32 >= l).count();
                assert_eq!(kept, (n as f64 / (d as f64).powi(l as i32)).ceil() as usize, "d {d} level {l}");
            }
            // A different seed keeps other strands, in the same numbers.
            let other = p.strand_groups(n, 4);
            assert_ne!(groups, other);
            assert_eq!(other.iter().filter(|&&g| g >= 3).count(), groups.iter().filter(|&&g| g >= 3).count());
        }
        assert_eq!(LodParams::default().kept(1, 7), 1);
        assert_eq!(LodParams::default().kept(0, 7), 0);
    }

    #[test]
    fn groups_partition_the_segments() {
        let s = curtain(3000, 0.001, 1);
        let p = LodParams::default();
        let groups = p.strand_groups(s.strand_count(), 9);
        let lod = StrandLod::build(&s, p, 9).unwrap();
        let view = lod.view(&LodRay::new(Vec3::ZERO, Vec3::Z, RayCone::default()));
        let items = lod.items(&s);
        let mut ids: Vec<u32> = items.iter().map(|i| view.decode(i.id).0).collect();
        ids.sort_unstable();
        assert_eq!(ids, s.segment_starts(), "every segment exactly once");
        // Each item carries its strand's group, and ids stay valid BVH items.
        let strand_of = |p: u32| s.offsets.partition_point(|&o| o <= p) - 1;
        for i in &items {
            let (first, group) = view.decode(i.id);
            assert_eq!(group, groups[strand_of(first)] as usize);
            assert!((i.id as usize) < bvh::MAX_ITEMS);
        }
        assert_eq!(lod.group_strands().iter().sum::<u32>() as usize, s.strand_count());
        // The coarsest group is the smallest; group 0 holds about 1 - 1/d of the strands.
        assert_eq!(lod.group_strands()[7] as usize, p.kept(3000, 7));
        assert_eq!(lod.group_strands()[0] as usize, 3000 - p.kept(3000, 1));
    }

    #[test]
    fn level_follows_the_footprint() {
        let s = curtain(100, 0.005, 2); // width 0.01
        let lod = StrandLod::build(&s, LodParams::default(), 0).unwrap();
        assert!((lod.width() - 0.01).abs() < 1e-7);
        let cone = RayCone { width: 0.0, spread: 0.001 };
        for j in [0.0, 0.3, 0.999] {
            // Footprint thinner than the hair: level 0 whatever the jitter.
            assert_eq!(lod.level_at(cone, 9.99, j), 0);
            assert_eq!(lod.level_at(RayCone::default(), 1e6, j), 0);
            // Footprint d^2.5 hair widths: floor(2.5 + jitter).
            let t = 0.01 * 1.5f32.powf(2.5) / 0.001;
            assert_eq!(lod.level_at(cone, t, j), (2.5 + j).floor() as u32);
            // Clamped to the coarsest level.
            assert_eq!(lod.level_at(cone, 1e9, j), 7);
        }
        // A segment across the ray at distance t takes the level of the formula with its
        // own jitter, and its group hides where that level passes the group.
        let mut rng = GenRng::seed_from_u64(5);
        let mut jitters = std::collections::BTreeSet::new();
        for _ in 0..2000 {
            let cone = RayCone { width: rng.random::<f32>() * 0.02, spread: rng.random::<f32>() * 0.01 };
            let (first, t) = (rng.random_range(0..1000u32), rng.random::<f32>() * 300.0);
            let j = lod.segment_jitter(first);
            jitters.insert(j.to_bits());
            let view = lod.view(&LodRay::new(Vec3::ZERO, Vec3::Z, cone));
            let (a, b) = ([-1.0, 0.0, t, 0.005], [1.0, 0.0, t, 0.005]);
            let level = lod.level_at(cone, t, j);
            let group = rng.random_range(0..8usize);
            // Away from the boundaries (rounding may differ there).
            if lod.level_at(cone, t * 1.001, j) != lod.level_at(cone, t * 0.999, j) {
                continue;
            }
            match view.segment(first, a, b, group) {
                Some((scale, l, cut)) => {
                    if level as usize <= group {
                        assert_eq!((l, scale), (level, lod.radius_scale(level)), "cone {cone:?} jitter {j} t {t}");
                        assert!(t < cut, "visible at {t}, cut {cut}");
                    } else {
                        assert!(t >= cut, "hidden at {t}, cut {cut}");
                    }
                    // Around the cut the level passes the group.
                    if cut.is_finite() && cut > 0.0 {
                        assert!(lod.level_at(cone, cut * 1.001, j) as usize > group, "cut {cut}");
                        assert!(lod.level_at(cone, cut * 0.999, j) as usize <= group, "cut {cut}");
                    }
                }
                None => assert!(level as usize > group, "cone {cone:?} jitter {j} t {t}: level {level}, group {group}"),
            }
        }
        assert!(jitters.len() > JITTER_STEPS / 2, "segments draw different jitters");
    }

    #[test]
    fn strand_sets_of_different_widths_pick_different_levels() {
        let thin = StrandLod::build(&curtain(50, 0.001, 3), LodParams::default(), 0).unwrap();
        let thick = StrandLod::build(&curtain(50, 0.01, 3), LodParams::default(), 0).unwrap();
        let cone = RayCone { width: 0.0, spread: 0.001 };
        let t = 40.0; // footprint 0.04: 20 thin widths, 2 thick ones
        assert_eq!(thin.level_at(cone, t, 0.5), 7); // floor(log_1.5 20 + 0.5) = 7
        assert_eq!(thick.level_at(cone, t, 0.5), 2); // floor(log_1.5 2 + 0.5) = 2
    }

    /// Fraction of rays along -z through the unit square that hit the curtain with the
    /// level forced by a cone of constant width `footprint`.
    fn coverage(accel: &Accel, footprint: f32) -> f64 {
        let mut rng = GenRng::seed_from_u64(11);
        let n = 40_000;
        let hits = (0..n)
            .filter(|_| {
                let mut ray = Ray::new(Vec3::new(rng.random(), 0.1 + 0.8 * rng.random::<f32>(), 1.0), -Vec3::Z);
                ray.cone = RayCone { width: footprint, spread: 0.0 };
                accel.intersect(&ray).is_some()
            })
            .count();
        hits as f64 / n as f64
    }

    #[test]
    fn width_compensation_keeps_projected_area() {
        // Hair widths summing to 0.4 of the square's width, before overlap.
        let s = curtain(8000, 0.000025, 4);
        for c in [1.0f32, 0.8] {
            let p = LodParams { compensation: c, ..Default::default() };
            let accel = Accel::build_with_lod(vec![(Shape::Strands(s.clone()), 0, Some(p))]);
            let lod = accel.objects[0].lod().unwrap();
            let full = coverage(&accel, 0.0);
            for l in 1..5u32 {
                // A constant footprint of d^l widths is level l for every jitter.
                let footprint = lod.width() * p.decimation.powi(l as i32);
                // Summed widths relative to level 0: c = 1 preserves them, c < 1 thins.
                let projected = p.kept(8000, l) as f64 * p.radius_scale(l) as f64 / 8000.0;
                if c == 1.0 {
                    assert!((projected - 1.0).abs() < 0.01, "level {l}: projected width {projected}");
                }
                // Strands at random places: coverage is 1 - exp(-summed width), so the
                // pruned coverage follows from the full one and the projected ratio
                // (standard deviation of a level-4 coverage here: about 0.01).
                let expect = 1.0 - (1.0 - full).powf(projected);
                let got = coverage(&accel, footprint);
                assert!(
                    (got - expect).abs() < 0.03,
                    "c {c} level {l}: coverage {got}, expected {expect} (full {full})"
                );
            }
        }
    }

    /// Mean and variance over rays along -z through the unit square of the opacity the
    /// curtain shows (1 - transmittance), at the level forced by a constant `footprint`.
    fn opacity_stats(accel: &Accel, footprint: f32) -> (f64, f64) {
        let mut rng = GenRng::seed_from_u64(12);
        let n = 20_000;
        let cone = RayCone { width: footprint, spread: 0.0 };
        let (mut sum, mut sq) = (0.0, 0.0);
        for _ in 0..n {
            let origin = Vec3::new(rng.random(), 0.1 + 0.8 * rng.random::<f32>(), 1.0);
            let a = 1.0 - accel.transmittance_cone(origin, -Vec3::Z, 2.0, None, cone, None) as f64;
            (sum, sq) = (sum + a, sq + a * a);
        }
        let mean = sum / n as f64;
        (mean, sq / n as f64 - mean * mean)
    }

    #[test]
    fn spread_strands_keep_the_projected_coverage_and_smooth_it() {
        let s = curtain(8000, 0.000025, 4);
        let p = LodParams { compensation: 1.0, start: 16.0, ..Default::default() };
        let spread = LodParams { spread: 4.0, ..p };
        let smooth = LodParams { smooth: true, ..spread };
        let opaque = Accel::build_with_lod(vec![(Shape::Strands(s.clone()), 0, Some(p))]);
        let soft = Accel::build_with_lod(vec![(Shape::Strands(s.clone()), 0, Some(spread))]);
        let tent = Accel::build_with_lod(vec![(Shape::Strands(s), 0, Some(smooth))]);
        let lod = soft.objects[0].lod().unwrap();
        assert!(soft.has_transparency() && !opaque.has_transparency());
        assert!(tent.smooth_layers() && !soft.smooth_layers());
        let (full, _) = opacity_stats(&opaque, 0.0);
        for l in 1..5u32 {
            // Width times opacity is the compensated width.
            let ratio = lod.radius_scale(l) * lod.opacity(l) / p.radius_scale(l);
            assert!((ratio - 1.0).abs() < 1e-5, "level {l}: {ratio}");
            let footprint = 16.0 * lod.width() * p.decimation.powi(l as i32) * 1.01;
            let (hard_mean, hard_var) = opacity_stats(&opaque, footprint);
            let (soft_mean, soft_var) = opacity_stats(&soft, footprint);
            // Strands at random places: the expected opacity is 1 - exp(-summed width
            // times opacity), the same for opaque and spread strands, and close to the
            // full set's coverage (standard deviation of a mean here about 0.004).
            assert!((soft_mean - hard_mean).abs() < 0.02, "level {l}: {soft_mean} vs {hard_mean}");
            assert!((soft_mean - full).abs() < 0.03, "level {l}: {soft_mean} vs full {full}");
            // Fractional coverage varies less from ray to ray than hit-or-miss.
            assert!(soft_var < 0.6 * hard_var, "level {l}: variance {soft_var} vs {hard_var}");
            // The tent is twice as wide at the same peak: half its width times its peak is
            // the compensated width, so it covers as much, and more smoothly still.
            let tent_lod = tent.objects[0].lod().unwrap();
            let ratio = tent_lod.radius_scale(l) * tent_lod.opacity(l) / p.radius_scale(l);
            assert!((ratio - 2.0).abs() < 1e-5, "level {l}: {ratio}");
            let (tent_mean, tent_var) = opacity_stats(&tent, footprint);
            assert!((tent_mean - hard_mean).abs() < 0.02, "level {l}: {tent_mean} vs {hard_mean}");
            assert!(tent_var < soft_var, "level {l}: variance {tent_var} vs {soft_var}");
        }
    }

    #[test]
    fn a_smooth_strand_fades_from_its_axis_to_its_edge() {
        // One vertical strand: every level keeps it.
        let mut s = StrandSet::new();
        let r = 0.001;
        s.push_strand([(Vec3::new(0.0, 0.0, 0.0), r), (Vec3::new(0.0, 1.0, 0.0), r)]);
        let p = LodParams { compensation: 1.0, start: 4.0, spread: 4.0, smooth: true, ..Default::default() };
        let accel = Accel::build_with_lod(vec![(Shape::Strands(s), 0, Some(p))]);
        let lod = accel.objects[0].lod().unwrap();
        let mut layers = Vec::new();
        for l in 1..4u32 {
            // A footprint at the start of level l: whatever the jitter, level l.
            let cone = RayCone { width: 4.0 * lod.width() * p.decimation.powi(l as i32) * 1.001, spread: 0.0 };
            let (peak, radius) = (lod.opacity(l), r * lod.radius_scale(l));
            assert!(peak < 1.0);
            for f in [0.0f32, 0.2, 0.5, 0.8, 0.97, 1.05] {
                // Along -z, and slanted: the offset is the distance between the lines.
                for dir in [-Vec3::Z, Vec3::new(0.3, 0.4, -1.0).normalize()] {
                    let across = Vec3::Y.cross(dir).normalize();
                    let origin = Vec3::new(0.0, 0.5, 0.0) + across * (f * radius) - dir;
                    let mut ray = Ray::new(origin, dir);
                    ray.cone = cone;
                    accel.intersect_k(&ray, 0.0, 4, &[], None, &mut layers);
                    if f > 1.0 {
                        assert!(layers.is_empty(), "level {l}, offset {f}: {layers:?}");
                        continue;
                    }
                    assert_eq!(layers.len(), 1, "level {l}, offset {f}");
                    assert_eq!(layers[0].hit.level, l);
                    let want = peak * (1.0 - f);
                    assert!(
                        (layers[0].opacity - want).abs() < 1e-3 * peak,
                        "level {l}, offset {f}: {layers:?} vs {want}"
                    );
                    let t = accel.transmittance_cone(origin, dir, 2.0, None, cone, None);
                    assert!((t - (1.0 - want)).abs() < 1e-3 * peak, "level {l}, offset {f}: {t}");
                }
            }
        }
    }

    #[test]
    fn a_near_ray_never_sees_lod_opacity() {
        let s = curtain(2000, 0.0005, 6);
        let p = LodParams { spread: 8.0, ..Default::default() };
        let accel = Accel::build_with_lod(vec![(Shape::Strands(s), 0, Some(p))]);
        let mut rng = GenRng::seed_from_u64(13);
        let (mut layers, mut hits) = (Vec::new(), 0);
        for i in 0..3000 {
            let origin = Vec3::new(rng.random(), 0.1 + 0.8 * rng.random::<f32>(), 1.0);
            let mut ray = Ray::new(origin, -Vec3::Z);
            // Footprints thinner than a hair at the curtain: level 0, opaque, whatever the jitter.
            ray.cone = if i % 2 == 0 { RayCone::default() } else { RayCone { width: 0.0, spread: 0.0009 } };
            accel.intersect_k(&ray, 0.0, 4, &[], None, &mut layers);
            assert!(layers.len() <= 1, "ray {i}: an opaque hit ends the list");
            if let Some(l) = layers.first() {
                assert_eq!((l.hit.level, l.opacity, l.hit.radius_scale), (0, 1.0, 1.0), "ray {i}");
                assert_eq!(accel.transmittance_cone(origin, -Vec3::Z, 2.0, None, ray.cone, None), 0.0);
                hits += 1;
            }
        }
        assert!(hits > 300, "the test needs hits: {hits}");
    }

    /// Brute force over every segment: the level of each from `level_at` at its midpoint,
    /// kept when its strand lives that long and the hit is where that group is visible.
    fn brute_force(s: &StrandSet, lod: &StrandLod, groups: &[u8], ray: &Ray) -> Option<(f32, u32, u32)> {
        let mut best: Option<(f32, u32, u32)> = None;
        for (strand, w) in s.offsets.windows(2).enumerate() {
            let group = groups[strand] as u32;
            for i in w[0]..w[1] - 1 {
                let jitter = lod.segment_jitter(i);
                let (a, b) = (s.position(i), s.position(i + 1));
                let mid = ((a + b) * 0.5 - ray.origin).dot(ray.dir);
                let level = lod.level_at(ray.cone, mid, jitter).min(group);
                let scale = lod.radius_scale(level);
                let widen = |p: [f32; 4]| [p[0], p[1], p[2], p[3] * scale];
                let tmax = best.map_or(ray.tmax, |h| h.0);
                let (p0, p1) = (widen(s.points[i as usize]), widen(s.points[i as usize + 1]));
                if let Some(h) = segment::intersect_cylinder(ray.origin, ray.dir, 0.0, tmax, p0, p1) {
                    if lod.level_at(ray.cone, h.t, jitter) <= group {
                        best = Some((h.t, i, level));
                    }
                }
            }
        }
        best
    }

    #[test]
    fn closest_hit_equals_brute_force_at_every_level() {
        let mut rng = GenRng::seed_from_u64(8);
        let mut s = StrandSet::new();
        for _ in 0..600 {
            let mut p = Vec3::new(rng.random(), rng.random(), rng.random()) * 4.0 - 2.0;
            let pts: Vec<(Vec3, f32)> = (0..rng.random_range(2..6))
                .map(|_| {
                    p += (Vec3::new(rng.random(), rng.random(), rng.random()) - 0.5) * 0.4;
                    (p, rng.random_range(0.002..0.01))
                })
                .collect();
            s.push_strand(pts);
        }
        let p = LodParams::default();
        let accel = Accel::build_with_lod(vec![(Shape::Strands(s.clone()), 0, Some(p))]);
        let lod = accel.objects[0].lod().unwrap();
        let groups = p.strand_groups(s.strand_count(), super::super::lod_seed(0));
        let (mut hits, mut coarse, mut layers) = (0, 0, Vec::new());
        for i in 0..3000 {
            let origin = Vec3::new(rng.random(), rng.random(), rng.random()) * 20.0 - 10.0;
            let target = Vec3::new(rng.random(), rng.random(), rng.random()) * 3.0 - 1.5;
            let mut ray = Ray::new(origin, (target - origin).normalize());
            // A third of the rays without a cone (level 0 everywhere), the others widening.
            if i % 3 > 0 {
                ray.cone = RayCone { width: 0.0, spread: rng.random::<f32>() * 0.01 };
            }
            let expected = brute_force(&s, lod, &groups, &ray);
            let got = accel.intersect(&ray);
            match (got, expected) {
                (Some(h), Some(e)) => {
                    assert!((h.t - e.0).abs() <= 1e-5 * e.0, "ray {i}: {h:?} vs {e:?}");
                    assert_eq!((h.prim, h.level), (e.1, e.2), "ray {i}");
                    assert_eq!(h.radius_scale, lod.radius_scale(h.level));
                    if i % 3 == 0 {
                        assert_eq!(h.level, 0);
                    }
                    hits += 1;
                    coarse += (h.level > 1) as u32;
                }
                (None, None) => {}
                (g, e) => panic!("ray {i}: {g:?} vs {e:?}"),
            }
            // Shadow rays (transmittance through opaque strands) and the multi-hit query see
            // the same levels.
            let blocked = accel.transmittance_cone(ray.origin, ray.dir, 12.0, None, ray.cone, None) == 0.0;
            assert_eq!(blocked, expected.is_some_and(|e| e.0 < 12.0), "ray {i}");
            accel.intersect_k(&ray, 0.0, 3, &[], None, &mut layers);
            assert_eq!(layers.first().map(|l| (l.hit.prim, l.hit.level)), expected.map(|e| (e.1, e.2)), "ray {i}");
        }
        assert!(hits > 300 && coarse > 50, "the test needs hits at coarse levels: {hits} {coarse}");
    }

    /// The closest hit of a ray along -z through (x, y) on `accel`, seen at exactly
    /// `level` whatever the segment's jitter (a constant footprint `d^(level - 1/128)`
    /// times `start * width`; jitters lie in [1/64, 63/64]).
    fn hit_at_level(accel: &Accel, x: f32, y: f32, level: u32) -> Option<crate::accel::Hit> {
        let lod = accel.objects[0].lod().unwrap();
        let p = lod.params();
        let footprint = p.start * lod.width() * p.decimation.powf(level as f32 - 1.0 / 128.0);
        let mut ray = Ray::new(Vec3::new(x, y, 1.0), -Vec3::Z);
        ray.cone = RayCone { width: footprint, spread: 0.0 };
        let hit = accel.intersect(&ray);
        if let Some(h) = hit {
            assert_eq!(h.level, level, "ray at ({x}, {y})");
        }
        hit
    }

    #[test]
    fn simplified_levels_skip_every_other_point_and_keep_the_ends() {
        // A zigzag: the odd points stand 0.1 off the line through the even ones.
        let mut s = StrandSet::new();
        s.push_strand((0..5).map(|i| (Vec3::new(i as f32 * 0.25, 0.1 * (i % 2) as f32, 0.0), 0.01)));
        let p = LodParams { levels: 4, simplify: 2, ..Default::default() };
        let accel = Accel::build_with_lod(vec![(Shape::Strands(s.clone()), 0, Some(p))]);
        let full = Accel::build_with_lod(vec![(Shape::Strands(s), 0, Some(LodParams { simplify: 0, ..p }))]);
        // One strand lives at every level. Below `simplify`, the odd points are there and
        // the chords between even points are not; from it on, the other way round.
        for level in 0..4 {
            let simplified = level >= 2;
            for x in [0.25, 0.75] {
                assert_eq!(hit_at_level(&accel, x, 0.1, level).is_some(), !simplified, "level {level}, x {x}");
                assert_eq!(hit_at_level(&accel, x, 0.0, level).is_some(), simplified, "level {level}, x {x}");
                // Without simplification the odd points stay at every level.
                assert!(hit_at_level(&full, x, 0.1, level).is_some());
            }
            // The end points are kept.
            for x in [0.01, 0.99] {
                assert!(hit_at_level(&accel, x, 0.0, level).is_some(), "level {level}, end {x}");
            }
        }
        // A hit on a chord is put on the segment it stands for, at the same fraction of
        // the pair's length (both segments of a pair are equally long here).
        let h = hit_at_level(&accel, 0.2, 0.0, 2).unwrap();
        let HitKind::Segment { s: along, .. } = h.kind else { panic!() };
        assert_eq!(h.prim, 0);
        assert!((along - 0.8).abs() < 1e-3, "{along}");
        let h = hit_at_level(&accel, 0.8, 0.0, 3).unwrap();
        let HitKind::Segment { s: along, .. } = h.kind else { panic!() };
        assert_eq!(h.prim, 3);
        assert!((along - 0.2).abs() < 1e-3, "{along}");
    }

    #[test]
    fn simplified_strands_stay_within_the_chord_deviation_of_their_curve() {
        // Quarter circles of radius 1 in the plane z = 0, nine points each: a chord over
        // two segments (22.5 degrees) departs from the arc by 1 - cos(11.25 deg) = 0.0192.
        let (r, deviation) = (0.02f32, 1.0 - 11.25f32.to_radians().cos());
        let arc = |i: usize, n: usize, radius: f32| {
            let a = std::f32::consts::FRAC_PI_2 * i as f32 / (n - 1) as f32;
            Vec3::new(a.cos(), a.sin(), 0.0) * radius
        };
        let mut s = StrandSet::new();
        s.push_strand((0..9).map(|i| (arc(i, 9, 1.0), r)));
        let p = LodParams { levels: 4, simplify: 1, ..Default::default() };
        let accel = Accel::build_with_lod(vec![(Shape::Strands(s), 0, Some(p))]);
        let lod = accel.objects[0].lod().unwrap();
        for level in 1..4 {
            let widened = r * lod.radius_scale(level);
            assert!(widened > deviation, "the test needs strands wider than the chords depart");
            for i in 0..200 {
                // Every point of the curve is covered, the ends included.
                let on = arc(i, 200, 1.0);
                assert!(hit_at_level(&accel, on.x, on.y, level).is_some(), "level {level}, point {i}");
                // Nothing lies farther from the curve than the widened radius plus the
                // chords' deviation (the chords lie inside the arc).
                for radius in [1.0 - widened - deviation - 0.005, 1.0 + widened + 0.005] {
                    let off = arc(i, 200, radius);
                    assert!(hit_at_level(&accel, off.x, off.y, level).is_none(), "level {level}, {off}");
                }
            }
        }
    }

    #[test]
    fn a_camera_bounds_the_level_and_leaves_camera_rays_as_they_were() {
        let s = curtain(3000, 0.0005, 7); // width 0.001
        let p = LodParams { spread: 4.0, ..Default::default() };
        // From 2 away a pixel covers 4 widths: camera rays take level 3 or 4 (log_1.5 4 = 3.4).
        let camera = LodCamera { eye: Vec3::new(0.5, 0.5, 2.0), cone: RayCone { width: 0.0, spread: 0.002 } };
        let free = Accel::build_with_lod(vec![(Shape::Strands(s.clone()), 0, Some(p))]);
        let seen = Accel::build_with_lod_for(vec![(Shape::Strands(s), 0, Some(p))], Some(camera));
        let mut rng = GenRng::seed_from_u64(14);
        let (mut hits, mut wide_hits, mut differ) = (0, 0, 0);
        for i in 0..4000 {
            let target = Vec3::new(rng.random(), 0.1 + 0.8 * rng.random::<f32>(), 0.0);
            let mut ray = Ray::new(camera.eye, (target - camera.eye).normalize());
            ray.cone = camera.cone;
            if i % 2 == 0 {
                // A camera ray sees the same hits, but where a segment straddles a level
                // change (the camera's level is read at its midpoint, the ray's at the hit).
                let (a, b) = (free.intersect(&ray), seen.intersect(&ray));
                differ += (a.map(|h| (h.prim, h.level)) != b.map(|h| (h.prim, h.level))) as u32;
                for h in [a, b].into_iter().flatten() {
                    assert!((3..=4).contains(&h.level), "ray {i}: {h:?}");
                }
                hits += a.is_some() as u32;
            } else {
                // A ten times wider ray is pruned to the coarsest level, or to the camera's.
                ray.cone.spread *= 10.0;
                if let Some(h) = free.intersect(&ray) {
                    assert_eq!(h.level, 7, "ray {i}");
                }
                if let Some(h) = seen.intersect(&ray) {
                    assert!((3..=4).contains(&h.level), "ray {i}: {h:?}");
                    wide_hits += 1;
                }
            }
        }
        assert!(hits > 300 && wide_hits > 300, "the test needs hits: {hits} {wide_hits}");
        assert!(differ * 50 < hits, "{differ} of {hits} camera rays differ");
        // The boxes are widened for the camera's levels only: 4 times the radius scale of
        // level 4 at most, instead of level 7's (0.0085 against 0.034 off the plane).
        let depth = |a: &Accel| a.bounds().max.z - a.bounds().min.z;
        assert!(depth(&seen) < 0.5 * depth(&free), "{} vs {}", depth(&seen), depth(&free));
    }

    #[test]
    fn contrast_moves_colours_toward_the_mean() {
        let mut s = curtain(2, 0.01, 1);
        let n = s.points.len();
        s.colors = Some((0..n).map(|i| if i < n / 2 { [1.0, 0.0, 0.0] } else { [0.0, 0.0, 1.0] }).collect());
        let off = StrandLod::build(&s, LodParams::default(), 0).unwrap();
        let on = StrandLod::build(&s, LodParams { contrast: true, ..Default::default() }, 0).unwrap();
        let red = Some(Vec3::X);
        assert_eq!(off.color(4, red), red);
        assert_eq!(on.color(0, red), red);
        let mean = on.mean_color.unwrap();
        let c = on.color(2, red).unwrap();
        // Level 2 with d = 1.5: deviation scaled by 1/1.5.
        assert!((c - (mean + (Vec3::X - mean) / 1.5)).length() < 1e-6, "{c} {mean}");
    }
}
