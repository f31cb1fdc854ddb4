//! Preparing a scene: the only code that reads the geometry and image files a
//! [`Description`] names. It loads meshes and strand sets, grows hair systems and fur,
//! applies transforms and builds the acceleration structures into a [`World`].
//! Images are decoded here too: fur attribute maps ([`read_map_images`], handed to the fur
//! as texels), environment maps (`environment`) and textures (`images`).
//! [`estimate_memory`] predicts the memory of that step from file headers.

mod environment;
mod estimate;
mod images;
mod maps;

pub use estimate::{check_memory, estimate_memory, parse_memory_size, MemoryEstimate};
pub use maps::{read_map_images, MAX_MAP_SIDE};

use crate::accel::lod::LodParams;
use crate::accel::{Accel, Shape, Visibility};
use crate::camera::{Camera, CameraError, Projection};
use crate::error::{LoadError, PrepareError};
use crate::geometry::StrandSet;
use crate::hair_system::{self, Guides};
use crate::io;
use crate::light::Light;
use crate::scene::{
    CameraDesc, Description, GuideSource, HairSource, LightSource, MaterialSource, MeshSource, RoughnessSource,
};
use crate::shading::texture::ColorMap;
use crate::shading::{Material, Roughness, Textured};
use crate::world::World;
use images::{Encoding, Textures};
use std::time::{Duration, Instant};

/// How long preparing took, by stage.
#[derive(Clone, Copy, Debug, Default)]
pub struct PrepareTimes {
    /// Reading and transforming geometry, and reading environment maps.
    pub load: Duration,
    /// Building the BVHs.
    pub build: Duration,
    /// CPU time of building the BVHs, all threads together.
    pub build_cpu: Duration,
}

/// The geometry of a description, loaded and in world space, with one material per shape.
pub struct LoadedGeometry {
    /// Shapes with the index of their material.
    pub shapes: Vec<(Shape, u32)>,
    /// Materials, indexed by the shapes.
    pub materials: Vec<Material>,
    /// Level of detail per shape (meshes and strand sets without it: `None`).
    pub lods: Vec<Option<LodParams>>,
    /// Which rays see each shape.
    pub visibility: Vec<Visibility>,
    /// What was skipped: strands or triangles whose numbers are not finite once
    /// transformed (enormous coordinates scaled past the float range, NaN from a generator).
    pub warnings: Vec<String>,
}

/// Loads every mesh and strand set a description names and applies its transform; the
/// materials' textures are decoded too (each file once).
pub fn load_geometry(desc: &Description) -> Result<LoadedGeometry, PrepareError> {
    load_geometry_taking(desc, &mut [])
}

/// [`load_geometry`], with the inline strand sets of some hair entries already moved out
/// of the description (`taken[i]` for entry `i`): those are used as they are, not copied.
fn load_geometry_taking(desc: &Description, taken: &mut [Option<StrandSet>]) -> Result<LoadedGeometry, PrepareError> {
    let mut materials = Vec::new();
    let mut shapes = Vec::new();
    let mut warnings = Vec::new();
    let mut lods = Vec::new();
    let mut visibility = Vec::new();
    let mut textures = Textures::default();
    for (i, m) in desc.contents.meshes.iter().enumerate() {
        let mut mesh = match &m.source {
            MeshSource::File(path) => io::read_mesh(path)?,
            MeshSource::Inline(mesh) => mesh.clone(),
        };
        mesh.transform(&m.transform);
        lods.push(None);
        visibility.push(m.visibility);
        let dropped = mesh.remove_unusable_triangles();
        warnings.extend(skipped(("mesh", i), dropped, "triangles with corners"));
        shapes.push((Shape::Mesh(mesh), materials.len() as u32));
        materials.push(material(&m.material, &mut textures).map_err(|e| entry_error(("mesh", i), e))?);
    }
    for (i, h) in desc.contents.hair.iter().enumerate() {
        let mut strands = match &h.source {
            HairSource::File(path) => {
                let strands = io::cem_hair::read_hair(path)?;
                // A warning, not an error: a frame of a hair cache can be empty (hair that
                // grows in later), and the rest of the scene still renders.
                if strands.strand_count() == 0 {
                    warnings.push(format!(
                        "{}: the file holds no strands; hair {} renders nothing",
                        path.display(),
                        i + 1
                    ));
                }
                strands
            }
            HairSource::Inline(s) => taken.get_mut(i).and_then(Option::take).unwrap_or_else(|| s.clone()),
        };
        strands.transform(&h.transform);
        if h.radius_scale != 1.0 {
            strands.points.iter_mut().for_each(|p| p[3] *= h.radius_scale);
        }
        if !h.file_colors {
            strands.colors = None;
        }
        if let MaterialSource::Inline(Material::Physical(m)) = &h.material {
            if m.needs_strand_colors() && strands.colors.is_none() {
                let from = match &h.source {
                    HairSource::File(path) => path.display().to_string(),
                    HairSource::Inline(_) => "the strand set".into(),
                };
                return Err(PrepareError::Invalid(format!(
                    "hair {}: the material takes its colour from the strands (`from_file`), but {from} has no \
                     colours (or `file_colors = false` drops them)",
                    i + 1
                )));
            }
        }
        lods.push(h.lod);
        visibility.push(h.visibility);
        let dropped = strands.remove_unusable_strands();
        warnings.extend(skipped(("hair", i), dropped, "strands with coordinates or radii negative,"));
        shapes.push((Shape::Strands(strands), materials.len() as u32));
        materials.push(material(&h.material, &mut textures).map_err(|e| entry_error(("hair", i), e))?);
    }
    for (i, h) in desc.contents.hair_systems.iter().enumerate() {
        let what = |e: String| PrepareError::Invalid(format!("hair_system {}: {e}", i + 1));
        let guides = match &h.guides {
            GuideSource::File(path) => {
                let mut curves = io::cem_hair::read_hair(path)?;
                curves.transform(&h.transform);
                Guides::from_curves(curves)
            }
            GuideSource::Inline(guides) => {
                let mut guides = guides.clone();
                guides.curves.transform(&h.transform);
                guides
            }
            GuideSource::Follicles { mesh, params } => match shapes.get(*mesh) {
                // Meshes come first in `shapes`, in description order, already in world space.
                Some((Shape::Mesh(m), _)) => hair_system::grow_guides(m, params, h.seed).map_err(what)?,
                _ => return Err(what(format!("follicles `mesh = {}` names no mesh", mesh + 1))),
            },
        };
        let strands = hair_system::expand(&h.system, &guides, h.colors, h.seed).map_err(what)?;
        lods.push(h.lod);
        visibility.push(h.visibility);
        shapes.push((Shape::Strands(strands), materials.len() as u32));
        materials.push(material(&h.material, &mut textures).map_err(|e| entry_error(("hair_system", i), e))?);
    }
    for (i, f) in desc.contents.fur.iter().enumerate() {
        let what = |e: String| PrepareError::Invalid(format!("fur {}: {e}", i + 1));
        // Meshes come first among the shapes, in order.
        let Some((Shape::Mesh(mesh), _)) = shapes.get(f.mesh) else {
            return Err(what(format!("there is no mesh {}", f.mesh + 1)));
        };
        let guides = match &f.guides {
            Some((HairSource::File(path), attractors)) => Some((io::cem_hair::read_hair(path)?, attractors)),
            Some((HairSource::Inline(s), attractors)) => Some((s.clone(), attractors)),
            None => None,
        };
        let images = read_map_images(&f.description)?;
        let options = crate::fur::GrowOptions {
            placement: f.placement,
            seed: f.seed,
            guides: guides.as_ref().map(|(s, a)| (s, *a)),
            images: &images,
            grows_on: f.grows_on.as_deref(),
            width_profile: f.width_profile.as_deref(),
        };
        let grown = crate::fur::grow(mesh, &f.description, options).map_err(|e| what(e.to_string()))?;
        lods.push(f.lod);
        visibility.push(f.visibility);
        shapes.push((Shape::Strands(grown.strands), materials.len() as u32));
        materials.push(Material::Fur(grown.shading));
    }
    for (i, (shape, _)) in shapes.iter().enumerate() {
        if shape.primitive_count() > crate::accel::bvh::MAX_ITEMS {
            return Err(PrepareError::Invalid(format!(
                "object {} has {} primitives; one object holds at most {} (split the strands into several files)",
                i + 1,
                shape.primitive_count(),
                crate::accel::bvh::MAX_ITEMS
            )));
        }
    }
    Ok(LoadedGeometry { shapes, materials, lods, visibility, warnings })
}

/// The material of `source`, its textures decoded (each file once, in `textures`).
fn material(source: &MaterialSource, textures: &mut Textures) -> Result<Material, LoadError> {
    Ok(match source {
        MaterialSource::Inline(m) => m.clone(),
        MaterialSource::Textured(t) => Material::Textured(Textured {
            color: ColorMap::Image(textures.get(&t.color, Encoding::Srgb)?),
            tint: t.tint,
            roughness: match &t.roughness {
                None => None,
                Some(RoughnessSource::Constant(r)) => Some(Roughness::Constant(*r)),
                Some(RoughnessSource::Map(path)) => Some(Roughness::Map(textures.get(path, Encoding::Linear)?)),
            },
            specular: t.specular,
        }),
    })
}

/// The world's lights: inline ones as they are, environment files decoded. A file that
/// cannot be used is an error, or its fallback sky with a warning added to `warnings`.
fn lights(desc: &Description, warnings: &mut Vec<String>) -> Result<Vec<Light>, PrepareError> {
    let mut lights = Vec::with_capacity(desc.contents.lights.len());
    for (i, l) in desc.contents.lights.iter().enumerate() {
        lights.push(match l {
            LightSource::Inline(l) => l.clone(),
            LightSource::File(f) => match (environment::read(f), f.fallback) {
                (Ok((map, note)), _) => {
                    warnings.extend(note);
                    Light::EnvironmentMap(map)
                }
                (Err(e), Some(radiance)) => {
                    warnings.push(format!("light {}: {e}: lit by a constant sky of the light's colour instead", i + 1));
                    Light::Environment { radiance, camera_visibility: f.placement.camera_visibility() }
                }
                (Err(e), None) => return Err(entry_error(("light", i), e)),
            },
        });
    }
    Ok(lights)
}

/// An image of entry `index` (0-based) of kind `entry` that cannot be used, named in `e`.
fn entry_error((entry, index): (&str, usize), e: LoadError) -> PrepareError {
    PrepareError::Invalid(format!("{entry} {}: {e}", index + 1))
}

/// The warning for `dropped` primitives of entry `index` (0-based) of kind `entry` whose
/// `what` (a plural noun and what was checked) were not finite or beyond
/// [`crate::geometry::MAX_COORDINATE`]; `None` when nothing was dropped.
fn skipped((entry, index): (&str, usize), dropped: usize, what: &str) -> Option<String> {
    (dropped > 0).then(|| {
        format!(
            "{entry} {}: skipped {dropped} {what} not finite or beyond ±{:e}",
            index + 1,
            crate::geometry::MAX_COORDINATE
        )
    })
}

/// Loads geometry, applies transforms and builds the BVHs.
pub fn prepare(desc: &Description) -> Result<(World, PrepareTimes), PrepareError> {
    prepare_taking(desc, &mut [])
}

/// [`prepare`] for a description not needed afterwards: inline strand sets (the demo's,
/// other tools' scenes) are moved into the scene instead of copied, which keeps their whole
/// size (16 bytes a point: 2.6 GB for 150 million segments) off the peak of the build.
pub fn prepare_owned(mut desc: Description) -> Result<(World, PrepareTimes), PrepareError> {
    let mut taken: Vec<Option<StrandSet>> = desc
        .contents
        .hair
        .iter_mut()
        .map(|h| match &mut h.source {
            HairSource::Inline(s) => Some(std::mem::take(s)),
            HairSource::File(_) => None,
        })
        .collect();
    prepare_taking(&desc, &mut taken)
}

/// The camera a scene's camera description gives on a film of `width` x `height`
/// pixels: its projection (orthographic when the description has an orthographic height,
/// else perspective with the vertical field of view the film's aspect ratio gives), its
/// screen window and its clipping range.
pub fn camera(c: &CameraDesc, width: u32, height: u32) -> Result<Camera, CameraError> {
    let projection = match c.ortho_height_for(width, height) {
        Some(height) => Projection::Orthographic { height },
        None => Projection::Perspective { vfov_deg: c.vfov_for(width, height) },
    };
    let camera = Camera::new(c.eye, c.target, c.up, projection, width, height)?;
    let camera = match c.window == crate::scene::FULL_SCREEN {
        true => camera,
        false => camera.windowed(c.window[0], c.window[1])?,
    };
    camera.clipped(c.clip[0], c.clip[1])
}

fn prepare_taking(desc: &Description, taken: &mut [Option<StrandSet>]) -> Result<(World, PrepareTimes), PrepareError> {
    desc.validate()?;
    let camera = camera(&desc.camera, desc.settings.width, desc.settings.height)?;
    let start = Instant::now();
    let LoadedGeometry { shapes, materials, lods, visibility, mut warnings } = load_geometry_taking(desc, taken)?;
    let lights = lights(desc, &mut warnings)?;
    let load = start.elapsed();
    let (start, cpu) = (Instant::now(), crate::stats::process_cpu_time());
    // The global switch drops every strand set's level of detail.
    let lod = |p: Option<LodParams>| p.filter(|_| desc.settings.lod);
    let lod_camera = crate::accel::lod::LodCamera { eye: desc.camera.eye, cone: camera.pixel_cone() };
    let mut accel = Accel::build_with_lod_for(
        shapes.into_iter().zip(lods).map(|((s, m), l)| (in_spatial_order(s, lod(l)), m, lod(l))).collect(),
        Some(lod_camera),
    );
    accel.set_visibility(visibility);
    let build = start.elapsed();
    let build_cpu = crate::stats::process_cpu_time().saturating_sub(cpu);
    let background = lights.iter().map(Light::background).sum();
    let camera_background = lights.iter().map(|l| l.background() * l.camera_visibility()).sum();
    let ambient = lights.iter().map(Light::ambient).sum();
    let settings = desc.settings.clone();
    let world = World { camera, settings, lights, materials, accel, background, camera_background, ambient, warnings };
    Ok((world, PrepareTimes { load, build, build_cpu }))
}

/// A shape as the acceleration structure stores it: a strand set along a Morton curve
/// ([`StrandSet::reorder_spatially`]) for the memory locality of its BVH leaves, unless
/// rendering it hashes point indices, which the reorder changes: with level of detail
/// (segment jitter) or per-point opacity (stochastic transparency draws), it keeps the
/// file's order so that every image stays the same.
fn in_spatial_order(shape: Shape, lod: Option<LodParams>) -> Shape {
    match shape {
        Shape::Strands(mut s) if lod.is_none() && s.opacity.is_none() => {
            s.reorder_spatially();
            Shape::Strands(s)
        }
        shape => shape,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{Affine3A, Vec3};

    #[test]
    fn prepare_owned_moves_inline_strands_into_the_same_world() {
        // The demo's hair is inline and moved by `prepare_owned`, with a transform applied
        // after the move: the objects must equal those `prepare` builds from a copy.
        let mut desc = crate::demo::description(300, 5);
        desc.contents.hair[0].transform = Affine3A::from_translation(Vec3::new(0.1, 0.2, 0.3));
        let (copied, _) = prepare(&desc).unwrap();
        let (moved, _) = prepare_owned(desc.clone()).unwrap();
        let (a, b) = (strand_sets(&copied), strand_sets(&moved));
        assert_eq!(a.len(), 1);
        assert_eq!(a[0].strand_count(), 300);
        assert_eq!(a, b);
        assert_eq!(crate::partial::fingerprint(&copied), crate::partial::fingerprint(&moved));
    }

    /// Every strand set of `world`, in object order.
    fn strand_sets(world: &World) -> Vec<StrandSet> {
        world
            .accel
            .objects
            .iter()
            .filter_map(|o| match &o.shape {
                Shape::Strands(s) => Some(s.clone()),
                Shape::Mesh(_) => None,
            })
            .collect()
    }

    /// A hair system (per-strand root UV and clump, per-strand random diffuse colour) and
    /// opaque fur (per-strand mapped material arrays) on a torus: strand sets that
    /// `prepare` stores in Morton order.
    const STRAND_SCENE: &str = r#"
[camera]
eye = [0.0, 1.9, 3.7]
target = [0.0, -0.15, 0.0]
[render]
resolution = [96, 72]
spp = 2
[[light]]
type = "distant"
direction = [0.45, 0.8, 0.4]
irradiance = [3.0, 3.0, 3.0]
[[light]]
type = "environment"
radiance = [0.15, 0.15, 0.15]
[[mesh]]
shape = { type = "torus", major = 1.0, minor = 0.35 }
material = { type = "diffuse", color = [0.3, 0.22, 0.15] }
[[hair_system]]
follicles = { mesh = 1, placement = "grid", u = 40, v = 12, randomization = 0.7, points_per_hair = 6, length = 0.3 }
seed = 1
hairs_per_clump = 6
clump_width = 0.09
hair_width = 0.004
hair_color = [0.35, 0.2, 0.1]
diffuse_rand = 0.5
[[fur]]
mesh = 1
preset = "Squirrel"
density = 3000
tip_opacity = 1.0
seed = 3
"#;

    #[test]
    fn strands_in_spatial_order_give_the_hits_strand_ids_and_image_of_file_order() {
        let desc = crate::io::scene_file::parse(STRAND_SCENE, std::path::Path::new("order.toml"), None).unwrap().0;
        let (world, _) = prepare(&desc).unwrap();
        // The same scene with its strands in the file's order.
        let geometry = load_geometry(&desc).unwrap();
        let file = World {
            camera: world.camera.clone(),
            settings: world.settings.clone(),
            lights: world.lights.clone(),
            materials: geometry.materials,
            accel: Accel::build(geometry.shapes),
            background: world.background,
            camera_background: world.camera_background,
            ambient: world.ambient,
            warnings: Vec::new(),
        };
        let (moved, kept) = (strand_sets(&world), strand_sets(&file));
        assert_eq!(moved.len(), 2);
        for (m, k) in moved.iter().zip(&kept) {
            assert!(k.file_order.is_none());
            let order = m.file_order.as_ref().expect("an opaque set without level of detail is reordered");
            assert!(order.windows(2).any(|w| w[0] > w[1]), "the order changed");
            assert_eq!(m.strand_count(), k.strand_count());
        }
        // Every camera ray's hit: same distance and normal, same strand by its file index,
        // same place along it; hit segments are the same points of that strand.
        let (w, h) = (world.settings.width, world.settings.height);
        let mut strand_hits = 0;
        for y in 0..h {
            for x in 0..w {
                let ray = world.camera.ray(x as f32 + 0.5, y as f32 + 0.5);
                let (a, b) = (world.accel.intersect(&ray), file.accel.intersect(&ray));
                assert_eq!(a.map(|h| (h.t, h.object, h.kind)), b.map(|h| (h.t, h.object, h.kind)), "pixel {x}, {y}");
                let (Some(a), Some(b)) = (a, b) else { continue };
                if let (Shape::Strands(m), Shape::Strands(k)) =
                    (&world.accel.objects[a.object as usize].shape, &file.accel.objects[b.object as usize].shape)
                {
                    assert_eq!(m.hit_point(a.prim, 0.3), k.hit_point(b.prim, 0.3));
                    assert_eq!(m.points[a.prim as usize], k.points[b.prim as usize]);
                    strand_hits += 1;
                }
            }
        }
        assert!(strand_hits > (w * h / 5) as usize, "the test needs strand hits: {strand_hits}");
        // The image and every AOV (strandId, strand random, root UV, clump) bit for bit.
        let (a, b) = (crate::render::render(&world, None).0, crate::render::render(&file, None).0);
        assert!(a == b, "the reordered scene renders another image");
        assert!(a.pixels.iter().any(|p| p.strand_id >= 0.0 && p.clump_id >= 0.0 && p.root_uv[0] >= 0.0));
    }
}
