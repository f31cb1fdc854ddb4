"""The Blender add-on in a real Blender (``bpy`` from pip, headless): a hair curves object
on a sphere, a camera and a sun, rendered through the tress engine and exported."""

import math
import os

import pytest

bpy = pytest.importorskip("bpy", reason="Blender's Python module is not installed (pip install bpy==5.0.1)")
np = pytest.importorskip("numpy")
tress = pytest.importorskip("tress", reason="the tress Python package is not installed")

from tress_testing import run_cli  # noqa: E402
from tress_addon import export, materials  # noqa: E402


@pytest.fixture(scope="module")
def addon():
    import tress_addon

    tress_addon.register()
    yield tress_addon
    tress_addon.unregister()


def make_scene(width=48, height=36):
    """Factory-empty scene: a UV sphere, a hair curves object of short strands on it, a
    camera and a sun."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.resolution_percentage = 100
    bpy.ops.mesh.primitive_uv_sphere_add(radius=1.0, segments=16, ring_count=8)
    sphere = bpy.context.active_object
    mat = bpy.data.materials.new("skin")
    mat.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0.6, 0.5, 0.4, 1.0)
    sphere.data.materials.append(mat)

    rng = np.random.default_rng(3)
    count, per = 40, 5
    roots = rng.normal(size=(count, 3))
    roots /= np.linalg.norm(roots, axis=1, keepdims=True)
    t = np.linspace(0, 1, per)
    pts = (roots[:, None, :] * (1.0 + 0.5 * t[None, :, None])).reshape(-1, 3)
    curves = bpy.data.hair_curves.new("groom")
    curves.add_curves([per] * count)
    curves.position_data.foreach_set("vector", pts.astype(np.float32).ravel())
    radius = np.tile(np.linspace(0.03, 0.01, per), count).astype(np.float32)
    attr = curves.attributes.get("radius") or curves.attributes.new("radius", "FLOAT", "POINT")
    attr.data.foreach_set("value", radius)
    hair_mat = bpy.data.materials.new("hair")
    tree = hair_mat.node_tree
    tree.nodes.clear()
    node = tree.nodes.new("ShaderNodeBsdfHairPrincipled")
    node.parametrization = "MELANIN"
    node.inputs["Melanin"].default_value = 0.6
    node.inputs["Melanin Redness"].default_value = 0.3
    node.inputs["Roughness"].default_value = 0.25
    out = tree.nodes.new("ShaderNodeOutputMaterial")
    tree.links.new(node.outputs[0], out.inputs["Surface"])
    curves.materials.append(hair_mat)
    groom = bpy.data.objects.new("groom", curves)
    groom.location = (0.0, 0.0, 0.1)
    groom.scale = (1.0, 1.0, 1.0)
    scene.collection.objects.link(groom)

    cam_data = bpy.data.cameras.new("cam")
    cam_data.lens = 40.0
    cam = bpy.data.objects.new("cam", cam_data)
    cam.location = (0.0, -6.0, 0.5)
    cam.rotation_euler = (math.radians(87.0), 0.0, 0.0)
    scene.collection.objects.link(cam)
    scene.camera = cam

    sun_data = bpy.data.lights.new("sun", "SUN")
    sun_data.energy = 3.0
    sun = bpy.data.objects.new("sun", sun_data)
    sun.rotation_euler = (math.radians(40.0), math.radians(20.0), 0.0)
    scene.collection.objects.link(sun)
    scene.render.engine = "TRESS"
    scene.tress.spp = 2
    scene.tress.threads = 2
    scene.view_settings.view_transform = "Standard"
    return scene, groom, cam, sun


def test_principled_hair_node_in_blender_maps_its_inputs(addon):
    scene, groom, _, _ = make_scene()
    m, warnings = materials.from_material(groom.data.materials[0], export.DEFAULT_HAIR, hair=True)
    q = -math.log(1 - 0.6)
    assert m["eumelanin"] == pytest.approx(q * 0.7, rel=1e-6)
    assert m["beta_m"] == pytest.approx(0.25, rel=1e-6)
    # Blender's default offset is 2 degrees, its default IOR 1.55, radial roughness 0.3.
    assert m["alpha"] == pytest.approx(2.0, rel=1e-5) and m["eta"] == pytest.approx(1.55, rel=1e-6)
    assert m["beta_n"] == pytest.approx(0.3, rel=1e-6)


def test_export_matches_blender(addon, tmp_path):
    scene, groom, cam, sun = make_scene()
    depsgraph = bpy.context.evaluated_depsgraph_get()
    doc, warnings = export.build(depsgraph, {"spp": 2})
    (hair,) = doc.hair
    strands = doc.files[hair["file"]]
    curves = groom.evaluated_get(depsgraph).data
    assert strands.strand_count == len(curves.curves) == 40
    radius = np.array([p.radius for p in curves.points], np.float32)
    assert np.array_equal(strands.radius, radius)
    world_points = np.array([groom.matrix_world @ p.position for p in curves.points], np.float32)
    assert np.allclose(strands.points, world_points, atol=1e-6)
    # Camera: Blender's own field of view (AUTO fit, landscape: sensor width across).
    fov_x = 2 * math.atan(cam.data.sensor_width / (2 * cam.data.lens))
    expected_vfov = math.degrees(2 * math.atan(math.tan(fov_x / 2) * 36 / 48))
    assert doc.camera["vfov"] == pytest.approx(expected_vfov, rel=1e-9)
    assert doc.camera["eye"] == pytest.approx(list(cam.matrix_world.translation), abs=1e-6)
    view = np.array(doc.camera["target"]) - np.array(doc.camera["eye"])
    axis = -np.array(cam.matrix_world.to_3x3().col[2])
    assert np.allclose(view, axis, atol=1e-6)
    assert doc.camera["clip"] == [pytest.approx(cam.data.clip_start), pytest.approx(cam.data.clip_end)]
    (distant,) = [light for light in doc.lights if light["type"] == "distant"]
    assert distant["irradiance"] == pytest.approx([3.0, 3.0, 3.0])
    assert np.allclose(distant["direction"], np.array(sun.matrix_world.to_3x3().col[2]), atol=1e-6)
    assert len(doc.meshes) == 1 and doc.meshes[0]["material"] == {"type": "diffuse",
                                                                  "color": pytest.approx([0.6, 0.5, 0.4])}


def test_ray_visibility_and_holdout_are_exported(addon, tmp_path):
    scene, groom, _, _ = make_scene()
    sphere = bpy.data.objects["Sphere"]
    sphere.visible_camera = False
    groom.visible_shadow = False
    groom.is_holdout = True
    doc, _ = export.build(bpy.context.evaluated_depsgraph_get())
    (mesh,) = doc.meshes
    (hair,) = doc.hair
    assert mesh["camera_visible"] is False and "casts_shadows" not in mesh and "matte" not in mesh
    assert hair["casts_shadows"] is False and hair["matte"] is True and "camera_visible" not in hair
    # The folder reads back with the switches (its USD export writes them as Arnold's).
    usda = tmp_path / "back.usda"
    tress.export(tress.load(doc.write(tmp_path / "folder")), usda)
    text = usda.read_text()
    assert "primvars:arnold:visibility:camera = false" in text
    assert "primvars:arnold:visibility:shadow = false" in text and "primvars:arnold:matte = true" in text


def test_render_through_the_engine_equals_the_command_line(addon, tmp_path, tress_cli):
    scene, _, _, _ = make_scene()
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.filepath = str(tmp_path / "blender.exr")
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(str(tmp_path / "blender.exr"))
    pixels = np.empty(len(image.pixels), np.float32)
    image.pixels.foreach_get(pixels)
    blender = pixels.reshape(image.size[1], image.size[0], 4)[::-1]
    assert blender.shape == (36, 48, 4)
    assert blender[..., 3].mean() > 0.1, "the sphere and hair are in view"

    folder = tmp_path / "folder"
    bpy.ops.export_scene.tress(directory=str(folder))
    assert (folder / "scene.toml").is_file() and (folder / "groom.hair").is_file()
    out = tmp_path / "cli.exr"
    run_cli(tress_cli, "render", folder / "scene.toml", "-o", out, "--quiet")
    cli = np.asarray(tress.read_exr(out))
    assert np.array_equal(blender, cli)


def test_particle_hair_exports_the_children_blender_evaluates(addon):
    make_scene()
    sphere = bpy.data.objects["Sphere"]
    mod = sphere.modifiers.new("fuzz", "PARTICLE_SYSTEM")
    settings = mod.particle_system.settings
    settings.type = "HAIR"
    settings.count = 20
    settings.hair_length = 0.5
    settings.child_type = "SIMPLE"
    settings.child_percent = settings.rendered_child_count = 3
    settings.root_radius, settings.tip_radius, settings.radius_scale = 0.02, 0.0, 1.0
    depsgraph = bpy.context.evaluated_depsgraph_get()
    doc, _ = export.build(depsgraph)
    (entry,) = [h for h in doc.hair if h["file"].startswith("Sphere_")]
    strands = doc.files[entry["file"]]
    psys = sphere.evaluated_get(depsgraph).particle_systems[0]
    assert strands.strand_count == len(psys.child_particles) == 60
    assert depsgraph.mode == "VIEWPORT"
    steps = 2 ** settings.display_step + 1
    points = np.asarray(strands.points).reshape(60, steps, 3)
    # Children grow from about the sphere's surface, about the hair length out.
    assert np.allclose(np.linalg.norm(points[:, 0], axis=1), 1.0, atol=0.1)
    assert np.allclose(np.linalg.norm(points[:, -1] - points[:, 0], axis=1), 0.5, rtol=0.25)
    # Radius from the particle settings' root radius (a diameter) to the tip radius.
    assert strands.radius[0] == pytest.approx(0.01) and strands.radius[steps - 1] == 0.0


def test_without_the_module_the_engine_runs_the_command_line(addon, tmp_path, tress_cli, monkeypatch):
    monkeypatch.setenv("PATH", os.path.dirname(tress_cli) + os.pathsep + os.environ.get("PATH", ""))
    images = []
    for use_module in (True, False):
        scene, _, _, _ = make_scene()
        scene.tress.use_module = use_module
        scene.render.image_settings.file_format = "OPEN_EXR"
        scene.render.image_settings.color_depth = "32"
        scene.render.filepath = str(tmp_path / f"module_{use_module}.exr")
        bpy.ops.render.render(write_still=True)
        image = bpy.data.images.load(scene.render.filepath)
        pixels = np.empty(len(image.pixels), np.float32)
        image.pixels.foreach_get(pixels)
        images.append(pixels)
    assert images[0].max() > 0
    assert np.array_equal(images[0], images[1])


def uv_environment(scene, width=256, height=128, strength=1.0):
    """A world whose equirectangular Environment Texture holds its own image coordinates:
    red = u and green = v (Blender's, v from the bottom row), so a pixel's colour says
    which part of the image is seen there."""
    img = bpy.data.images.new("uv", width, height, float_buffer=True)
    u = (np.arange(width) + 0.5) / width
    v = (np.arange(height) + 0.5) / height
    px = np.zeros((height, width, 4), np.float32)
    px[..., 0], px[..., 1], px[..., 3] = u[None, :], v[:, None], 1.0
    img.pixels.foreach_set(px.ravel())
    world = bpy.data.worlds.new("uv")
    scene.world = world
    world.use_nodes = True
    tree = world.node_tree
    bg = tree.nodes["Background"]
    bg.inputs["Strength"].default_value = strength
    tex = tree.nodes.new("ShaderNodeTexEnvironment")
    tex.image = img
    tex.interpolation = "Closest"
    tree.links.new(tex.outputs[0], bg.inputs["Color"])
    return img


def render_pixels(scene, path):
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.filepath = str(path)
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(str(path))
    pixels = np.empty(len(image.pixels), np.float32)
    image.pixels.foreach_get(pixels)
    bpy.data.images.remove(image)
    return pixels.reshape(scene.render.resolution_y, scene.render.resolution_x, 4)


def test_world_environment_texture_is_seen_where_cycles_sees_it(addon, tmp_path):
    """An equirectangular world image is exported as an environment map that tress shows
    in the same directions as Blender's own Cycles: every pixel of two wide views agrees
    on which part of the image it sees."""
    import mathutils

    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.resolution_x, scene.render.resolution_y = 8, 6
    scene.view_settings.view_transform = "Standard"
    uv_environment(scene, strength=2.0)
    cam_data = bpy.data.cameras.new("cam")
    cam_data.lens_unit = "FOV"
    cam_data.angle = math.radians(60.0)
    cam = bpy.data.objects.new("cam", cam_data)
    scene.collection.objects.link(cam)
    scene.camera = cam
    # Cycles' denoiser blurs the image's coordinates; without it 64 samples agree to 0.001.
    scene.cycles.samples = 64
    scene.cycles.use_denoising = False
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.device = "CPU"
    scene.tress.spp = 16
    doc, _ = export.build(bpy.context.evaluated_depsgraph_get())
    (env,) = doc.lights
    assert env == {"type": "environment", "file": export.ENVIRONMENT_FILE, "intensity": 2.0}
    # Views away from the image's seam (behind -X) and its poles.
    for i, d in enumerate([(1.0, 0.3, 0.1), (-0.4, -0.8, 0.5)]):
        cam.rotation_euler = mathutils.Vector(d).normalized().to_track_quat("-Z", "Y").to_euler()
        seen = {}
        for engine in ("CYCLES", "TRESS"):
            scene.render.engine = engine
            seen[engine] = render_pixels(scene, tmp_path / f"{engine}_{i}.exr")[..., :2] / 2.0
        assert np.abs(seen["TRESS"] - seen["CYCLES"]).max() < 0.01, (d, seen)


def test_render_passes_equal_the_command_lines_aovs(addon, tmp_path, tress_cli):
    scene, _, _, _ = make_scene()
    layer = scene.view_layers[0]
    layer.use_pass_z = layer.use_pass_normal = layer.use_pass_object_index = True
    scene.tress.hair_passes = True
    # Blender 5 names the multilayer EXR by its media type.
    scene.render.image_settings.media_type = "MULTI_LAYER_IMAGE"
    scene.render.image_settings.file_format = "OPEN_EXR_MULTILAYER"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.exr_codec = "ZIP"
    scene.render.filepath = str(tmp_path / "passes.exr")
    bpy.ops.render.render(write_still=True)
    from tress_addon import exr

    # Blender writes one EXR part a pass; OpenEXR's own Python module reads them.
    openexr = pytest.importorskip("OpenEXR", reason="OpenEXR's Python module is not installed (pip install OpenEXR)")
    blender = {}
    with openexr.File(str(tmp_path / "passes.exr"), separate_channels=True) as f:
        for part in f.parts:
            blender.update({name: np.asarray(c.pixels, np.float32) for name, c in part.channels.items()})
    folder = tmp_path / "folder"
    bpy.ops.export_scene.tress(directory=str(folder))
    out = tmp_path / "cli.exr"
    run_cli(tress_cli, "render", folder / "scene.toml", "-o", out, "--quiet")
    cli = exr.read_channels(str(out))
    prefix = f"{layer.name}."
    pairs = {"Depth.Z": "Z", "Normal.X": "N.X", "Normal.Z": "N.Z", "IndexOB.X": "objectId",
             "strandId.X": "strandId", "strandAlong.X": "strandAlong", "rootUV.U": "rootUV.U",
             "rootUV.V": "rootUV.V", "clumpId.X": "clumpId", "strandRandom.X": "strandRandom"}
    for name, channel in pairs.items():
        assert prefix + name in blender, sorted(blender)
        assert np.array_equal(blender[prefix + name], cli[channel]), name
    assert cli["strandAlong"].max() > 0.5, "hair is in view"
