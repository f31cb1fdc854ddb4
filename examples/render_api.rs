//! The library API in one page: a scene built in code (a sphere with Maya's Mouse fur
//! preset over a ground plane, a sun and a sky), prepared and rendered, then written.
//!
//! `cargo run --release --example render_api -- [OUT.png|OUT.exr]` (default
//! `render_api.png`; a few seconds).

use glam::{Affine3A, Vec3};
use tress::geometry::TriangleMesh;
use tress::light::Light;
use tress::math::Color;
use tress::scene::{CameraDesc, Contents, Description, FurEntry, MeshEntry, MeshSource};
use tress::shading::Material;
use tress::world::RenderSettings;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let output = std::env::args().nth(1).unwrap_or_else(|| "render_api.png".into());
    let mut fur = tress::fur::presets::preset("Mouse")?;
    fur.density = 40_000;
    let desc = Description {
        camera: CameraDesc {
            eye: Vec3::new(0.0, 0.6, 3.0),
            target: Vec3::ZERO,
            up: Vec3::Y,
            vfov: 30.0,
            ..Default::default()
        },
        settings: RenderSettings { width: 320, height: 240, spp: 8, ..RenderSettings::default() },
        contents: Contents {
            lights: vec![
                Light::Distant { direction: Vec3::new(0.4, 0.9, 0.6).normalize(), irradiance: Color::splat(3.0) }
                    .into(),
                Light::Environment { radiance: Color::new(0.4, 0.45, 0.5), camera_visibility: 1.0 }.into(),
            ],
            meshes: vec![
                MeshEntry {
                    source: MeshSource::Inline(TriangleMesh::sphere(0.6, 48)),
                    material: Material::Diffuse { color: Color::new(0.35, 0.33, 0.3) }.into(),
                    transform: Affine3A::IDENTITY,
                    visibility: Default::default(),
                },
                MeshEntry {
                    source: MeshSource::Inline(TriangleMesh::plane(10.0)),
                    material: Material::Diffuse { color: Color::splat(0.5) }.into(),
                    transform: Affine3A::from_translation(Vec3::new(0.0, -0.7, 0.0)),
                    visibility: Default::default(),
                },
            ],
            // Fur grows on meshes[0], as placed in the world.
            fur: vec![FurEntry {
                mesh: 0,
                description: fur,
                placement: Default::default(),
                seed: 1,
                guides: None,
                lod: None,
                grows_on: None,
                width_profile: None,
                visibility: Default::default(),
            }],
            ..Default::default()
        },
    };
    desc.validate()?;
    // Growing the fur and building the BVHs; the world holds no paths and no description.
    let (world, times) = tress::prepare::prepare_owned(desc)?;
    eprintln!("prepared in {:.2} s; rendering 320x240 at 8 spp", (times.load + times.build).as_secs_f64());
    // Renders on the current rayon pool (every core); the pixels are the same for any
    // number of threads.
    let (film, stats) = tress::render::render(&world, None);
    tress::film::write_image(std::path::Path::new(&output), &film)?;
    eprintln!("wrote {output}: {} rays in {:.2} s", stats.rays, stats.elapsed.as_secs_f64());
    Ok(())
}
