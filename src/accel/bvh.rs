//! A binary bounding volume hierarchy built with the binned surface area heuristic
//! (Wald 2007, "On fast Construction of SAH-based Bounding Volume Hierarchies"), in
//! parallel with rayon, and traversed front to back with a small stack.
//!
//! The BVH stores no primitives, only `u32` item ids (a triangle index, or the first point
//! of a hair segment); callers intersect items through a callback. Nodes are 32 bytes and
//! siblings are adjacent, so an inner node needs one child index.

use crate::math::Aabb;
use glam::Vec3;

/// One BVH node: a box and either two children or a range of items.
#[derive(Clone, Copy, Debug)]
#[repr(C)]
pub struct Node {
    min: [f32; 3],
    /// Inner node: index of the left child (the right one follows it). Leaf: first item.
    first: u32,
    max: [f32; 3],
    /// Number of items; 0 for an inner node.
    count: u32,
}

impl Node {
    fn bounds(&self) -> Aabb {
        Aabb { min: Vec3::from(self.min), max: Vec3::from(self.max) }
    }
}

/// A bounding volume hierarchy over items.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
    items: Vec<u32>,
}

/// A ray prepared for box tests.
#[derive(Clone, Copy, Debug)]
pub struct RayBoxTest {
    origin: Vec3,
    inv_dir: Vec3,
}

impl RayBoxTest {
    /// Precomputes the reciprocal direction.
    #[inline]
    pub fn new(origin: Vec3, dir: Vec3) -> RayBoxTest {
        RayBoxTest { origin, inv_dir: dir.recip() }
    }

    /// Entry distance of the ray into the box if it enters before `tmax`.
    /// Slab test; `f32::max`/`min` drop the NaN that 0 * inf gives for a ray lying in a slab plane.
    #[inline]
    fn enter(&self, min: [f32; 3], max: [f32; 3], tmax: f32) -> Option<f32> {
        let t0 = (Vec3::from(min) - self.origin) * self.inv_dir;
        let t1 = (Vec3::from(max) - self.origin) * self.inv_dir;
        let near = t0.min(t1).max_element().max(0.0);
        let far = t0.max(t1).min_element().min(tmax);
        // A tiny relative slack keeps boxes of zero thickness (flat meshes) from being missed.
        (near <= far * (1.0 + 4.0 * f32::EPSILON)).then_some(near)
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

const BINS: usize = 16;
const MAX_LEAF: usize = 8;
/// Cost of visiting a node relative to intersecting one item (SAH constants).
const TRAVERSAL_COST: f32 = 1.0;
/// Subtrees at least this big are built on another rayon task.
const PARALLEL_THRESHOLD: usize = 4096;

enum BuildNode {
    Leaf { bounds: Aabb, first: usize, count: usize },
    Inner { bounds: Aabb, children: Box<[BuildNode; 2]> },
}

impl Bvh {
    /// Builds the hierarchy. Items with empty or non-finite bounds are dropped: they can
    /// never be hit and would poison the heuristic.
    pub fn build(mut items: Vec<BuildItem>) -> Bvh {
        items.retain(|it| !it.bounds.is_empty() && it.bounds.min.is_finite() && it.bounds.max.is_finite());
        if items.is_empty() {
            return Bvh::default();
        }
        let root = build_node(&mut items, 0, 0);
        let mut nodes = Vec::with_capacity(2 * items.len() / 2 + 1);
        nodes.push(Node { min: [0.0; 3], first: 0, max: [0.0; 3], count: 0 });
        flatten(&root, 0, &mut nodes);
        Bvh { nodes, items: items.into_iter().map(|it| it.id).collect() }
    }

    /// Bounds of everything in the hierarchy.
    pub fn bounds(&self) -> Aabb {
        self.nodes.first().map_or(Aabb::EMPTY, Node::bounds)
    }

    /// Number of nodes.
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// Bytes held by nodes and item ids.
    pub fn memory_bytes(&self) -> usize {
        self.nodes.len() * std::mem::size_of::<Node>() + self.items.len() * 4
    }

    /// Visits the items whose leaves the ray enters before `*tmax`, nearest boxes first.
    /// `visit(id, tmax)` intersects one item, shortens `*tmax` on a hit, and returns true
    /// to stop the traversal (any-hit queries).
    #[inline]
    pub fn traverse(&self, ray: &RayBoxTest, tmax: &mut f32, mut visit: impl FnMut(u32, &mut f32) -> bool) {
        let Some(root) = self.nodes.first() else { return };
        if ray.enter(root.min, root.max, *tmax).is_none() {
            return;
        }
        let mut stack = [0u32; 64];
        let mut top = 0usize;
        let mut index = 0usize;
        loop {
            let node = &self.nodes[index];
            if node.count > 0 {
                let first = node.first as usize;
                for &id in &self.items[first..first + node.count as usize] {
                    if visit(id, tmax) {
                        return;
                    }
                }
            } else {
                let l = node.first as usize;
                let (a, b) = (&self.nodes[l], &self.nodes[l + 1]);
                let ta = ray.enter(a.min, a.max, *tmax);
                let tb = ray.enter(b.min, b.max, *tmax);
                match (ta, tb) {
                    (Some(ta), Some(tb)) => {
                        let (near, far) = if ta <= tb { (l, l + 1) } else { (l + 1, l) };
                        // The stack depth is bounded by the tree depth; the builder caps it.
                        stack[top] = far as u32;
                        top += 1;
                        index = near;
                        continue;
                    }
                    (Some(_), None) => {
                        index = l;
                        continue;
                    }
                    (None, Some(_)) => {
                        index = l + 1;
                        continue;
                    }
                    (None, None) => {}
                }
            }
            if top == 0 {
                return;
            }
            top -= 1;
            index = stack[top] as usize;
        }
    }
}

/// Deepest tree the traversal stack can hold; below it, nodes become leaves.
const MAX_DEPTH: usize = 60;

/// Builds the subtree over `items`, which start at index `offset` of the whole item array.
fn build_node(items: &mut [BuildItem], offset: usize, depth: usize) -> BuildNode {
    let bounds = items.iter().fold(Aabb::EMPTY, |b, it| b.union(it.bounds));
    let leaf = |items: &[BuildItem]| BuildNode::Leaf { bounds, first: offset, count: items.len() };
    if items.len() <= 2 || depth >= MAX_DEPTH {
        return leaf(items);
    }
    let split = choose_split(items, &bounds);
    let mid = match split {
        Some((axis, position)) => partition(items, |it| it.bounds.center()[axis] < position),
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

/// The binned SAH split (axis, centroid position), or None when no split beats a leaf
/// (or the items' centroids coincide).
fn choose_split(items: &[BuildItem], bounds: &Aabb) -> Option<(usize, f32)> {
    let centroids = items.iter().fold(Aabb::EMPTY, |b, it| b.grow(it.bounds.center()));
    let mut best: Option<(f32, usize, f32)> = None;
    for axis in 0..3 {
        let (lo, hi) = (centroids.min[axis], centroids.max[axis]);
        if hi <= lo {
            continue;
        }
        let scale = BINS as f32 / (hi - lo);
        let mut bin_bounds = [Aabb::EMPTY; BINS];
        let mut bin_counts = [0usize; BINS];
        for it in items {
            let b = (((it.bounds.center()[axis] - lo) * scale) as usize).min(BINS - 1);
            bin_bounds[b] = bin_bounds[b].union(it.bounds);
            bin_counts[b] += 1;
        }
        // Sweep from the right to get the cost of every right side, then from the left.
        let mut right_area = [0.0f32; BINS];
        let mut right_count = [0usize; BINS];
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
                best = Some((cost, axis, lo + (i + 1) as f32 / scale));
            }
        }
    }
    let (cost, axis, position) = best?;
    let leaf_cost = items.len() as f32 * bounds.half_area();
    let split_cost = TRAVERSAL_COST * bounds.half_area() + cost;
    (split_cost < leaf_cost || items.len() > MAX_LEAF).then_some((axis, position))
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

/// Writes `node` at `nodes[at]` and its subtree after it, children side by side.
fn flatten(node: &BuildNode, at: usize, nodes: &mut Vec<Node>) {
    match node {
        BuildNode::Leaf { bounds, first, count } => {
            nodes[at] =
                Node { min: bounds.min.into(), first: *first as u32, max: bounds.max.into(), count: *count as u32 };
        }
        BuildNode::Inner { bounds, children } => {
            let l = nodes.len();
            let dummy = Node { min: [0.0; 3], first: 0, max: [0.0; 3], count: 0 };
            nodes.push(dummy);
            nodes.push(dummy);
            nodes[at] = Node { min: bounds.min.into(), first: l as u32, max: bounds.max.into(), count: 0 };
            flatten(&children[0], l, nodes);
            flatten(&children[1], l + 1, nodes);
        }
    }
}
