//! How much memory a scene will take, estimated from its description and the headers of
//! its files before anything is loaded, so a scene too big for the machine (or for a farm
//! slot's limit) is refused at once rather than after minutes of loading, or by the
//! kernel's out-of-memory killer.

use crate::error::{LoadError, PrepareError};
use crate::film::Pixel;
use crate::io;
use crate::scene::{Description, GuideSource, HairSource, MeshSource};
use std::path::Path;

/// Bytes of BVH per primitive: 64-byte nodes of four children whose leaves hold up to four
/// items, plus a 4-byte item id each. Measured on the demo scene (`tress info`): 16 bytes
/// per segment; 32 leaves room for poorer trees.
const BVH_BYTES: u64 = 32;
/// Bytes per primitive while a BVH is built: its build items (a box and an id, 28 bytes)
/// and the binary tree before it is collapsed into 4-wide nodes.
const BUILD_BYTES: u64 = 96;
/// Copies of the image held at once: the film being rendered, a snapshot for a checkpoint
/// or the output, and the encoder's channel arrays.
const IMAGE_COPIES: u64 = 3;

/// Estimated bytes of a scene, by part.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MemoryEstimate {
    /// Meshes and strands: positions, radii, indices, colours.
    pub geometry: u64,
    /// The BVHs, and the temporary data of building them.
    pub bvh: u64,
    /// The image being rendered and written.
    pub image: u64,
    /// Fur map images, decoded.
    pub maps: u64,
}

impl MemoryEstimate {
    /// Everything together.
    pub fn total(&self) -> u64 {
        self.geometry.saturating_add(self.bvh).saturating_add(self.image).saturating_add(self.maps)
    }

    fn add(&mut self, geometry: u64, primitives: u64) {
        self.geometry = self.geometry.saturating_add(geometry);
        self.bvh = self.bvh.saturating_add(primitives.saturating_mul(BVH_BYTES + BUILD_BYTES));
    }
}

/// Estimates the memory a render of `desc` needs, reading only the headers of its files
/// (OBJ files, which have none, are scanned for their `v` and `f` lines); fur is counted
/// from its density and segments.
pub fn estimate_memory(desc: &Description) -> Result<MemoryEstimate, LoadError> {
    let mut e = MemoryEstimate::default();
    for m in &desc.contents.meshes {
        let (vertices, triangles) = match &m.source {
            MeshSource::Inline(mesh) => (mesh.positions.len() as u64, mesh.indices.len() as u64),
            MeshSource::File(path) => mesh_counts(path)?,
        };
        // Positions, normals and texture coordinates (an upper bound when a file lacks
        // them), and three indices per triangle.
        e.add(vertices * (12 + 12 + 8) + triangles * 12, triangles);
    }
    for h in &desc.contents.hair {
        let (strands, points, colors, opacity) = match &h.source {
            HairSource::Inline(s) => {
                (s.strand_count() as u64, s.points.len() as u64, s.colors.is_some(), s.opacity.is_some())
            }
            HairSource::File(path) => {
                let c = io::cem_hair::read_hair_counts(path)?;
                (u64::from(c.strands), u64::from(c.points), c.colors && h.file_colors, c.opacity)
            }
        };
        let per_point = 16 + if colors { 12 } else { 0 } + if opacity { 4 } else { 0 };
        // Each strand's first point starts no segment.
        e.add(points * per_point + strands * 4, points.saturating_sub(strands));
    }
    for h in &desc.contents.hair_systems {
        // Guides: `n` points each become `(n - 1) * (sub_segments + 1) + 2` points of every
        // hair of their clump (`hair_system::expand`).
        let (guides, guide_points) = match &h.guides {
            GuideSource::File(path) => {
                let c = io::cem_hair::read_hair_counts(path)?;
                (u64::from(c.strands), u64::from(c.points))
            }
            GuideSource::Inline(g) => (g.curves.strand_count() as u64, g.curves.points.len() as u64),
            GuideSource::Follicles { params, .. } => {
                let count = match params.placement {
                    crate::hair_system::Placement::Grid { u, v } => u64::from(u) * u64::from(v),
                    crate::hair_system::Placement::Random { count } => u64::from(count),
                };
                (count, count.saturating_mul(u64::from(params.points_per_hair)))
            }
        };
        let steps = u64::from(h.system.sub_segments) + 1;
        let per_clump = u64::from(h.system.hairs_per_clump);
        let strands = guides.saturating_mul(per_clump);
        let points = (guide_points.saturating_sub(guides).saturating_mul(steps).saturating_add(2 * guides))
            .saturating_mul(per_clump);
        // A point and a colour; a root UV and clump per hair. The clumps are expanded apart
        // and then joined, so both copies are held at the peak.
        let bytes = points.saturating_mul(16 + 12).saturating_add(strands.saturating_mul(4 + 8 + 4));
        e.add(bytes.saturating_mul(2), points.saturating_sub(strands));
    }
    for f in &desc.contents.fur {
        // Density is the expected root count over the whole mesh (baldness only removes
        // roots), each hair `segments + 1` points with a colour and an opacity, and a root
        // UV and clump per hair.
        let d = &f.description;
        let strands = u64::from(d.density.min(crate::fur::description::MAX_DENSITY));
        let points = strands * (u64::from(d.segments) + 1);
        e.add(points * (16 + 12 + 4) + strands * (4 + 8 + 4), strands * u64::from(d.segments));
        for path in crate::fur::image_map_paths(d) {
            let (w, h) = super::maps::map_dimensions(path)?;
            e.maps = e.maps.saturating_add(u64::from(w) * u64::from(h) * super::maps::DECODE_BYTES_PER_PIXEL);
        }
    }
    let s = &desc.settings;
    e.image = u64::from(s.width) * u64::from(s.height) * std::mem::size_of::<Pixel>() as u64 * IMAGE_COPIES;
    Ok(e)
}

/// Refuses a render of `desc` whose estimated memory is above `limit` bytes, or, without
/// a limit, above the memory the machine has available ([`crate::memory::available`]);
/// the error gives the estimate by part.
pub fn check_memory(desc: &Description, limit: Option<u64>) -> Result<MemoryEstimate, PrepareError> {
    let e = estimate_memory(desc)?;
    let (limit, what) = match limit {
        Some(l) => (l, "the memory limit of"),
        None => match crate::memory::available() {
            Some(a) => (a, "the memory available,"),
            None => return Ok(e),
        },
    };
    if e.total() > limit {
        let b = crate::stats::human_bytes;
        return Err(PrepareError::Invalid(format!(
            "the scene needs an estimated {} (geometry {}, BVH {}, image {}, maps {}), more than {what} {}",
            b(e.total()),
            b(e.geometry),
            b(e.bvh),
            b(e.image),
            b(e.maps),
            b(limit)
        )));
    }
    Ok(e)
}

fn mesh_counts(path: &Path) -> Result<(u64, u64), LoadError> {
    match path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
        Some("obj") => io::obj::count_obj(path),
        // A polygon of the PLY file is usually a triangle or a quad: count two triangles.
        Some("ply") => io::ply::read_ply_counts(path).map(|(v, f)| (v, 2 * f)),
        _ => Err(LoadError::format(path, "unknown mesh format: expected a .obj or .ply file")),
    }
}

/// Parses a memory size: a number of bytes with an optional binary suffix `K`, `M`, `G`
/// or `T` (powers of 1024; `B` and `iB` are accepted after it), e.g. `8G`, `512MiB`, `1.5G`.
pub fn parse_memory_size(text: &str) -> Result<u64, String> {
    let t = text.trim();
    let t = t.strip_suffix("iB").or_else(|| t.strip_suffix('B')).unwrap_or(t);
    let (number, scale) = match t.char_indices().last() {
        Some((i, c)) if c.is_ascii_alphabetic() => {
            let power = match c.to_ascii_uppercase() {
                'K' => 1,
                'M' => 2,
                'G' => 3,
                'T' => 4,
                _ => return Err(format!("`{text}` is not a memory size such as 8G or 512M")),
            };
            (&t[..i], 1024f64.powi(power))
        }
        _ => (t, 1.0),
    };
    match number.trim().parse::<f64>() {
        Ok(n) if n.is_finite() && n >= 0.0 && n * scale < u64::MAX as f64 => Ok((n * scale) as u64),
        _ => Err(format!("`{text}` is not a memory size such as 8G or 512M")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stats::Memory;

    #[test]
    fn memory_sizes_parse() {
        assert_eq!(parse_memory_size("8G"), Ok(8 << 30));
        assert_eq!(parse_memory_size("512MiB"), Ok(512 << 20));
        assert_eq!(parse_memory_size("1.5k"), Ok(1536));
        assert_eq!(parse_memory_size("100"), Ok(100));
        assert_eq!(parse_memory_size("2TB"), Ok(2 << 40));
        for bad in ["", "G", "8X", "-1G", "nanG", "1e30T"] {
            assert!(parse_memory_size(bad).is_err(), "{bad}");
        }
    }

    /// The estimate covers what the prepared scene holds, without overstating it wildly.
    #[test]
    fn estimate_brackets_the_prepared_scene() {
        let mut desc = crate::demo::description(3000, 1);
        (desc.settings.width, desc.settings.height) = (64, 48);
        let e = estimate_memory(&desc).unwrap();
        let (world, _) = super::super::prepare(&desc).unwrap();
        let m = Memory::of(&world.accel);
        let held = m.strand_points + m.strand_bvh + m.mesh + m.mesh_bvh + m.top_bvh;
        assert!(e.geometry + e.bvh >= held, "estimate {e:?} below the {held} bytes held");
        assert!(e.geometry + e.bvh <= 6 * held, "estimate {e:?} far above the {held} bytes held");
        assert_eq!(e.image, 64 * 48 * std::mem::size_of::<Pixel>() as u64 * IMAGE_COPIES);
    }

    /// A hair system's render hairs are counted from its follicles and clumps.
    #[test]
    fn hair_systems_are_estimated() {
        let scene = "[camera]\neye = [0, 0, 4]\ntarget = [0, 0, 0]\n[render]\nresolution = [8, 8]\n\
            [[mesh]]\nshape = { type = \"sphere\", radius = 1.0 }\nmaterial = { type = \"diffuse\", color = [1, 1, 1] }\n\
            [[hair_system]]\nfollicles = { mesh = 1, placement = \"grid\", u = 30, v = 20, points_per_hair = 6, length = 0.3 }\n\
            hairs_per_clump = 8\nsub_segments = 1\n";
        let desc = io::scene_file::parse(scene, Path::new("h.toml"), None).unwrap().0;
        let e = estimate_memory(&desc).unwrap();
        let (world, _) = super::super::prepare(&desc).unwrap();
        let m = Memory::of(&world.accel);
        assert_eq!(m.strands, 30 * 20 * 8);
        let held = m.strand_points + m.strand_bvh;
        assert!(e.geometry + e.bvh >= held, "estimate {e:?} below the {held} bytes held");
        assert!(e.geometry + e.bvh <= 8 * held, "estimate {e:?} far above the {held} bytes held");
    }

    #[test]
    fn files_are_estimated_from_their_headers() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let desc = io::scene_file::read(&root.join("scenes/lights_and_glass.toml"), None).unwrap().0;
        let e = estimate_memory(&desc).unwrap();
        // 3000 strands of the hair file dominate: 677 kB of file, more in memory with BVH.
        let counts = io::cem_hair::read_hair_counts(&root.join("scenes/hairy_torus.hair")).unwrap();
        assert_eq!(counts.strands, 3000);
        assert!(e.geometry > u64::from(counts.points) * 16 && e.bvh > 0, "{e:?}");
        assert_eq!(io::ply::read_ply_counts(&root.join("scenes/box.ply")).unwrap().0, 8);
        assert_eq!(io::obj::count_obj(&root.join("tests/data/cube.obj")).unwrap(), (8, 12));
        let mut missing = desc.clone();
        missing.contents.hair[0].source = HairSource::File(root.join("nowhere.hair"));
        assert!(estimate_memory(&missing).unwrap_err().to_string().contains("nowhere.hair"));
    }
}
