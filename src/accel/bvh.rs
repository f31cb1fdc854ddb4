//! A 4-wide bounding volume hierarchy. It is built as a binary tree with the binned surface
//! area heuristic (Wald 2007, "On fast Construction of SAH-based Bounding Volume
//! Hierarchies"), in parallel with rayon, then collapsed into nodes of four children
//! (Dammertz et al. 2008, "Shallow Bounding Volume Hierarchies for Fast SIMD Ray Tracing
//! of Incoherent Rays"), whose boxes one ray tests at once with 4-wide SIMD.
//!
//! The BVH stores no primitives, only `u32` item ids (a triangle index, or the first point
//! of a hair segment); callers intersect items through a callback.

use crate::math::Aabb;
use glam::{Vec3, Vec3A};
use rayon::prelude::*;
use wide::{bytemuck, f32x4, u32x4};

/// A node of four children. Their boxes are stored on an 8-bit grid spanning the node's
/// own box (Mahovsky 2005, "Ray Tracing with Reduced-Precision Bounding Volume Hierarchies";
/// Ylitie et al. 2017, "Efficient Incoherent Ray Traversal on GPUs Through Compressed Wide
/// BVHs"), rounded outwards, so a node is 64 bytes, one cache line, instead of 128 with
/// float boxes. The grid loosens each box by at most 1/255 of the parent's extent.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(64))]
struct Node4 {
    /// World position of grid point 0 (the minimum corner of the node's box).
    origin: [f32; 3],
    /// World size of one grid step along each axis (positive).
    step: [f32; 3],
    /// Child boxes in grid steps, one lane per child: min x, y, z then max x, y, z.
    planes: [[u8; 4]; 6],
    /// Inner child: index of its node. Leaf child: index of its first item, with the item
    /// count (1 to `MAX_LEAF`) in the top [`COUNT_BITS`] bits. [`NO_CHILD`] marks an unused slot.
    child: [u32; 4],
}

/// Bits of [`Node4::child`] holding a leaf's item count.
const COUNT_BITS: u32 = 4;
/// Bits of [`Node4::child`] holding a node or item index.
const INDEX_BITS: u32 = 32 - COUNT_BITS;
/// Most items (and nodes) one hierarchy can index.
pub const MAX_ITEMS: usize = (1 << INDEX_BITS) - 1;
/// The index part of [`Node4::child`].
const INDEX_MASK: u32 = (1 << INDEX_BITS) - 1;
/// An unused child slot.
const NO_CHILD: u32 = u32::MAX;

const EMPTY_NODE: Node4 = Node4 { origin: [0.0; 3], step: [1.0; 3], planes: [[0; 4]; 6], child: [NO_CHILD; 4] };

/// A bounding volume hierarchy over items.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node4>,
    items: Vec<u32>,
    bounds: Option<Aabb>,
}

/// A ray prepared for box tests.
#[derive(Clone, Copy, Debug)]
pub struct RayBoxTest {
    origin: Vec3,
    inv_dir: Vec3,
    /// Per axis, the row of [`Node4::planes`] the ray meets first: the minimum plane (0 to
    /// 2) for a positive direction, the maximum (3 to 5) for a negative one.
    near_row: [usize; 3],
}

/// Four grid coordinates as floats.
#[inline(always)]
fn widen(q: [u8; 4]) -> f32x4 {
    #[cfg(target_arch = "x86_64")]
    {
        // Zero-extend the bytes to 32-bit lanes and convert: four SSE2 instructions (SSE2
        // is part of every x86-64 CPU), where the portable form converts lane by lane.
        use std::arch::x86_64::{
            _mm_cvtepi32_ps, _mm_cvtsi32_si128, _mm_setzero_si128, _mm_unpacklo_epi16, _mm_unpacklo_epi8,
        };
        // SAFETY: these intrinsics only need SSE2, which every x86-64 target enables.
        unsafe {
            let zero = _mm_setzero_si128();
            let bytes = _mm_cvtsi32_si128(i32::from_le_bytes(q));
            bytemuck::cast(_mm_cvtepi32_ps(_mm_unpacklo_epi16(_mm_unpacklo_epi8(bytes, zero), zero)))
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    f32x4::new(q.map(f32::from))
}

impl RayBoxTest {
    /// Precomputes the reciprocal direction. Zero components are replaced by a tiny value
    /// of the same sign, so no test multiplies zero by infinity (Embree does the same).
    #[inline]
    pub fn new(origin: Vec3, dir: Vec3) -> RayBoxTest {
        let safe = |d: f32| if d.abs() < 1e-18 { 1e-18f32.copysign(d) } else { d };
        let inv_dir = Vec3::new(1.0 / safe(dir.x), 1.0 / safe(dir.y), 1.0 / safe(dir.z));
        let row = |axis: usize| if inv_dir[axis] >= 0.0 { axis } else { axis + 3 };
        RayBoxTest { origin, inv_dir, near_row: [row(0), row(1), row(2)] }
    }

    /// Entry distances of the ray into a node's four boxes and the mask of boxes entered
    /// before `tmax` (slab test on four boxes at once; Kay & Kajiya 1986, with the near and
    /// far planes chosen by the direction's signs as in Williams et al. 2005).
    #[inline(always)]
    fn enter4(&self, node: &Node4, tmax: f32) -> ([f32; 4], u32) {
        // A plane at grid coordinate q lies at origin + q step, which the ray meets at
        // t = q (step / dir) + (origin - o) / dir: one multiply-add per plane.
        let slab = |axis: usize| {
            let scale = f32x4::splat(node.step[axis] * self.inv_dir[axis]);
            let base = f32x4::splat((node.origin[axis] - self.origin[axis]) * self.inv_dir[axis]);
            let near = self.near_row[axis];
            let far = if near < 3 { near + 3 } else { near - 3 };
            (widen(node.planes[near]) * scale + base, widen(node.planes[far]) * scale + base)
        };
        let (nx, fx) = slab(0);
        let (ny, fy) = slab(1);
        let (nz, fz) = slab(2);
        let near = nx.fast_max(ny).fast_max(nz.fast_max(f32x4::ZERO));
        // A tiny relative slack keeps boxes of zero thickness (flat meshes) and the rounding
        // of the plane distances from losing grazing rays.
        let far = fx.fast_min(fy).fast_min(fz.fast_min(f32x4::splat(tmax))) * f32x4::splat(1.0 + 8.0 * f32::EPSILON);
        let used = u32x4::new(node.child).simd_ne(u32x4::splat(NO_CHILD));
        let mask = near.simd_le(far).to_bitmask() & used.to_bitmask();
        (near.to_array(), mask)
    }
}

/// A reference to a child on the traversal stack: a node, or a leaf's item range.
#[derive(Clone, Copy, Debug, Default)]
struct Entry {
    /// Node index, or first item of a leaf.
    index: u32,
    /// Item count of a leaf; 0 for a node.
    count: u8,
    /// Distance at which the ray enters the child's box.
    t: f32,
}

impl Bvh {
    /// Bounds of everything in the hierarchy.
    pub fn bounds(&self) -> Aabb {
        self.bounds.unwrap_or(Aabb::EMPTY)
    }

    /// Number of nodes.
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// Bytes held by nodes and item ids.
    pub fn memory_bytes(&self) -> usize {
        self.nodes.len() * std::mem::size_of::<Node4>() + self.items.len() * 4
    }

    /// Visits the leaves the ray enters before `*tmax`, nearest boxes first.
    /// `visit(ids, tmax)` intersects a leaf's items (at most [`MAX_LEAF`]), shortens `*tmax`
    /// on a hit, and returns true to stop the traversal (any-hit queries).
    #[inline]
    pub fn traverse(&self, ray: &RayBoxTest, tmax: &mut f32, mut visit: impl FnMut(&[u32], &mut f32) -> bool) {
        if self.nodes.is_empty() {
            return;
        }
        // The binary tree is at most MAX_DEPTH + 32 levels deep (past MAX_DEPTH the builder
        // halves by count, and there are fewer than 2^32 items); each 4-wide level, at
        // least one binary level, pushes at most three entries.
        // Left uninitialised: zeroing it would cost more than a short traversal.
        let mut stack = [std::mem::MaybeUninit::<Entry>::uninit(); 3 * (MAX_DEPTH + 32) + 4];
        let mut top = 0usize;
        let mut current = Entry { index: 0, count: 0, t: 0.0 };
        loop {
            if current.count > 0 {
                let first = current.index as usize;
                if visit(&self.items[first..first + current.count as usize], tmax) {
                    return;
                }
            } else {
                let node = &self.nodes[current.index as usize];
                let (near, mut mask) = ray.enter4(node, *tmax);
                if mask != 0 {
                    // Children hit, nearest first: insertion sort of at most four.
                    let mut hits = [Entry::default(); 4];
                    let mut n = 0;
                    while mask != 0 {
                        let i = mask.trailing_zeros() as usize;
                        mask &= mask - 1;
                        let child = node.child[i];
                        let e = Entry { index: child & INDEX_MASK, count: (child >> INDEX_BITS) as u8, t: near[i] };
                        let mut k = n;
                        while k > 0 && hits[k - 1].t > e.t {
                            hits[k] = hits[k - 1];
                            k -= 1;
                        }
                        hits[k] = e;
                        n += 1;
                    }
                    for e in hits[1..n].iter().rev() {
                        stack[top].write(*e);
                        top += 1;
                    }
                    current = hits[0];
                    continue;
                }
            }
            // Pop the next child the ray still reaches.
            loop {
                if top == 0 {
                    return;
                }
                top -= 1;
                // SAFETY: entries below `top` were written by the push above.
                let e = unsafe { stack[top].assume_init() };
                if e.t <= *tmax {
                    current = e;
                    break;
                }
            }
        }
    }
}

/// What a build needs to know about an item.
#[derive(Clone, Copy, Debug)]
pub struct BuildItem {
    /// Bounds of the item.
    pub bounds: Aabb,
    /// Id reported back to the intersection callback.
    pub id: u32,
}

const BINS: usize = 32;
/// Most items in a leaf.
pub const MAX_LEAF: usize = 8;
/// Cost of visiting a node relative to intersecting one item (SAH constants). Leaves test
/// four segments at once, so items are cheap next to nodes: measured on the hairy torus
/// (docs/performance.md), 4 gives the same speed as 1 with 60 % less BVH memory.
const TRAVERSAL_COST: f32 = 4.0;
/// Subtrees at least this big are built on another rayon task.
const PARALLEL_THRESHOLD: usize = 4096;

enum BuildNode {
    Leaf { bounds: Aabb, first: usize, count: usize },
    Inner { bounds: Aabb, children: Box<[BuildNode; 2]> },
}

impl BuildNode {
    fn bounds(&self) -> Aabb {
        match self {
            BuildNode::Leaf { bounds, .. } | BuildNode::Inner { bounds, .. } => *bounds,
        }
    }
}

impl Bvh {
    /// Builds the hierarchy. Items with empty or non-finite bounds are dropped: they can
    /// never be hit and would poison the heuristic. Only the first [`MAX_ITEMS`] items are
    /// indexed (scene loading rejects larger objects with an error before they get here).
    pub fn build(mut items: Vec<BuildItem>) -> Bvh {
        items.retain(|it| !it.bounds.is_empty() && it.bounds.min.is_finite() && it.bounds.max.is_finite());
        items.truncate(MAX_ITEMS);
        if items.is_empty() {
            return Bvh::default();
        }
        let root = build_node(&mut items, 0, 0);
        let mut nodes = Vec::with_capacity(items.len() / 4 + 1);
        nodes.push(EMPTY_NODE);
        let bounds = match &root {
            BuildNode::Leaf { bounds, .. } => {
                // A single leaf still needs a node to hang from.
                let grid = Grid::spanning(*bounds);
                (nodes[0].origin, nodes[0].step) = (grid.origin.into(), grid.step.into());
                set_child(&mut nodes[0], &grid, 0, &root, 0);
                *bounds
            }
            BuildNode::Inner { bounds, .. } => {
                collapse(&root, 0, &mut nodes);
                *bounds
            }
        };
        Bvh { nodes, items: items.into_iter().map(|it| it.id).collect(), bounds: Some(bounds) }
    }
}

/// Deepest tree the traversal stack can hold; below it, nodes become leaves.
const MAX_DEPTH: usize = 60;

/// Builds the subtree over `items`, which start at index `offset` of the whole item array.
fn build_node(items: &mut [BuildItem], offset: usize, depth: usize) -> BuildNode {
    let (bounds, centroids) = bounds_and_centroids(items);
    let leaf = |items: &[BuildItem]| BuildNode::Leaf { bounds, first: offset, count: items.len() };
    if items.len() <= 2 {
        return leaf(items);
    }
    // Past the depth the traversal stack is sized for, split by count (the tree then
    // deepens by one level per halving, so this cannot recurse without end).
    let split = if depth >= MAX_DEPTH { None } else { choose_split(items, &bounds, &centroids) };
    let mid = match split {
        Some((axis, lo, scale, bin)) => partition(items, |it| bin_of(it.bounds.center()[axis], lo, scale) < bin),
        None if items.len() > MAX_LEAF => {
            // Centroids coincide: split by count so leaves stay small.
            items.len() / 2
        }
        None => return leaf(items),
    };
    let mid = if mid == 0 || mid == items.len() { items.len() / 2 } else { mid };
    let (left, right) = items.split_at_mut(mid);
    let (l, r) = if left.len() + right.len() >= PARALLEL_THRESHOLD {
        rayon::join(|| build_node(left, offset, depth + 1), || build_node(right, offset + mid, depth + 1))
    } else {
        (build_node(left, offset, depth + 1), build_node(right, offset + mid, depth + 1))
    };
    BuildNode::Inner { bounds, children: Box::new([l, r]) }
}

/// Items per parallel task when scanning the large nodes near the root (which alone hold
/// most of the build's sequential work).
const SCAN_CHUNK: usize = 16 * 1024;

/// Bounds of the items' boxes and of their centroids, in parallel for large sets.
fn bounds_and_centroids(items: &[BuildItem]) -> (Aabb, Aabb) {
    let scan = |items: &[BuildItem]| {
        items.iter().fold((Aabb::EMPTY, Aabb::EMPTY), |(b, c), it| (b.union(it.bounds), c.grow(it.bounds.center())))
    };
    if items.len() < 2 * SCAN_CHUNK {
        return scan(items);
    }
    items
        .par_chunks(SCAN_CHUNK)
        .map(scan)
        .reduce(|| (Aabb::EMPTY, Aabb::EMPTY), |a, b| (a.0.union(b.0), a.1.union(b.1)))
}

/// The bin of a centroid coordinate; the split and the partition both use it, so an item
/// goes to the side its bin was counted on.
#[inline]
fn bin_of(c: f32, lo: f32, scale: f32) -> usize {
    (((c - lo) * scale) as usize).min(BINS - 1)
}

/// Boxes and counts of the items falling in each bin, along each axis.
#[derive(Clone, Copy)]
struct Bins {
    bounds: [[Aabb; BINS]; 3],
    counts: [[u32; BINS]; 3],
}

impl Bins {
    const EMPTY: Bins = Bins { bounds: [[Aabb::EMPTY; BINS]; 3], counts: [[0; BINS]; 3] };

    fn merge(mut self, o: Bins) -> Bins {
        for axis in 0..3 {
            for b in 0..BINS {
                self.bounds[axis][b] = self.bounds[axis][b].union(o.bounds[axis][b]);
                self.counts[axis][b] += o.counts[axis][b];
            }
        }
        self
    }
}

/// The binned SAH split (axis, bin origin, bin scale, first bin of the right side), or None
/// when no split beats a leaf (or the items' centroids coincide).
fn choose_split(items: &[BuildItem], bounds: &Aabb, centroids: &Aabb) -> Option<(usize, f32, f32, usize)> {
    let extent = centroids.max - centroids.min;
    let scale = Vec3A::select(extent.cmpgt(Vec3A::ZERO), BINS as f32 / extent, Vec3A::ZERO);
    let fill = |items: &[BuildItem]| {
        let mut bins = Bins::EMPTY;
        for it in items {
            let c = it.bounds.center();
            for axis in 0..3 {
                let b = bin_of(c[axis], centroids.min[axis], scale[axis]);
                bins.bounds[axis][b] = bins.bounds[axis][b].union(it.bounds);
                bins.counts[axis][b] += 1;
            }
        }
        bins
    };
    let bins = if items.len() < 2 * SCAN_CHUNK {
        fill(items)
    } else {
        items.par_chunks(SCAN_CHUNK).map(fill).reduce(|| Bins::EMPTY, Bins::merge)
    };
    let mut best: Option<(f32, usize, usize)> = None;
    for axis in 0..3 {
        if scale[axis] <= 0.0 {
            continue;
        }
        let (bin_bounds, bin_counts) = (&bins.bounds[axis], &bins.counts[axis]);
        // Sweep from the right to get the cost of every right side, then from the left.
        let mut right_area = [0.0f32; BINS];
        let mut right_count = [0u32; BINS];
        let (mut acc, mut n) = (Aabb::EMPTY, 0);
        for i in (1..BINS).rev() {
            acc = acc.union(bin_bounds[i]);
            n += bin_counts[i];
            right_area[i] = acc.half_area();
            right_count[i] = n;
        }
        let (mut acc, mut n) = (Aabb::EMPTY, 0);
        for i in 0..BINS - 1 {
            acc = acc.union(bin_bounds[i]);
            n += bin_counts[i];
            let cost = acc.half_area() * n as f32 + right_area[i + 1] * right_count[i + 1] as f32;
            if n > 0 && right_count[i + 1] > 0 && best.is_none_or(|(c, _, _)| cost < c) {
                best = Some((cost, axis, i + 1));
            }
        }
    }
    let (cost, axis, bin) = best?;
    let leaf_cost = items.len() as f32 * bounds.half_area();
    let split_cost = TRAVERSAL_COST * bounds.half_area() + cost;
    (split_cost < leaf_cost || items.len() > MAX_LEAF).then_some((axis, centroids.min[axis], scale[axis], bin))
}

/// Moves items for which `left` holds to the front; returns how many there are.
fn partition(items: &mut [BuildItem], left: impl Fn(&BuildItem) -> bool) -> usize {
    let mut mid = 0;
    for i in 0..items.len() {
        if left(&items[i]) {
            items.swap(i, mid);
            mid += 1;
        }
    }
    mid
}

/// Writes the 4-wide node for binary inner node `node` at `nodes[at]`, and its subtree
/// after it: the node's children are opened, largest box first, until there are four.
fn collapse(node: &BuildNode, at: usize, nodes: &mut Vec<Node4>) {
    let mut children: Vec<&BuildNode> = match node {
        BuildNode::Inner { children, .. } => vec![&children[0], &children[1]],
        BuildNode::Leaf { .. } => vec![node],
    };
    while children.len() < 4 {
        let open = children
            .iter()
            .enumerate()
            .filter(|(_, c)| matches!(c, BuildNode::Inner { .. }))
            .max_by(|a, b| a.1.bounds().half_area().total_cmp(&b.1.bounds().half_area()))
            .map(|(i, _)| i);
        let Some(i) = open else { break };
        let BuildNode::Inner { children: grand, .. } = children.swap_remove(i) else { unreachable!() };
        children.push(&grand[0]);
        children.push(&grand[1]);
    }
    let grid = Grid::spanning(children.iter().fold(Aabb::EMPTY, |b, c| b.union(c.bounds())));
    nodes[at].origin = grid.origin.into();
    nodes[at].step = grid.step.into();
    for (slot, child) in children.into_iter().enumerate() {
        let index = match child {
            BuildNode::Leaf { .. } => 0,
            BuildNode::Inner { .. } => {
                nodes.push(EMPTY_NODE);
                nodes.len() - 1
            }
        };
        set_child(&mut nodes[at], &grid, slot, child, index as u32);
        if index > 0 {
            collapse(child, index, nodes);
        }
    }
}

/// The 8-bit grid of a node: 255 steps across its box along each axis.
struct Grid {
    origin: Vec3,
    step: Vec3,
}

impl Grid {
    /// The grid whose 256 planes along each axis span `bounds`: the last plane lies at or
    /// beyond the maximum in f32 arithmetic, and steps are never zero.
    fn spanning(bounds: Aabb) -> Grid {
        let (origin, max) = (Vec3::from(bounds.min), Vec3::from(bounds.max));
        let mut step = ((max - origin) / 255.0).max(Vec3::splat(f32::MIN_POSITIVE));
        for axis in 0..3 {
            while origin[axis] + 255.0 * step[axis] < max[axis] {
                step[axis] = step[axis].next_up();
            }
        }
        Grid { origin, step }
    }

    /// The grid interval holding `[min, max]` along `axis`, rounded outwards in the same f32
    /// arithmetic as the decoding: planes `lo` and `hi` with `origin + lo step <= min` and
    /// `origin + hi step >= max`.
    fn quantise(&self, axis: usize, min: f32, max: f32) -> (u8, u8) {
        let (o, h) = (self.origin[axis], self.step[axis]);
        let plane = |q: f32| o + q * h;
        let mut lo = ((min - o) / h).floor().clamp(0.0, 255.0);
        while lo > 0.0 && plane(lo) > min {
            lo -= 1.0;
        }
        let mut hi = ((max - o) / h).ceil().clamp(0.0, 255.0);
        while hi < 255.0 && plane(hi) < max {
            hi += 1.0;
        }
        (lo as u8, hi as u8)
    }
}

/// Fills slot `slot` of `node` with `child` (a leaf, or the inner node at `index`), its box
/// on the node's `grid`.
fn set_child(node: &mut Node4, grid: &Grid, slot: usize, child: &BuildNode, index: u32) {
    let b = child.bounds();
    for axis in 0..3 {
        let (lo, hi) = grid.quantise(axis, b.min[axis], b.max[axis]);
        node.planes[axis][slot] = lo;
        node.planes[axis + 3][slot] = hi;
    }
    node.child[slot] = match child {
        BuildNode::Leaf { first, count, .. } => *first as u32 | (*count as u32) << INDEX_BITS,
        BuildNode::Inner { .. } => index,
    };
}
