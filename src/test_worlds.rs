//! Worlds for the unit tests of the modules below [`crate::prepare`] (the renderer's),
//! prepared the way a user's scene is, so those modules import neither [`crate::scene`]
//! nor [`crate::io`] themselves.

use crate::accel::lod::LodParams;
use crate::world::World;

/// The demo (hair on a sphere over a ground plane, a distant light and the environment)
/// with `strands` strands grown from `seed`, at `width` x `height` and `spp` samples,
/// its hair with level of detail `lod`.
pub(crate) fn demo(strands: u32, seed: u64, (width, height, spp): (u32, u32, u32), lod: Option<LodParams>) -> World {
    let mut desc = crate::demo::description(strands, seed);
    (desc.settings.width, desc.settings.height, desc.settings.spp) = (width, height, spp);
    desc.contents.hair[0].lod = lod;
    crate::prepare::prepare(&desc).unwrap().0
}

/// The scene file `name` of the repository's `scenes/` directory at `width` x `height`.
pub(crate) fn scene_file(name: &str, (width, height): (u32, u32)) -> World {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name);
    let mut desc = crate::io::scene_file::read(&path, None).unwrap().0;
    (desc.settings.width, desc.settings.height) = (width, height);
    crate::prepare::prepare(&desc).unwrap().0
}
