//! [`Contents`]: the lights and entries of a scene, shared by the scene TOML, the importers
//! and the demo, with what is done to the lists as a whole: appending another scene's,
//! moving them, overriding strand widths, validating them.

use super::{FurEntry, GuideSource, HairEntry, HairSource, HairSystemEntry, LightSource, MeshEntry, MeshSource};
use crate::error::PrepareError;
use crate::light::Light;
use crate::math::Aabb;
use glam::{Affine3A, Vec3};

/// The lights and entries of a scene: what [`super::Description`] holds besides the camera
/// and settings, and what an importer reads from another tool's file.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Contents {
    /// Lights, in world space.
    pub lights: Vec<LightSource>,
    /// Meshes.
    pub meshes: Vec<MeshEntry>,
    /// Strand sets.
    pub hair: Vec<HairEntry>,
    /// Hair systems; follicle guides index [`Contents::meshes`].
    pub hair_systems: Vec<HairSystemEntry>,
    /// Fur grown on meshes; `mesh` indexes [`Contents::meshes`].
    pub fur: Vec<FurEntry>,
}

impl Contents {
    /// Appends `other`'s lights and entries after these, so the indices of these stay as
    /// they are; `other`'s fur and follicle guides, which name meshes by index, move by the
    /// meshes before them.
    pub fn append(&mut self, other: Contents) {
        let offset = self.meshes.len();
        self.lights.extend(other.lights);
        self.meshes.extend(other.meshes);
        self.hair.extend(other.hair);
        self.hair_systems.extend(other.hair_systems.into_iter().map(|mut h| {
            if let GuideSource::Follicles { mesh, .. } = &mut h.guides {
                *mesh += offset;
            }
            h
        }));
        self.fur.extend(other.fur.into_iter().map(|f| FurEntry { mesh: f.mesh + offset, ..f }));
    }

    /// Every entry's visibility: meshes, strand sets, hair systems and fur.
    pub fn visibilities_mut(&mut self) -> impl Iterator<Item = &mut super::Visibility> {
        (self.meshes.iter_mut().map(|e| &mut e.visibility))
            .chain(self.hair.iter_mut().map(|e| &mut e.visibility))
            .chain(self.hair_systems.iter_mut().map(|e| &mut e.visibility))
            .chain(self.fur.iter_mut().map(|e| &mut e.visibility))
    }

    /// Applies `m` on top of every entry's and light's own transform (a TOML `[[import]]`'s
    /// `transform`). Follicle guides and fur follow the meshes they grow on.
    pub fn transform(&mut self, m: &Affine3A) {
        for e in &mut self.meshes {
            e.transform = *m * e.transform;
        }
        for e in &mut self.hair {
            e.transform = *m * e.transform;
        }
        for e in &mut self.hair_systems {
            e.transform = *m * e.transform;
        }
        for l in &mut self.lights {
            match l {
                LightSource::Inline(l) => *l = transform_light(l, m),
                // Infinitely far, as an inline map below.
                LightSource::File(f) => f.placement = f.placement.rotated(crate::math::orthogonal_part(m)),
            }
        }
    }

    /// The bounds in world space of the meshes, strand sets and hair-system guides held in
    /// memory (empty when there are none). Entries that name a file are left out:
    /// `io::bounds` reads them and adds theirs.
    pub fn bounds(&self) -> Aabb {
        let meshes = self.meshes.iter().filter_map(|e| match &e.source {
            MeshSource::Inline(m) => Some(m.bounds_under(&e.transform)),
            MeshSource::File(_) => None,
        });
        let hair = self.hair.iter().filter_map(|e| match &e.source {
            HairSource::Inline(s) => Some(s.bounds_under(&e.transform)),
            HairSource::File(_) => None,
        });
        let guides = self.hair_systems.iter().filter_map(|e| match &e.guides {
            GuideSource::Inline(g) => Some(g.curves.bounds_under(&e.transform)),
            GuideSource::File(_) | GuideSource::Follicles { .. } => None,
        });
        meshes.chain(hair).chain(guides).fold(Aabb::EMPTY, Aabb::union)
    }

    /// Draws every strand `width` wide: the strand sets held in memory (their points'
    /// radii, with `radius_scale` reset to 1) and the hairs of hair systems (their
    /// `hair_width`). Strand sets named by file are left as they are: read them first
    /// (`io::override_hair_width` does).
    pub fn set_hair_width(&mut self, width: f32) {
        for e in &mut self.hair {
            if let HairSource::Inline(s) = &mut e.source {
                s.points.iter_mut().for_each(|p| p[3] = 0.5 * width);
            }
            e.radius_scale = 1.0;
        }
        for e in &mut self.hair_systems {
            e.system.hair_width = width;
        }
    }

    /// Multiplies every strand's radius by `k` (strand sets and hair systems alike).
    pub fn scale_hair_radius(&mut self, k: f32) {
        for e in &mut self.hair {
            e.radius_scale *= k;
        }
        for e in &mut self.hair_systems {
            e.system.hair_width *= k;
        }
    }

    /// Checks the entries for values no render can use: level of detail, radius scales,
    /// hair-system attributes and follicles, fur and the meshes they name.
    pub fn validate(&self) -> Result<(), PrepareError> {
        let lods = (self.hair.iter().map(|h| ("hair", h.lod)).enumerate())
            .chain(self.hair_systems.iter().map(|h| ("hair_system", h.lod)).enumerate())
            .chain(self.fur.iter().map(|f| ("fur", f.lod)).enumerate());
        for (i, (kind, p)) in lods {
            if let Some(p) = p {
                p.validate().map_err(|e| PrepareError::Invalid(format!("{kind} {}: {e}", i + 1)))?;
            }
        }
        for h in &self.hair {
            if !(h.radius_scale.is_finite() && h.radius_scale >= 0.0) {
                return Err(PrepareError::Invalid(format!(
                    "hair radius_scale {} must be finite and >= 0",
                    h.radius_scale
                )));
            }
        }
        for (i, h) in self.hair_systems.iter().enumerate() {
            let what = |e: String| PrepareError::Invalid(format!("hair_system {}: {e}", i + 1));
            h.system.validate().map_err(what)?;
            if let GuideSource::Follicles { mesh, params } = &h.guides {
                params.validate().map_err(what)?;
                if *mesh >= self.meshes.len() {
                    return Err(what(format!(
                        "follicles `mesh = {}` names no mesh (the scene has {})",
                        mesh + 1,
                        self.meshes.len()
                    )));
                }
            }
        }
        for (i, f) in self.fur.iter().enumerate() {
            let what = |e: String| PrepareError::Invalid(format!("fur {}: {e}", i + 1));
            if f.mesh >= self.meshes.len() {
                return Err(what(format!("`mesh` = {} names no mesh (there are {})", f.mesh + 1, self.meshes.len())));
            }
            f.description.validate().map_err(what)?;
            if let Some((_, a)) = &f.guides {
                a.validate().map_err(what)?;
            }
        }
        Ok(())
    }
}

/// `l` moved by `m` (directions keep unit length; radii and intensities stay).
fn transform_light(l: &Light, m: &Affine3A) -> Light {
    let dir = |d: Vec3| m.transform_vector3(d).normalize_or(d);
    match *l {
        Light::Distant { direction, irradiance } => Light::Distant { direction: dir(direction), irradiance },
        Light::Sun { direction, radiance, cos_max } => Light::Sun { direction: dir(direction), radiance, cos_max },
        Light::Point { position, intensity, decay } => {
            Light::Point { position: m.transform_point3(position), intensity, decay }
        }
        Light::Spot { position, direction, intensity, cos_inner, cos_outer, decay } => Light::Spot {
            position: m.transform_point3(position),
            direction: dir(direction),
            intensity,
            cos_inner,
            cos_outer,
            decay,
        },
        Light::Quad { corner, edge_u, edge_v, radiance, camera_visibility } => Light::Quad {
            corner: m.transform_point3(corner),
            edge_u: m.transform_vector3(edge_u),
            edge_v: m.transform_vector3(edge_v),
            radiance,
            camera_visibility,
        },
        Light::Sphere { center, radius, radiance, camera_visibility } => {
            Light::Sphere { center: m.transform_point3(center), radius, radiance, camera_visibility }
        }
        Light::Mesh(ref mesh) => Light::Mesh(mesh.transformed(m)),
        Light::Environment { radiance, camera_visibility } => Light::Environment { radiance, camera_visibility },
        // Infinitely far: only the transform's orthogonal part turns it, its rotation and,
        // when the transform mirrors (its determinant is negative), that reflection.
        Light::EnvironmentMap(ref map) => Light::EnvironmentMap(map.rotated(crate::math::orthogonal_part(m))),
    }
}
