//! The final gather's irradiance cache on diffuse surfaces (Ward, Rubinstein & Clear 1988,
//! "A ray tracing solution for diffuse interreflection"): the light gathered at a few
//! points is stored as records and interpolated in between, so most camera samples need no
//! gather rays. Hair keeps gathering at every hit (its shading is not a function of a
//! point and a normal).
//!
//! A record holds the mean radiance arriving over the cosine-weighted hemisphere (the
//! irradiance over pi, what a Lambertian surface of albedo 1 reflects), the harmonic mean
//! distance `R` to what its rays hit, and the gradients of that light under rotation and
//! translation (Ward & Heckbert 1992, "Irradiance gradients"), from a stratified gather.
//! A record serves a point `p` of normal `n` where Ward's error estimate
//! `eps = |p - p_i| / R_i + sqrt(1 - n . n_i)` is below the accuracy `a`, with the weight
//! `1 / eps - 1 / a` (Ward's `1 / eps` less its value at the edge, so records fade out
//! instead of ending in a seam). `R` is clamped to a range of pixel footprints
//! (Tabellion & Lamorlette 2004, "An approximate global illumination system for computer
//! generated films"), so corners do not take a record per pixel nor open floors one record.
//!
//! Determinism: the cache is filled before the render by a pre-pass over image points on
//! grids `spacing << (LEVELS - 1)` pixels apart, then twice as dense level by level down
//! to `spacing`. The points of a level are traced in parallel against the records of the
//! levels before (read-only) with random numbers from (seed, level, point), and their new
//! records are appended in point order; the render then only reads the cache, and falls
//! back to gathering where no record serves. So the cache, and the image, are the same
//! for any thread count, and for any set of tiles rendered from the same scene.

use super::direct::{trace, Bounce, Indirect, Whitted};
use super::interaction::Interaction;
use super::tracer::{CameraHint, Counters, Tracer};
use crate::math::rng::{hash_combine, PixelSampler};
use crate::math::{frame, Color, Ray, RayCone};
use crate::shading::Material;
use crate::world::{IrradianceCacheSettings, World};
use glam::Vec3;
use rayon::prelude::*;
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::RTree;
use std::cell::RefCell;
use std::f32::consts::PI;

/// Grid levels of the pre-pass: points `8 * spacing` pixels apart first, `spacing` last.
const LEVELS: u32 = 4;

/// Mixed into the seed of the pre-pass's random numbers, apart from the camera samples'.
const STREAM: u32 = 0x1ca4_c4e5;

/// One cached gather.
#[derive(Clone, Copy, Debug)]
struct Record {
    p: Vec3,
    n: Vec3,
    /// Mean radiance arriving over the cosine-weighted hemisphere (irradiance / pi).
    e: Color,
    /// Clamped harmonic mean distance to what the gather rays hit.
    r: f32,
    /// Change of `e` per radian of rotation about each axis, per colour channel.
    rotation: [Vec3; 3],
    /// Change of `e` per unit of translation, per colour channel.
    translation: [Vec3; 3],
}

/// The records and an R-tree over the cubes around the spheres they serve.
#[derive(Debug)]
pub struct IrradianceCache {
    records: Vec<Record>,
    tree: RTree<GeomWithData<Rectangle<[f32; 3]>, u32>>,
    accuracy: f32,
}

/// The albedo the cached light is reflected with, for a hit the cache serves: diffuse
/// surfaces only (not hair, not glossy or specular materials).
pub(super) fn cached_albedo(at: &Interaction) -> Option<Color> {
    match at.material {
        Material::Diffuse { color } if !at.on_hair() => Some(at.sp.color.unwrap_or(*color)),
        Material::Textured(t) if !at.on_hair() && t.roughness.is_none() => Some(t.albedo(&at.sp)),
        _ => None,
    }
}

impl IrradianceCache {
    /// Fills the cache for `world`'s image by the pre-pass (see the module's description),
    /// on the current rayon pool; the rays it traces are added to `counters`.
    pub fn build(world: &World, settings: IrradianceCacheSettings, counters: &mut Counters) -> IrradianceCache {
        let mut cache = IrradianceCache { records: Vec::new(), tree: RTree::new(), accuracy: settings.accuracy };
        let (width, height) = (world.settings.width, world.settings.height);
        for level in 0..LEVELS {
            let step = settings.spacing << (LEVELS - 1 - level);
            let points: Vec<(u32, u32)> = (0..height.div_ceil(step))
                .flat_map(|j| (0..width.div_ceil(step)).map(move |i| (i * step + step / 2, j * step + step / 2)))
                .filter(|&(x, y)| x < width && y < height)
                .collect();
            let found: Vec<(Vec<Record>, u64)> =
                points.par_iter().map(|&(x, y)| cache.records_at(world, settings, level, x, y)).collect();
            for (records, rays) in found {
                cache.records.extend(records);
                counters.rays += rays;
            }
            let a = cache.accuracy;
            cache.tree = RTree::bulk_load(
                cache
                    .records
                    .iter()
                    .enumerate()
                    .map(|(i, r)| {
                        let reach = Vec3::splat(a * r.r);
                        GeomWithData::new(
                            Rectangle::from_corners((r.p - reach).to_array(), (r.p + reach).to_array()),
                            i as u32,
                        )
                    })
                    .collect(),
            );
        }
        cache
    }

    /// Number of records.
    pub fn len(&self) -> usize {
        self.records.len()
    }

    /// True when the cache holds no record (nothing diffuse in view).
    pub fn is_empty(&self) -> bool {
        self.records.is_empty()
    }

    /// The interpolated mean incoming radiance (irradiance / pi) at `p` with unit normal
    /// `n`, or `None` where no record serves.
    pub(super) fn lookup(&self, p: Vec3, n: Vec3) -> Option<Color> {
        let (mut sum, mut weights) = (Color::ZERO, 0.0f32);
        for item in self.tree.locate_all_at_point(p.to_array()) {
            let r = &self.records[item.data as usize];
            let d = p - r.p;
            // Ward et al. 1988: a record in front of the point (above its plane) sees
            // light the point may not.
            if d.dot(n + r.n) < -1e-3 * r.r {
                continue;
            }
            let eps = d.length() / r.r + (1.0 - n.dot(r.n)).max(0.0).sqrt();
            if eps >= self.accuracy {
                continue;
            }
            let w = 1.0 / eps.max(1e-6) - 1.0 / self.accuracy;
            // First-order extrapolation by the gradients (Ward & Heckbert 1992, eq. 3).
            let turn = r.n.cross(n);
            let at = |c: usize| r.e[c] + turn.dot(r.rotation[c]) + d.dot(r.translation[c]);
            sum += w * Color::new(at(0), at(1), at(2)).max(Color::ZERO);
            weights += w;
        }
        (weights > 0.0).then(|| sum / weights)
    }

    /// The records a pre-pass camera ray through the centre of pixel (`x`, `y`) makes, at
    /// the diffuse hits along it (through mirrors and semi-transparent hair) that no
    /// record serves yet; and the rays traced.
    fn records_at(
        &self,
        world: &World,
        settings: IrradianceCacheSettings,
        level: u32,
        x: u32,
        y: u32,
    ) -> (Vec<Record>, u64) {
        let mut sampler = PixelSampler::new(hash_combine(&[world.settings.seed, STREAM, level]), x, y, 0);
        let ray = world.camera.ray(x as f32 + 0.5, y as f32 + 0.5);
        let recorder = Recorder { cache: self, settings, found: RefCell::new(Vec::new()) };
        let mut tracer = Tracer::new(world);
        trace(&mut tracer, &ray, Bounce::camera(CameraHint::None), &mut sampler, &recorder);
        (recorder.found.into_inner(), tracer.counters.rays)
    }
}

/// The pre-pass's "integrator": follows camera and specular rays like the final gather,
/// and at diffuse hits no record serves, gathers a new record instead of light.
struct Recorder<'a> {
    cache: &'a IrradianceCache,
    settings: IrradianceCacheSettings,
    found: RefCell<Vec<Record>>,
}

impl Indirect for Recorder<'_> {
    fn diffuse(&self, tracer: &mut Tracer, at: &Interaction, depth: u32, sampler: &mut PixelSampler) -> Color {
        if cached_albedo(at).is_some() && self.cache.lookup(at.sp.p, at.sp.normal).is_none() {
            let record = gather_record(tracer, at, depth, self.settings, sampler);
            self.found.borrow_mut().push(record);
        }
        Color::ZERO
    }
}

/// Gathers a record at a diffuse hit: `rays` cosine-weighted directions stratified in
/// `M` rings of equal weight (`sin^2 theta` uniform) by `N` sectors, `N` about `pi M`
/// (Ward & Heckbert 1992, section 2), each returning what the final gather's rays return.
fn gather_record(
    tracer: &mut Tracer,
    at: &Interaction,
    depth: u32,
    settings: IrradianceCacheSettings,
    sampler: &mut PixelSampler,
) -> Record {
    let sp = &at.sp;
    let n = sp.normal;
    let (b1, b2) = frame(n);
    let rings = ((settings.rays as f32 / PI).sqrt().round() as usize).max(2);
    let sectors = (settings.rays as usize / rings).max(3);
    let count = (rings * sectors) as f32;
    let sector = |phi: f32| b1 * phi.cos() + b2 * phi.sin();
    // Radiance and hit distance per stratum, ring-major.
    let mut radiance = vec![Color::ZERO; rings * sectors];
    let mut dist = vec![f32::INFINITY; rings * sectors];
    let (mut inverse_dist, mut rotation) = (0.0f32, [Vec3::ZERO; 3]);
    for j in 0..rings {
        let centre = (j as f32 + 0.5) / rings as f32;
        let tan_centre = (centre / (1.0 - centre)).sqrt();
        for k in 0..sectors {
            let (u, v) = sampler.next_2d();
            let sin2 = (j as f32 + u) / rings as f32;
            let (sin_t, cos_t) = (sin2.sqrt(), (1.0 - sin2).max(0.0).sqrt());
            let phi = 2.0 * PI * (k as f32 + v) / sectors as f32;
            let dir = (sector(phi) * sin_t + n * cos_t).normalize();
            // A record stands for many pixels: its rays see strands at full detail.
            let ray = Ray { cone: RayCone::default(), ..at.spawn_ray(dir) };
            let gathered = Whitted { see_emitters: false };
            let (l, first) = trace(tracer, &ray, Bounce::scattered(depth + 1, false), sampler, &gathered);
            let t = first.map_or(f32::INFINITY, |f| f.t);
            radiance[j * sectors + k] = l;
            dist[j * sectors + k] = t;
            inverse_dist += 1.0 / t;
            // Rotational gradient (Ward & Heckbert 1992, eq. 5): turning the normal about
            // the axis `v` (a quarter turn after the sample's azimuth) raises its cosine
            // by `tan theta` per radian, relative to the cosine it was drawn with.
            let v = sector(phi + 0.5 * PI);
            for (c, g) in rotation.iter_mut().enumerate() {
                *g += v * (tan_centre * l[c] / count);
            }
        }
    }
    // Translational gradient (after Ward & Heckbert 1992, eq. 6): moving the point shifts
    // every boundary between strata by the angle the scene behind it turns through, about
    // dx cos(theta) / R across rings and dx / (R sin(theta)) across sectors (R the nearer
    // hit of the two strata); the light changes by the radiance difference across the
    // boundary times the cosine-weighted solid angle swept. Divided by pi as `e` is.
    let mut translation = [Vec3::ZERO; 3];
    let ring_sin = |j: usize| (j as f32 / rings as f32).sqrt();
    for k in 0..sectors {
        let across_rings = sector(2.0 * PI * (k as f32 + 0.5) / sectors as f32);
        let across_sectors = sector(2.0 * PI * k as f32 / sectors as f32 + 0.5 * PI);
        let before = (k + sectors - 1) % sectors;
        for j in 0..rings {
            let (sin_lo, sin_hi) = (ring_sin(j), ring_sin(j + 1));
            let here = j * sectors + k;
            let mut add = |other: usize, dir: Vec3, weight: f32| {
                let r = dist[here].min(dist[other]);
                if r.is_finite() && r > 0.0 {
                    let diff = radiance[here] - radiance[other];
                    for (c, g) in translation.iter_mut().enumerate() {
                        *g += dir * (weight * diff[c] / (r * PI));
                    }
                }
            };
            if j > 0 {
                let cos2 = 1.0 - sin_lo * sin_lo;
                add((j - 1) * sectors + k, across_rings, 2.0 * PI / sectors as f32 * sin_lo * cos2);
            }
            add(j * sectors + before, across_sectors, sin_hi - sin_lo);
        }
    }
    let e = radiance.iter().sum::<Color>() / count;
    let harmonic = if inverse_dist > 0.0 { count / inverse_dist } else { f32::INFINITY };
    // Screen-space clamp: a record serves between `spacing` and `8 spacing` pixels around it.
    let scale = at.footprint() * settings.spacing as f32 / settings.accuracy;
    let r = if scale > 0.0 {
        harmonic.clamp(scale, scale * (1 << (LEVELS - 1)) as f32)
    } else {
        harmonic.min(tracer.world.accel.bounds().half_area().sqrt())
    };
    // Gradient limiting (Krivanek & Gautron 2009, "Practical Global Illumination with
    // Irradiance Caching"): within its reach a record extrapolates at most to 0 or to
    // twice its value, so a hit very near (a strand over a floor) cannot overshoot.
    let reach = settings.accuracy * r;
    for (c, g) in translation.iter_mut().enumerate() {
        let most = e[c] / reach;
        if g.length() > most {
            *g = g.normalize_or_zero() * most;
        }
    }
    Record { p: sp.p, n, e, r, rotation, translation }
}
