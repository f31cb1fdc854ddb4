//! An 8-wide bounding volume hierarchy. It is built as a binary tree with the binned surface
//! area heuristic (Wald 2007, "On fast Construction of SAH-based Bounding Volume
//! Hierarchies"), in parallel with rayon, then collapsed into nodes of eight children
//! (Dammertz et al. 2008, "Shallow Bounding Volume Hierarchies for Fast SIMD Ray Tracing
//! of Incoherent Rays"; Wald et al. 2014, "Embree"), whose boxes one ray tests at once with
//! SIMD, boxes stored quantised to 8 bits.
//!
//! The BVH stores no primitives, only `u32` item ids (a triangle index, or the first point
//! of a hair segment); callers intersect items through a callback.
//!
//! Items may carry a small tag (level of detail: the widest level a hair segment is drawn
//! at); a leaf hands the largest of its items' tags to the callback.

use crate::math::{Aabb, RayMask, PACKET};
use glam::{Vec3, Vec3A};
use rayon::prelude::*;
use wide::{bytemuck, f32x4, f32x8, u32x4};

/// Children per node.
const WIDTH: usize = 8;

/// A node of eight children. Their boxes are stored on an 8-bit grid spanning the node's
/// own box (Mahovsky 2005, "Ray Tracing with Reduced-Precision Bounding Volume Hierarchies";
/// Ylitie et al. 2017, "Efficient Incoherent Ray Traversal on GPUs Through Compressed Wide
/// BVHs"), rounded outwards: 104 bytes of data per eight children, where float boxes take
/// 224. The grid loosens each box by at most 1/255 of the parent's extent.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(64))]
struct Node {
    /// World position of grid point 0 (the minimum corner of the node's box).
    origin: [f32; 3],
    /// World size of one grid step along each axis (positive).
    step: [f32; 3],
    /// Child boxes in grid steps, one lane per child: min x, y, z then max x, y, z.
    planes: [[u8; WIDTH]; 6],
    /// Inner child: index of its node. Leaf child: index of its first item, with the item
    /// count (1 to `MAX_LEAF`) in the top [`COUNT_BITS`] bits. [`NO_CHILD`] marks an unused slot.
    child: [u32; WIDTH],
    /// Per child, the largest [`BuildItem::tag`] below it. The node's 104 bytes of data
    /// above leave 24 of its 128 free: this costs no memory.
    tag: [u8; WIDTH],
}

/// Bits of [`Node::child`] holding a leaf's item count.
const COUNT_BITS: u32 = 4;
/// Bits of [`Node::child`] holding a node or item index.
const INDEX_BITS: u32 = 32 - COUNT_BITS;
/// Most items (and nodes) one hierarchy can index.
pub const MAX_ITEMS: usize = (1 << INDEX_BITS) - 1;
/// The index part of [`Node::child`].
const INDEX_MASK: u32 = (1 << INDEX_BITS) - 1;
/// An unused child slot.
const NO_CHILD: u32 = u32::MAX;

const EMPTY_NODE: Node =
    Node { origin: [0.0; 3], step: [1.0; 3], planes: [[0; WIDTH]; 6], child: [NO_CHILD; WIDTH], tag: [0; WIDTH] };

/// A bounding volume hierarchy over items.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
    items: Vec<u32>,
    bounds: Option<Aabb>,
}

/// A ray prepared for box tests.
#[derive(Clone, Copy, Debug)]
pub struct RayBoxTest {
    origin: Vec3,
    inv_dir: Vec3,
    /// Boxes the ray leaves before this distance are not entered.
    tmin: f32,
}

impl RayBoxTest {
    /// Precomputes the reciprocal direction. Zero components are replaced by a tiny value
    /// of the same sign, so no test multiplies zero by infinity (Embree does the same).
    /// Boxes are entered only where the ray is beyond `tmin` (0 for a whole ray; a query
    /// that continues past hits it already has starts there).
    #[inline]
    pub fn new(origin: Vec3, dir: Vec3, tmin: f32) -> RayBoxTest {
        let safe = |d: f32| if d.abs() < 1e-18 { 1e-18f32.copysign(d) } else { d };
        let inv_dir = Vec3::new(1.0 / safe(dir.x), 1.0 / safe(dir.y), 1.0 / safe(dir.z));
        RayBoxTest { origin, inv_dir, tmin: tmin.max(0.0) }
    }

    /// Per axis, the factors that turn a grid coordinate q of `node` into the distance at
    /// which the ray meets that plane: the plane lies at origin + q step, so
    /// t = q (step / dir) + (origin - o) / dir, one multiply-add per plane.
    #[inline(always)]
    fn plane_factors(&self, node: &Node) -> ([f32; 3], [f32; 3]) {
        let (step, origin) = (Vec3::from(node.step), Vec3::from(node.origin));
        ((step * self.inv_dir).into(), ((origin - self.origin) * self.inv_dir).into())
    }
}

/// Relative slack on the exit distance: it keeps boxes of zero thickness (flat meshes) and
/// the rounding of the plane distances from losing grazing rays.
const EXIT_SLACK: f32 = 1.0 + 8.0 * f32::EPSILON;

/// The slab test (Kay & Kajiya 1986) of a ray against a node's eight boxes: the distances
/// at which the ray enters them, and the mask of boxes entered before `tmax`. Portable
/// 4-wide SIMD, two halves.
#[inline(always)]
fn enter_portable(ray: &RayBoxTest, node: &Node, tmax: f32) -> ([f32; WIDTH], u32) {
    let (scale, base) = ray.plane_factors(node);
    let mut near = [0.0; WIDTH];
    let mut mask = 0;
    for half in 0..2 {
        let lanes = |row: usize| -> [u8; 4] { node.planes[row][4 * half..4 * half + 4].try_into().unwrap_or([0; 4]) };
        let slab = |a: usize| {
            let (s, b) = (f32x4::splat(scale[a]), f32x4::splat(base[a]));
            let (t0, t1) = (widen4(lanes(a)) * s + b, widen4(lanes(a + 3)) * s + b);
            (t0.fast_min(t1), t0.fast_max(t1))
        };
        let ((nx, fx), (ny, fy), (nz, fz)) = (slab(0), slab(1), slab(2));
        let n = nx.fast_max(ny).fast_max(nz.fast_max(f32x4::splat(ray.tmin)));
        let f = fx.fast_min(fy).fast_min(fz.fast_min(f32x4::splat(tmax))) * f32x4::splat(EXIT_SLACK);
        let child: [u32; 4] = node.child[4 * half..4 * half + 4].try_into().unwrap_or([NO_CHILD; 4]);
        let used = u32x4::new(child).simd_ne(u32x4::splat(NO_CHILD));
        mask |= (n.simd_le(f).to_bitmask() & used.to_bitmask()) << (4 * half);
        near[4 * half..4 * half + 4].copy_from_slice(&n.to_array());
    }
    (near, mask)
}

/// Four grid coordinates as floats.
#[inline(always)]
fn widen4(q: [u8; 4]) -> f32x4 {
    f32x4::new(q.map(f32::from))
}

/// [`enter_portable`] with AVX2 and FMA: all eight boxes in one 8-wide pass.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn enter_avx2(ray: &RayBoxTest, node: &Node, tmax: f32) -> ([f32; WIDTH], u32) {
    use std::arch::x86_64::*;
    let (scale, base) = ray.plane_factors(node);
    let mut near = _mm256_set1_ps(ray.tmin);
    let mut far = _mm256_set1_ps(tmax);
    for a in 0..3 {
        let (s, b) = (_mm256_set1_ps(scale[a]), _mm256_set1_ps(base[a]));
        let lo = _mm256_cvtepi32_ps(_mm256_cvtepu8_epi32(_mm_cvtsi64_si128(i64::from_le_bytes(node.planes[a]))));
        let hi = _mm256_cvtepi32_ps(_mm256_cvtepu8_epi32(_mm_cvtsi64_si128(i64::from_le_bytes(node.planes[a + 3]))));
        let (t0, t1) = (_mm256_fmadd_ps(lo, s, b), _mm256_fmadd_ps(hi, s, b));
        near = _mm256_max_ps(near, _mm256_min_ps(t0, t1));
        far = _mm256_min_ps(far, _mm256_max_ps(t0, t1));
    }
    far = _mm256_mul_ps(far, _mm256_set1_ps(EXIT_SLACK));
    let hit = _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_LE_OQ>(near, far)) as u32;
    let child: [i32; WIDTH] = bytemuck::cast(node.child);
    let child = _mm256_setr_epi32(child[0], child[1], child[2], child[3], child[4], child[5], child[6], child[7]);
    let unused = _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(child, _mm256_set1_epi32(-1)))) as u32;
    (bytemuck::cast(near), hit & !unused)
}

/// A reference to a child on the traversal stack: a node, or a leaf's item range.
#[derive(Clone, Copy, Debug, Default)]
struct Entry {
    /// Node index, or first item of a leaf.
    index: u32,
    /// Item count of a leaf; 0 for a node.
    count: u8,
    /// The leaf's tag ([`BuildItem::tag`]).
    tag: u8,
    /// Packet traversal: the rays that enter the child (bit i for ray i); 0 for one ray.
    rays: u16,
    /// Distance at which the ray enters the child's box (a packet: the nearest of its rays').
    t: f32,
}

impl Entry {
    /// The entry of `node`'s child in `slot`, entered at distance `t` by `rays` (0 for one
    /// ray); its tag is read only with `TAGS`.
    #[inline(always)]
    fn child<const TAGS: bool>(node: &Node, slot: usize, t: f32, rays: RayMask) -> Entry {
        let child = node.child[slot];
        Entry {
            index: child & INDEX_MASK,
            count: (child >> INDEX_BITS) as u8,
            tag: if TAGS { node.tag[slot] } else { 0 },
            rays,
            t,
        }
    }
}

/// The traversal stack: the binary tree is at most MAX_DEPTH + 32 levels deep (past
/// MAX_DEPTH the builder halves by count, and there are fewer than 2^32 items); each 8-wide
/// level, at least one binary level, pushes at most seven entries.
/// Left uninitialised: zeroing it would cost more than a short traversal.
type Stack = [std::mem::MaybeUninit<Entry>; (WIDTH - 1) * (MAX_DEPTH + 32) + WIDTH];

/// Pushes the children in `mask` (made by `entry`) on the stack, farthest first, and returns
/// the nearest, which the traversal enters next (None when the mask is empty).
#[inline(always)]
fn push_nearest_first(
    mut mask: u32,
    entry: impl Fn(u32) -> Entry,
    stack: &mut Stack,
    top: &mut usize,
) -> Option<Entry> {
    // Most nodes are entered through one or two children: those skip the sort.
    match mask.count_ones() {
        0 => None,
        1 => Some(entry(mask.trailing_zeros())),
        2 => {
            let a = entry(mask.trailing_zeros());
            let b = entry((mask & (mask - 1)).trailing_zeros());
            let (first, second) = if b.t < a.t { (b, a) } else { (a, b) };
            stack[*top].write(second);
            *top += 1;
            Some(first)
        }
        _ => {
            // Children hit, nearest first: insertion sort of at most eight.
            let mut hits = [Entry::default(); WIDTH];
            let mut n = 0;
            while mask != 0 {
                let e = entry(mask.trailing_zeros());
                mask &= mask - 1;
                let mut k = n;
                while k > 0 && hits[k - 1].t > e.t {
                    hits[k] = hits[k - 1];
                    k -= 1;
                }
                hits[k] = e;
                n += 1;
            }
            for e in hits[1..n].iter().rev() {
                stack[*top].write(*e);
                *top += 1;
            }
            Some(hits[0])
        }
    }
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
        self.nodes.len() * std::mem::size_of::<Node>() + self.items.len() * 4
    }

    /// Visits the leaves the ray enters before `*tmax`, nearest boxes first.
    /// `visit(ids, tag, tmax)` intersects a leaf's items (at most [`MAX_LEAF`]; `tag` is the
    /// largest of their [`BuildItem::tag`]s with `TAGS`, 0 without, which spares reading
    /// them), shortens `*tmax` on a hit, and returns true to stop the traversal (any-hit
    /// queries).
    ///
    /// On x86-64 CPUs with AVX2 and FMA (detected at run time) the node tests are 8-wide;
    /// elsewhere they run as two 4-wide halves. Both give the same boxes and the same order.
    #[inline]
    pub fn traverse<const TAGS: bool>(
        &self,
        ray: &RayBoxTest,
        tmax: &mut f32,
        visit: impl FnMut(&[u32], u8, &mut f32) -> bool,
    ) {
        if self.nodes.is_empty() {
            return;
        }
        #[cfg(target_arch = "x86_64")]
        if std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma") {
            // SAFETY: the CPU has the features `traverse_avx2` is compiled for.
            return unsafe { self.traverse_avx2::<TAGS>(ray, tmax, visit) };
        }
        self.traverse_with::<TAGS>(ray, tmax, visit, enter_portable)
    }

    /// [`Bvh::traverse`] compiled for AVX2 and FMA (the leaf callback is inlined here too).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    fn traverse_avx2<const TAGS: bool>(
        &self,
        ray: &RayBoxTest,
        tmax: &mut f32,
        visit: impl FnMut(&[u32], u8, &mut f32) -> bool,
    ) {
        self.traverse_with::<TAGS>(ray, tmax, visit, |ray, node, tmax| enter_avx2(ray, node, tmax))
    }

    /// The traversal loop, with the node test `enter`.
    #[inline(always)]
    fn traverse_with<const TAGS: bool>(
        &self,
        ray: &RayBoxTest,
        tmax: &mut f32,
        mut visit: impl FnMut(&[u32], u8, &mut f32) -> bool,
        enter: impl Fn(&RayBoxTest, &Node, f32) -> ([f32; WIDTH], u32),
    ) {
        let mut stack: Stack = [std::mem::MaybeUninit::uninit(); _];
        let mut top = 0usize;
        let mut current = Entry::default();
        loop {
            if current.count > 0 {
                let first = current.index as usize;
                if visit(&self.items[first..first + current.count as usize], current.tag, tmax) {
                    return;
                }
            } else {
                let node = &self.nodes[current.index as usize];
                let (near, mask) = enter(ray, node, *tmax);
                let entry = |i: u32| Entry::child::<TAGS>(node, i as usize, near[i as usize], 0);
                if let Some(e) = push_nearest_first(mask, entry, &mut stack, &mut top) {
                    current = e;
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

/// The rays of `mask` whose `tmax` still reaches distance `t`.
#[inline(always)]
fn reaching(tmax: &[f32; PACKET], t: f32, mask: RayMask) -> RayMask {
    let (lo, hi) =
        (f32x8::new(tmax[..8].try_into().unwrap_or([0.0; 8])), f32x8::new(tmax[8..].try_into().unwrap_or([0.0; 8])));
    let t = f32x8::splat(t);
    let reach = lo.simd_ge(t).to_bitmask() | hi.simd_ge(t).to_bitmask() << 8;
    mask & reach as RayMask
}

/// The node test of a packet: each ray of `rays` through [`enter_portable`] (or its AVX2
/// twin `enter`); per child, the rays that enter it and the nearest of their entry distances.
#[inline(always)]
fn enter_packet(
    tests: &[RayBoxTest],
    tmax: &[f32; PACKET],
    mut rays: RayMask,
    node: &Node,
    enter: impl Fn(&RayBoxTest, &Node, f32) -> ([f32; WIDTH], u32),
) -> ([f32; WIDTH], [RayMask; WIDTH]) {
    let mut nearest = [f32::INFINITY; WIDTH];
    let mut entering = [0; WIDTH];
    while rays != 0 {
        let r = rays.trailing_zeros() as usize;
        rays &= rays - 1;
        let (near, mut mask) = enter(&tests[r], node, tmax[r]);
        while mask != 0 {
            let c = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            entering[c] |= 1 << r;
            nearest[c] = nearest[c].min(near[c]);
        }
    }
    (nearest, entering)
}

/// [`enter_packet`] with AVX2 and FMA, each ray through the arithmetic of [`enter_avx2`]
/// (so the same boxes and distances), with the node's grid decoded once for all rays.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn enter_packet_avx2(
    tests: &[RayBoxTest],
    tmax: &[f32; PACKET],
    mut rays: RayMask,
    node: &Node,
) -> ([f32; WIDTH], [RayMask; WIDTH]) {
    use std::arch::x86_64::*;
    let mut q = [_mm256_setzero_ps(); 6];
    for (row, q) in q.iter_mut().enumerate() {
        *q = _mm256_cvtepi32_ps(_mm256_cvtepu8_epi32(_mm_cvtsi64_si128(i64::from_le_bytes(node.planes[row]))));
    }
    let child: [i32; WIDTH] = bytemuck::cast(node.child);
    let child = _mm256_setr_epi32(child[0], child[1], child[2], child[3], child[4], child[5], child[6], child[7]);
    let unused = _mm256_castsi256_ps(_mm256_cmpeq_epi32(child, _mm256_set1_epi32(-1)));
    let infinity = _mm256_set1_ps(f32::INFINITY);
    let mut nearest = infinity;
    // Per ray, the children it enters, one byte each.
    let mut entered = [0u8; PACKET];
    while rays != 0 {
        let r = rays.trailing_zeros() as usize;
        rays &= rays - 1;
        let ray = &tests[r];
        let (scale, base) = ray.plane_factors(node);
        let mut near = _mm256_set1_ps(ray.tmin);
        let mut far = _mm256_set1_ps(tmax[r]);
        for a in 0..3 {
            let (s, b) = (_mm256_set1_ps(scale[a]), _mm256_set1_ps(base[a]));
            let (t0, t1) = (_mm256_fmadd_ps(q[a], s, b), _mm256_fmadd_ps(q[a + 3], s, b));
            near = _mm256_max_ps(near, _mm256_min_ps(t0, t1));
            far = _mm256_min_ps(far, _mm256_max_ps(t0, t1));
        }
        far = _mm256_mul_ps(far, _mm256_set1_ps(EXIT_SLACK));
        let hit = _mm256_andnot_ps(unused, _mm256_cmp_ps::<_CMP_LE_OQ>(near, far));
        entered[r] = _mm256_movemask_ps(hit) as u8;
        nearest = _mm256_min_ps(nearest, _mm256_blendv_ps(infinity, near, hit));
    }
    // Transpose the 16 x 8 bits: bit c of every ray's byte, gathered by a byte movemask.
    let bytes: __m128i = bytemuck::cast(entered);
    let mut entering = [0; WIDTH];
    for (c, e) in entering.iter_mut().enumerate() {
        *e = _mm_movemask_epi8(_mm_sll_epi64(bytes, _mm_cvtsi32_si128(7 - c as i32))) as RayMask;
    }
    (bytemuck::cast(nearest), entering)
}

impl Bvh {
    /// [`Bvh::traverse`] for a packet of up to [`PACKET`] rays (`tests[i]` with `tmax[i]`,
    /// for the rays `i` in `rays`) that mostly visit the same nodes, such as a pixel's samples: each node is fetched,
    /// sorted and pushed once for all of them, and every leaf is handed to
    /// `visit(ids, tag, rays, tmax)` with the rays that enter it. `visit` shortens their
    /// `tmax` on hits and returns the rays that are done (any-hit queries), which then leave
    /// the packet. Each ray sees every leaf it would see alone, so closest hits are the same.
    #[inline]
    pub fn traverse_packet<const TAGS: bool>(
        &self,
        tests: &[RayBoxTest],
        rays: RayMask,
        tmax: &mut [f32; PACKET],
        visit: impl FnMut(&[u32], u8, RayMask, &mut [f32; PACKET]) -> RayMask,
    ) {
        // Rays without a test are not traced.
        let rays = rays & (RayMask::MAX >> (PACKET - tests.len().min(PACKET)));
        if self.nodes.is_empty() || rays == 0 {
            return;
        }
        #[cfg(target_arch = "x86_64")]
        if std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma") {
            // SAFETY: the CPU has the features `traverse_packet_avx2` is compiled for.
            return unsafe { self.traverse_packet_avx2::<TAGS>(tests, rays, tmax, visit) };
        }
        self.traverse_packet_with::<TAGS>(tests, rays, tmax, visit, |tests, tmax, rays, node| {
            enter_packet(tests, tmax, rays, node, enter_portable)
        })
    }

    /// [`Bvh::traverse_packet`] compiled for AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    fn traverse_packet_avx2<const TAGS: bool>(
        &self,
        tests: &[RayBoxTest],
        rays: RayMask,
        tmax: &mut [f32; PACKET],
        visit: impl FnMut(&[u32], u8, RayMask, &mut [f32; PACKET]) -> RayMask,
    ) {
        self.traverse_packet_with::<TAGS>(tests, rays, tmax, visit, |tests, tmax, rays, node| {
            enter_packet_avx2(tests, tmax, rays, node)
        })
    }

    /// The packet traversal loop, with the node test `enter` of a packet ([`enter_packet`]).
    #[inline(always)]
    fn traverse_packet_with<const TAGS: bool>(
        &self,
        tests: &[RayBoxTest],
        mut live: RayMask,
        tmax: &mut [f32; PACKET],
        mut visit: impl FnMut(&[u32], u8, RayMask, &mut [f32; PACKET]) -> RayMask,
        enter: impl Fn(&[RayBoxTest], &[f32; PACKET], RayMask, &Node) -> ([f32; WIDTH], [RayMask; WIDTH]),
    ) {
        let mut stack: Stack = [std::mem::MaybeUninit::uninit(); _];
        let mut top = 0usize;
        let mut current = Entry { rays: live, ..Entry::default() };
        loop {
            if current.count > 0 {
                let first = current.index as usize;
                live &= !visit(&self.items[first..first + current.count as usize], current.tag, current.rays, tmax);
            } else {
                let node = &self.nodes[current.index as usize];
                let (near, entering) = enter(tests, tmax, current.rays, node);
                let mask = entering.iter().enumerate().fold(0, |m, (c, &r)| m | u32::from(r != 0) << c);
                let entry = |i: u32| Entry::child::<TAGS>(node, i as usize, near[i as usize], entering[i as usize]);
                if let Some(e) = push_nearest_first(mask, entry, &mut stack, &mut top) {
                    current = e;
                    continue;
                }
            }
            // Pop the next child some live ray still reaches.
            loop {
                if top == 0 || live == 0 {
                    return;
                }
                top -= 1;
                // SAFETY: entries below `top` were written by the push above.
                let e = unsafe { stack[top].assume_init() };
                let rays = reaching(tmax, e.t, e.rays & live);
                if rays != 0 {
                    current = Entry { rays, ..e };
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
    /// A small value of the caller's: a leaf hands the largest of its items' to the
    /// traversal's callback (level of detail: how wide its segments may be drawn).
    pub tag: u8,
}

impl BuildItem {
    /// An item every traversal visits, tagged 0.
    pub fn new(bounds: Aabb, id: u32) -> BuildItem {
        BuildItem { bounds, id, tag: 0 }
    }
}

/// Most items in a leaf.
pub const MAX_LEAF: usize = 8;
/// Cost of visiting a node relative to intersecting one item (SAH constants). Leaves test
/// four segments at once, so items are cheap next to nodes: measured on the hairy torus
/// (docs/performance.md), 4 gives the same speed as 1 with 60 % less BVH memory.
const TRAVERSAL_COST: f32 = 4.0;
/// Subtrees at least this big are built on another rayon task.
const PARALLEL_THRESHOLD: usize = 4096;

/// A node of the binary tree, and the largest tag of its items.
enum BuildNode {
    Leaf { bounds: Aabb, first: usize, count: usize, tag: u8 },
    Inner { bounds: Aabb, children: Box<[BuildNode; 2]>, tag: u8 },
}

impl BuildNode {
    fn bounds(&self) -> Aabb {
        match self {
            BuildNode::Leaf { bounds, .. } | BuildNode::Inner { bounds, .. } => *bounds,
        }
    }

    fn tag(&self) -> u8 {
        match self {
            BuildNode::Leaf { tag, .. } | BuildNode::Inner { tag, .. } => *tag,
        }
    }

    /// The inner node over `l` and `r`.
    fn join(l: BuildNode, r: BuildNode) -> BuildNode {
        let (bounds, tag) = (l.bounds().union(r.bounds()), l.tag().max(r.tag()));
        BuildNode::Inner { bounds, children: Box::new([l, r]), tag }
    }
}

impl Bvh {
    /// Builds the hierarchy. Items with empty or non-finite bounds are dropped: they can
    /// never be hit and would poison the heuristic. Only the first [`MAX_ITEMS`] items are
    /// indexed (scene loading rejects larger objects with an error before they get here).
    pub fn build(mut items: Vec<BuildItem>) -> Bvh {
        let valid = |it: &BuildItem| !it.bounds.is_empty() && it.bounds.min.is_finite() && it.bounds.max.is_finite();
        // Checked in parallel first: usually every item is valid and nothing needs to move.
        if !items.par_iter().all(valid) {
            items.retain(valid);
        }
        items.truncate(MAX_ITEMS);
        if items.is_empty() {
            return Bvh::default();
        }
        let (bounds, centroids) = bounds_and_centroids(&items);
        let root = build_node(&mut items, 0, 0, bounds, centroids);
        let nodes = match &root {
            BuildNode::Leaf { .. } => {
                // A single leaf still needs a node to hang from.
                let mut nodes = vec![EMPTY_NODE];
                let grid = Grid::spanning(bounds);
                (nodes[0].origin, nodes[0].step) = (grid.origin.into(), grid.step.into());
                set_child(&mut nodes[0], &grid, 0, &root, 0);
                nodes
            }
            BuildNode::Inner { .. } => collapse_root(&root),
        };
        drop_tree(root, 0);
        // Collected into a new vector (not in place, which would keep the build items'
        // twelve times larger allocation alive).
        let ids: Vec<u32> = items.par_iter().map(|it| it.id).collect();
        drop(items);
        Bvh { nodes, items: ids, bounds: Some(bounds) }
    }
}

/// Frees the binary tree (one allocation per inner node), the subtrees of its top
/// `PARALLEL_DROP_DEPTH` levels in parallel.
fn drop_tree(node: BuildNode, depth: usize) {
    const PARALLEL_DROP_DEPTH: usize = 4;
    if let BuildNode::Inner { children, .. } = node {
        if depth < PARALLEL_DROP_DEPTH {
            let [l, r] = *children;
            rayon::join(|| drop_tree(l, depth + 1), || drop_tree(r, depth + 1));
        }
    }
}

/// Deepest tree the traversal stack can hold; below it, nodes become leaves.
const MAX_DEPTH: usize = 60;

/// Builds the subtree over `items`, which start at index `offset` of the whole item array;
/// `bounds` and `centroids` bound the items' boxes and centres (the parent's split knows
/// both, which spares every node a pass over its items).
fn build_node(items: &mut [BuildItem], offset: usize, depth: usize, bounds: Aabb, centroids: Aabb) -> BuildNode {
    let leaf = |items: &[BuildItem]| BuildNode::Leaf {
        bounds,
        first: offset,
        count: items.len(),
        tag: items.iter().map(|it| it.tag).max().unwrap_or(0),
    };
    if items.len() <= 2 {
        return leaf(items);
    }
    // Past the depth the traversal stack is sized for, split by count (the tree then
    // deepens by one level per halving, so this cannot recurse without end).
    let split = if depth >= MAX_DEPTH { None } else { choose_split(items, &bounds, &centroids) };
    let (mid, sides) = match split {
        Some(split) => {
            let (mid, left_centroids, right_centroids) = partition_parallel(items, |c| split.goes_left(c));
            (mid, Some(((split.left, left_centroids), (split.right, right_centroids))))
        }
        // Centroids coincide: split by count so leaves stay small.
        None if items.len() > MAX_LEAF => (items.len() / 2, None),
        None => return leaf(items),
    };
    // The split's bins put at least one item on each side; the check keeps a split by count
    // (which always progresses) should rounding ever disagree.
    let (mid, sides) = if mid == 0 || mid == items.len() { (items.len() / 2, None) } else { (mid, sides) };
    let (left, right) = items.split_at_mut(mid);
    let ((lb, lc), (rb, rc)) = sides.unwrap_or_else(|| (bounds_and_centroids(left), bounds_and_centroids(right)));
    let (l, r) = if left.len() + right.len() >= PARALLEL_THRESHOLD {
        rayon::join(
            || build_node(left, offset, depth + 1, lb, lc),
            || build_node(right, offset + mid, depth + 1, rb, rc),
        )
    } else {
        (build_node(left, offset, depth + 1, lb, lc), build_node(right, offset + mid, depth + 1, rb, rc))
    };
    BuildNode::join(l, r)
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

/// The bins of a centroid along the three axes (all three at once, in SIMD), `last` the
/// index of the last bin; the split and the partition both use it, so an item goes to the
/// side its bin was counted on. Below the first bin (and NaN) is bin 0, past the last is the
/// last.
#[inline]
fn bins_of(c: Vec3A, lo: Vec3A, scale: Vec3A, last: f32) -> [usize; 3] {
    let b = ((c - lo) * scale).max(Vec3A::ZERO).min(Vec3A::splat(last));
    // On x86-64, truncated in one SSE2 instruction: the lanes lie in [0, last], where it is
    // exact (`as_uvec3` converts lane by lane, each a saturating cast: once a quarter of the
    // build's instructions).
    #[cfg(target_arch = "x86_64")]
    // SAFETY: SSE2 is part of x86-64.
    let b: [i32; 4] = bytemuck::cast(unsafe { std::arch::x86_64::_mm_cvttps_epi32(b.into()) });
    #[cfg(not(target_arch = "x86_64"))]
    let b = b.as_uvec3().to_array();
    [b[0] as usize, b[1] as usize, b[2] as usize]
}

/// Boxes and counts of the items falling in each of `B` bins, along each axis.
#[derive(Clone, Copy)]
struct Bins<const B: usize> {
    bounds: [[Aabb; B]; 3],
    counts: [[u32; B]; 3],
}

impl<const B: usize> Bins<B> {
    const EMPTY: Bins<B> = Bins { bounds: [[Aabb::EMPTY; B]; 3], counts: [[0; B]; 3] };

    fn merge(mut self, o: Bins<B>) -> Bins<B> {
        for axis in 0..3 {
            for b in 0..B {
                self.bounds[axis][b] = self.bounds[axis][b].union(o.bounds[axis][b]);
                self.counts[axis][b] += o.counts[axis][b];
            }
        }
        self
    }
}

/// A binned SAH split: the items whose centroid falls in a bin below `bin` along `axis` go
/// left; `left` and `right` bound the items of either side.
struct Split {
    axis: usize,
    lo: Vec3A,
    scale: Vec3A,
    last: f32,
    bin: usize,
    left: Aabb,
    right: Aabb,
}

impl Split {
    #[inline]
    fn goes_left(&self, centroid: Vec3A) -> bool {
        bins_of(centroid, self.lo, self.scale, self.last)[self.axis] < self.bin
    }
}

/// The binned SAH split of the items, or None when no split beats a leaf (or the items'
/// centroids coincide). Small nodes use fewer bins: there the fixed cost of the bins (their
/// reset and sweep) outweighs the items', and a handful of items needs no 32 candidate planes.
fn choose_split(items: &[BuildItem], bounds: &Aabb, centroids: &Aabb) -> Option<Split> {
    // The thresholds: the fewest instructions at which the traced hairy torus's camera and
    // shadow rays cost within 0.5 % of 32 bins everywhere (docs/performance.md, tuning constants).
    match items.len() {
        0..=8 => binned_split::<4>(items, bounds, centroids),
        9..=32 => binned_split::<8>(items, bounds, centroids),
        33..=128 => binned_split::<16>(items, bounds, centroids),
        _ => binned_split::<32>(items, bounds, centroids),
    }
}

/// [`choose_split`] with `B` bins along each axis.
fn binned_split<const B: usize>(items: &[BuildItem], bounds: &Aabb, centroids: &Aabb) -> Option<Split> {
    let extent = centroids.max - centroids.min;
    let scale = Vec3A::select(extent.cmpgt(Vec3A::ZERO), B as f32 / extent, Vec3A::ZERO);
    let last = (B - 1) as f32;
    let fill = |items: &[BuildItem]| {
        let mut bins = Bins::<B>::EMPTY;
        for it in items {
            let b = bins_of(it.bounds.center(), centroids.min, scale, last);
            for (axis, &b) in b.iter().enumerate() {
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
        let mut right_area = [0.0f32; B];
        let mut right_count = [0u32; B];
        let (mut acc, mut n) = (Aabb::EMPTY, 0);
        for i in (1..B).rev() {
            acc = acc.union(bin_bounds[i]);
            n += bin_counts[i];
            right_area[i] = acc.half_area();
            right_count[i] = n;
        }
        let (mut acc, mut n) = (Aabb::EMPTY, 0);
        for i in 0..B - 1 {
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
    if split_cost >= leaf_cost && items.len() <= MAX_LEAF {
        return None;
    }
    let side = |bins: &[Aabb]| bins.iter().fold(Aabb::EMPTY, |b, &c| b.union(c));
    let (left, right) = (side(&bins.bounds[axis][..bin]), side(&bins.bounds[axis][bin..]));
    Some(Split { axis, lo: centroids.min, scale, last, bin, left, right })
}

/// Moves the items whose centroid `left` accepts to the front, swapping each misplaced pair
/// once (Hoare's two-index partition); returns how many there are and the bounds of the
/// centroids on either side (the children's, taken on the way).
fn partition(items: &mut [BuildItem], left: impl Fn(Vec3A) -> bool) -> (usize, Aabb, Aabb) {
    let (mut left_centroids, mut right_centroids) = (Aabb::EMPTY, Aabb::EMPTY);
    // Items before `i` go left, from `j` on right; those between are still to sort.
    let (mut i, mut j) = (0, items.len());
    loop {
        let right_one = loop {
            if i == j {
                return (i, left_centroids, right_centroids);
            }
            let c = items[i].bounds.center();
            if !left(c) {
                break c;
            }
            left_centroids = left_centroids.grow(c);
            i += 1;
        };
        let left_one = loop {
            j -= 1;
            if j == i {
                return (i, left_centroids, right_centroids.grow(right_one));
            }
            let c = items[j].bounds.center();
            if left(c) {
                break c;
            }
            right_centroids = right_centroids.grow(c);
        };
        items.swap(i, j);
        left_centroids = left_centroids.grow(left_one);
        right_centroids = right_centroids.grow(right_one);
        i += 1;
    }
}

/// [`partition`] of a large node in parallel, in place: each run of [`SCAN_CHUNK`] items is
/// partitioned on its own, then the right items before the split point trade places with
/// the left items after it, the k-th of the ones with the k-th of the others. The order
/// depends on the chunk size alone, not on the threads.
fn partition_parallel(items: &mut [BuildItem], left: impl Fn(Vec3A) -> bool + Sync) -> (usize, Aabb, Aabb) {
    if items.len() < 2 * SCAN_CHUNK {
        return partition(items, left);
    }
    let parts: Vec<(usize, Aabb, Aabb)> = items.par_chunks_mut(SCAN_CHUNK).map(|c| partition(c, &left)).collect();
    let mid = parts.iter().map(|p| p.0).sum();
    let (mut misplaced_right, mut misplaced_left) = (Vec::new(), Vec::new());
    for (k, &(lefts, _, _)) in parts.iter().enumerate() {
        let (start, end) = (k * SCAN_CHUNK, ((k + 1) * SCAN_CHUNK).min(items.len()));
        let (rights, lefts_end) = (start + lefts..end.min(mid), start + lefts);
        if !rights.is_empty() {
            misplaced_right.push(rights);
        }
        if lefts_end > start.max(mid) {
            misplaced_left.push(start.max(mid) - mid..lefts_end - mid);
        }
    }
    let (head, tail) = items.split_at_mut(mid);
    let (mut rights, mut lefts) = (misplaced_right.into_iter(), misplaced_left.into_iter());
    let (mut r, mut l) = (rights.next(), lefts.next());
    while let (Some(a), Some(b)) = (&mut r, &mut l) {
        let n = a.len().min(b.len());
        head[a.start..a.start + n].swap_with_slice(&mut tail[b.start..b.start + n]);
        (a.start, b.start) = (a.start + n, b.start + n);
        if a.start == a.end {
            r = rights.next();
        }
        if b.start == b.end {
            l = lefts.next();
        }
    }
    let (lc, rc) = parts.iter().fold((Aabb::EMPTY, Aabb::EMPTY), |(l, r), p| (l.union(p.1), r.union(p.2)));
    (mid, lc, rc)
}

/// The children of binary inner node `node` that its 8-wide node gets (the first `n` of the
/// array): children are opened, largest box first, until there are eight.
fn open(node: &BuildNode) -> ([&BuildNode; WIDTH], usize) {
    let mut children = [node; WIDTH];
    let mut n = 1;
    if let BuildNode::Inner { children: pair, .. } = node {
        (children[0], children[1], n) = (&pair[0], &pair[1], 2);
    }
    while n < WIDTH {
        let open = children[..n]
            .iter()
            .enumerate()
            .filter(|(_, c)| matches!(c, BuildNode::Inner { .. }))
            .max_by(|a, b| a.1.bounds().half_area().total_cmp(&b.1.bounds().half_area()))
            .map(|(i, _)| i);
        let Some(i) = open else { break };
        let BuildNode::Inner { children: grand, .. } = children[i] else { unreachable!() };
        // The opened child's slot takes the last child, its two children go last.
        (children[i], children[n - 1], children[n]) = (children[n - 1], &grand[0], &grand[1]);
        n += 1;
    }
    (children, n)
}

/// How many 8-wide nodes [`collapse`] writes for `node` and its subtree.
fn wide_nodes(node: &BuildNode) -> usize {
    match node {
        BuildNode::Leaf { .. } => 0,
        BuildNode::Inner { .. } => {
            let (children, n) = open(node);
            1 + children[..n].iter().map(|c| wide_nodes(c)).sum::<usize>()
        }
    }
}

/// The 8-wide nodes of the tree under binary inner node `root`, depth first. The subtrees
/// of the root's children are written in parallel, each into a vector of its own starting
/// at the index [`wide_nodes`] says, then concatenated: the same nodes in the same order as
/// one serial [`collapse`].
fn collapse_root(root: &BuildNode) -> Vec<Node> {
    let (children, n) = open(root);
    let children = &children[..n];
    let sizes: Vec<usize> = children.par_iter().map(|c| wide_nodes(c)).collect();
    let starts: Vec<usize> = sizes.iter().scan(1, |next, &s| Some(std::mem::replace(next, *next + s))).collect();
    let subtrees: Vec<Vec<Node>> = children
        .par_iter()
        .zip(&sizes)
        .zip(&starts)
        .map(|((&child, &size), &start)| {
            let mut nodes = Vec::with_capacity(size);
            if size > 0 {
                nodes.push(EMPTY_NODE);
                collapse(child, 0, &mut nodes, start);
            }
            nodes
        })
        .collect();
    let mut nodes = Vec::with_capacity(1 + sizes.iter().sum::<usize>());
    nodes.push(EMPTY_NODE);
    let grid = Grid::spanning(root.bounds());
    (nodes[0].origin, nodes[0].step) = (grid.origin.into(), grid.step.into());
    for (slot, (child, &start)) in children.iter().zip(&starts).enumerate() {
        set_child(&mut nodes[0], &grid, slot, child, start as u32);
    }
    for subtree in subtrees {
        nodes.extend(subtree);
    }
    nodes
}

/// Writes the 8-wide node for binary inner node `node` at `nodes[at]`, and its subtree
/// after it; `nodes[0]` is node `start` of the whole hierarchy.
fn collapse(node: &BuildNode, at: usize, nodes: &mut Vec<Node>, start: usize) {
    let (children, n) = open(node);
    let grid = Grid::spanning(node.bounds());
    nodes[at].origin = grid.origin.into();
    nodes[at].step = grid.step.into();
    for (slot, &child) in children[..n].iter().enumerate() {
        let index = match child {
            BuildNode::Leaf { .. } => 0,
            BuildNode::Inner { .. } => {
                nodes.push(EMPTY_NODE);
                nodes.len() - 1
            }
        };
        set_child(&mut nodes[at], &grid, slot, child, (start + index) as u32);
        if index > 0 {
            collapse(child, index, nodes, start);
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
fn set_child(node: &mut Node, grid: &Grid, slot: usize, child: &BuildNode, index: u32) {
    let b = child.bounds();
    for axis in 0..3 {
        let (lo, hi) = grid.quantise(axis, b.min[axis], b.max[axis]);
        node.planes[axis][slot] = lo;
        node.planes[axis + 3][slot] = hi;
    }
    node.tag[slot] = child.tag();
    node.child[slot] = match child {
        BuildNode::Leaf { first, count, .. } => *first as u32 | (*count as u32) << INDEX_BITS,
        BuildNode::Inner { .. } => index,
    };
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::rng::GenRng;
    use rand::{Rng, SeedableRng};

    /// Random small boxes spread over a cube of side 10, some flat.
    fn random_items(rng: &mut GenRng, n: usize) -> Vec<BuildItem> {
        (0..n)
            .map(|i| {
                let c = Vec3::new(rng.random(), rng.random(), rng.random()) * 10.0;
                let mut half = Vec3::new(rng.random(), rng.random(), rng.random()) * 0.4;
                if i % 7 == 0 {
                    half.y = 0.0;
                }
                BuildItem::new(Aabb::new(c - half, c + half), i as u32)
            })
            .collect()
    }

    /// Float slab test of one box, with the traversal's exit slack.
    fn crosses(b: &Aabb, o: Vec3, inv: Vec3) -> bool {
        let t0 = (Vec3::from(b.min) - o) * inv;
        let t1 = (Vec3::from(b.max) - o) * inv;
        t0.min(t1).max_element().max(0.0) <= t0.max(t1).min_element() * EXIT_SLACK
    }

    /// The items in the leaves a traversal with node test `enter` visits.
    fn visited(
        bvh: &Bvh,
        ray: &RayBoxTest,
        enter: impl Fn(&RayBoxTest, &Node, f32) -> ([f32; WIDTH], u32),
    ) -> std::collections::BTreeSet<u32> {
        let mut seen = std::collections::BTreeSet::new();
        bvh.traverse_with::<false>(
            ray,
            &mut f32::INFINITY.clone(),
            |ids, _, _| {
                seen.extend(ids.iter().copied());
                false
            },
            enter,
        );
        seen
    }

    #[test]
    fn quantised_nodes_enclose_their_items_on_every_node_test() {
        let mut rng = GenRng::seed_from_u64(3);
        let items = random_items(&mut rng, 3000);
        let bvh = Bvh::build(items.clone());
        let mut crossing = 0;
        for _ in 0..500 {
            let o = Vec3::new(rng.random(), rng.random(), rng.random()) * 30.0 - 10.0;
            let target = Vec3::new(rng.random(), rng.random(), rng.random()) * 10.0;
            let dir = (target - o).normalize();
            let ray = RayBoxTest::new(o, dir, 0.0);
            let expected: Vec<u32> =
                items.iter().filter(|it| crosses(&it.bounds, o, ray.inv_dir)).map(|it| it.id).collect();
            crossing += expected.len();
            let portable = visited(&bvh, &ray, enter_portable);
            assert!(expected.iter().all(|id| portable.contains(id)), "portable node test lost an item");
            #[cfg(target_arch = "x86_64")]
            if std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma") {
                // SAFETY: the CPU has AVX2 and FMA.
                let wide = visited(&bvh, &ray, |r, n, t| unsafe { enter_avx2(r, n, t) });
                assert!(expected.iter().all(|id| wide.contains(id)), "AVX2 node test lost an item");
                // The two node tests differ only by the rounding of a fused multiply-add.
                assert!(wide.symmetric_difference(&portable).count() <= 1 + portable.len() / 100);
            }
        }
        assert!(crossing > 1000, "the test needs rays that cross boxes: {crossing}");
    }

    /// Per ray, the items in the leaves a packet traversal with node test `enter` visits.
    fn visited_by_packet(
        bvh: &Bvh,
        tests: &[RayBoxTest],
        enter: impl Fn(&[RayBoxTest], &[f32; PACKET], RayMask, &Node) -> ([f32; WIDTH], [RayMask; WIDTH]),
    ) -> Vec<std::collections::BTreeSet<u32>> {
        let mut seen = vec![std::collections::BTreeSet::new(); tests.len()];
        let all = RayMask::MAX >> (PACKET - tests.len());
        let visit = |ids: &[u32], _, rays: RayMask, _: &mut [f32; PACKET]| {
            (0..tests.len()).filter(|i| rays >> i & 1 == 1).for_each(|i| seen[i].extend(ids.iter().copied()));
            0
        };
        bvh.traverse_packet_with::<false>(tests, all, &mut [f32::INFINITY; PACKET], visit, enter);
        seen
    }

    #[test]
    fn a_packet_visits_what_each_of_its_rays_visits_alone() {
        let mut rng = GenRng::seed_from_u64(5);
        let bvh = Bvh::build(random_items(&mut rng, 3000));
        for _ in 0..100 {
            let o = Vec3::new(rng.random(), rng.random(), rng.random()) * 30.0 - 10.0;
            let target = Vec3::new(rng.random(), rng.random(), rng.random()) * 10.0;
            let n = rng.random_range(1..=PACKET);
            let tests: Vec<RayBoxTest> = (0..n)
                .map(|_| {
                    let jitter = Vec3::new(rng.random(), rng.random(), rng.random()) * 0.5;
                    RayBoxTest::new(o, (target + jitter - o).normalize(), 0.0)
                })
                .collect();
            let portable = visited_by_packet(&bvh, &tests, |t, m, r, n| enter_packet(t, m, r, n, enter_portable));
            for (test, seen) in tests.iter().zip(&portable) {
                assert_eq!(*seen, visited(&bvh, test, enter_portable));
            }
            #[cfg(target_arch = "x86_64")]
            if std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma") {
                // SAFETY: the CPU has AVX2 and FMA.
                let wide = visited_by_packet(&bvh, &tests, |t, m, r, n| unsafe { enter_packet_avx2(t, m, r, n) });
                for (test, seen) in tests.iter().zip(&wide) {
                    assert_eq!(*seen, visited(&bvh, test, |r, n, t| unsafe { enter_avx2(r, n, t) }));
                }
            }
        }
    }

    #[test]
    fn grid_rounds_outwards() {
        let grid = Grid::spanning(Aabb::new(Vec3::new(-1.0, 1e3, 0.0), Vec3::new(3.0, 1e3 + 0.1, 0.0)));
        for (axis, min, max) in [(0, -0.3f32, 1.7f32), (1, 1e3 + 0.01, 1e3 + 0.02), (1, 1e3, 1e3 + 0.1), (2, 0.0, 0.0)]
        {
            let (lo, hi) = grid.quantise(axis, min, max);
            assert!(lo <= hi);
            assert!(grid.origin[axis] + f32::from(lo) * grid.step[axis] <= min);
            assert!(grid.origin[axis] + f32::from(hi) * grid.step[axis] >= max);
        }
    }
}
