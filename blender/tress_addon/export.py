"""A Blender scene, as the depsgraph evaluates it, as a tress scene (:class:`SceneDoc`).

Everything is exported in Blender's world space (Z up); the camera's up vector is the
camera's own Y axis, so no axis conversion is needed.

- Hair curves objects (``Curves``): every curve's points and ``radius`` attribute (0.005
  where it has none), per-point ``color`` attributes as strand colours; the object's
  transform is applied to the points and its scale (cube root of the determinant) to the
  radii, as tress does for ``[[hair]] transform``.
- Particle hair: parents and children as Blender evaluates them for rendering
  (``ParticleSystem.co_hair``), ``2^render_step`` segments each (``display_step`` in a
  viewport depsgraph), radius from the particle
  settings' root and tip radius times radius scale.
- Meshes: the evaluated mesh in world space, split by material slot, each part with its
  material's nearest tress material (:mod:`.materials`).
- Camera: position and orientation, vertical field of view from focal length, sensor size
  and sensor fit, clip start and end; orthographic cameras and lens shift are not mapped
  (warned).
- Lights: sun to ``distant`` (strength as irradiance, angle as angular diameter), point
  to ``point`` (or a ``sphere`` light of its radius), spot to ``spot``, area to ``quad``;
  Blender's watts are turned into intensity as ``power / 4π`` (point, spot) and into
  radiance as ``power / (π · area)`` (area, sphere).
- World: the Background colour times strength as an ``environment`` light; an
  equirectangular Environment Texture linked to it as an environment map (resampled to
  tress's lat-long convention, :func:`environment_pixels`) with the strength as intensity;
  other projections as their mean colour (warned).
"""

from __future__ import annotations

import math

from . import materials
from .scene_folder import ImageData, MeshData, SceneDoc, StrandData, visibility

try:
    import numpy as np
except ImportError:  # Blender ships NumPy; without it nothing here works.
    np = None

DEFAULT_HAIR = {"type": "physical", "eumelanin": 1.3}
DEFAULT_SURFACE = {"type": "diffuse", "color": [0.8, 0.8, 0.8]}
DEFAULT_CURVE_RADIUS = 0.005


def _matrix(m):
    return np.array([list(row) for row in m], dtype=np.float64)


def _apply(mat4, points):
    return points @ mat4[:3, :3].T + mat4[:3, 3]


def _radius_scale(mat4) -> float:
    return abs(np.linalg.det(mat4[:3, :3])) ** (1.0 / 3.0)


def resolution(scene):
    r = scene.render
    return max(1, round(r.resolution_x * r.resolution_percentage / 100)), max(
        1, round(r.resolution_y * r.resolution_percentage / 100)
    )


def vertical_fov(lens: float, sensor_width: float, sensor_height: float, fit: str, width: int, height: int) -> float:
    """Vertical field of view in degrees of a Blender camera, from its focal length,
    sensor and sensor fit (``AUTO`` fits the sensor width to the larger image side)."""
    aspect = width / height
    if fit == "VERTICAL" or (fit == "AUTO" and height > width):
        size = sensor_height if fit == "VERTICAL" else sensor_width
        return math.degrees(2.0 * math.atan(size / (2.0 * lens)))
    half_h = math.atan(sensor_width / (2.0 * lens))
    return math.degrees(2.0 * math.atan(math.tan(half_h) / aspect))


def camera(obj, scene, warnings):
    """The ``[camera]`` table of a camera object."""
    m = _matrix(obj.matrix_world)
    eye = m[:3, 3]
    forward = -m[:3, 2] / np.linalg.norm(m[:3, 2])
    up = m[:3, 1] / np.linalg.norm(m[:3, 1])
    cam = obj.data
    w, h = resolution(scene)
    if cam.type != "PERSP":
        warnings.append(f"camera {obj.name}: {cam.type.lower()} projection is rendered as perspective")
    if abs(cam.shift_x) > 1e-6 or abs(cam.shift_y) > 1e-6:
        warnings.append(f"camera {obj.name}: lens shift is not mapped")
    vfov = vertical_fov(cam.lens, cam.sensor_width, cam.sensor_height, cam.sensor_fit, w, h)
    # Blender's clip distances are along the view axis, as tress's.
    clip = [float(cam.clip_start), float(cam.clip_end)]
    return {"eye": eye.tolist(), "target": (eye + forward).tolist(), "up": up.tolist(), "vfov": vfov, "clip": clip}


def light(obj, warnings):
    """The ``[[light]]`` entry of a light object, or None."""
    data = obj.data
    m = _matrix(obj.matrix_world)
    position = m[:3, 3]
    z = m[:3, 2] / np.linalg.norm(m[:3, 2])
    color = np.array(list(data.color), dtype=np.float64)
    if data.type == "SUN":
        return {
            "type": "distant",
            "direction": z.tolist(),
            "irradiance": (color * data.energy).tolist(),
            "angular_diameter": min(180.0, math.degrees(data.angle)),
        }
    if data.type in ("POINT", "SPOT"):
        intensity = color * data.energy / (4.0 * math.pi)
        if data.type == "SPOT":
            outer = math.degrees(data.spot_size) / 2.0
            return {
                "type": "spot",
                "position": position.tolist(),
                "target": (position - z).tolist(),
                "intensity": intensity.tolist(),
                "outer_angle": outer,
                "inner_angle": outer * (1.0 - data.spot_blend),
            }
        r = float(data.shadow_soft_size)
        if r > 0.0:
            return {
                "type": "sphere",
                "center": position.tolist(),
                "radius": r,
                "radiance": (intensity / (math.pi * r * r)).tolist(),
            }
        return {"type": "point", "position": position.tolist(), "intensity": intensity.tolist()}
    if data.type == "AREA":
        sx = data.size
        sy = data.size if data.shape in ("SQUARE", "DISK") else data.size_y
        if data.shape in ("DISK", "ELLIPSE"):
            warnings.append(f"light {obj.name}: a {data.shape.lower()} area light is rendered as a rectangle")
        ex = m[:3, 0] * sx
        ey = m[:3, 1] * sy
        area = float(np.linalg.norm(np.cross(ex, ey)))
        # tress's quad emits towards edge_u x edge_v; Blender's area light towards -Z.
        edge_u, edge_v = ey, ex
        corner = position - 0.5 * (edge_u + edge_v)
        return {
            "type": "quad",
            "corner": corner.tolist(),
            "edge_u": edge_u.tolist(),
            "edge_v": edge_v.tolist(),
            "radiance": (color * data.energy / (math.pi * max(area, 1e-12))).tolist(),
        }
    warnings.append(f"light {obj.name}: {data.type} lights are not mapped")
    return None


# Environment maps are resampled to at most this width (and half of it in height).
MAX_ENVIRONMENT_WIDTH = 4096


def environment_pixels(pixels):
    """An equirectangular image in Blender's convention (``pixels``: height x width x
    channels, bottom row first, as ``Image.pixels`` holds it) resampled to tress's
    (top row first), both in Blender's world axes, which the export keeps.

    Blender's Environment Texture looks up direction ``d`` at ``u = 1/2 - atan2(d.y,
    d.x) / 2π``, ``v = 1/2 + asin(d.z) / π`` (v from the bottom row: +X at the image centre,
    +Z at the top). tress's environment light maps ``(u, v)`` (v from the top row) to
    ``θ = π v``, ``φ = 2π (u + 1/4)``, ``d = (sin θ cos φ, cos θ, sin θ sin φ)``
    (docs/scene-format.md). Each tress pixel takes the bilinear value of the Blender image
    in its direction."""
    src = np.asarray(pixels, dtype=np.float32)[..., :3]
    sh, sw = src.shape[:2]
    w = max(2, min(sw, MAX_ENVIRONMENT_WIDTH))
    h = max(1, min(sh, w // 2 if sw > MAX_ENVIRONMENT_WIDTH else sh))
    u = (np.arange(w) + 0.5) / w
    v = (np.arange(h) + 0.5) / h
    theta = np.pi * v[:, None]
    phi = 2.0 * np.pi * (u[None, :] + 0.25)
    dx, dy, dz = np.sin(theta) * np.cos(phi), np.cos(theta) * np.ones_like(phi), np.sin(theta) * np.sin(phi)
    ub = (0.5 - np.arctan2(dy, dx) / (2.0 * np.pi)) % 1.0
    vb = 0.5 + np.arcsin(np.clip(dz, -1.0, 1.0)) / np.pi
    x = ub * sw - 0.5
    y = np.clip(vb * sh - 0.5, 0.0, sh - 1)
    x0 = np.floor(x).astype(np.int64)
    y0 = np.floor(y).astype(np.int64)
    fx = (x - x0)[..., None]
    fy = (y - y0)[..., None]
    x1, y1 = (x0 + 1) % sw, np.minimum(y0 + 1, sh - 1)
    x0 %= sw
    top = src[y0, x0] * (1 - fx) + src[y0, x1] * fx
    bottom = src[y1, x0] * (1 - fx) + src[y1, x1] * fx
    return (top * (1 - fy) + bottom * fy).astype(np.float32)


ENVIRONMENT_FILE = "world.pfm"


def world(scene, doc: SceneDoc, warnings):
    """The ``environment`` light of the world, or None when it is black: the Background
    colour times strength, or an equirectangular Environment Texture linked to it, resampled
    into ``doc.files`` as :data:`ENVIRONMENT_FILE`."""
    w = scene.world
    if w is None:
        return None
    color = np.array(list(w.color)[:3], dtype=np.float64)
    if getattr(w, "use_nodes", False) and w.node_tree is not None:
        bg = next((n for n in w.node_tree.nodes if n.bl_idname == "ShaderNodeBackground"), None)
        if bg is not None:
            strength = float(bg.inputs["Strength"].default_value)
            socket = bg.inputs["Color"]
            color = np.array(list(socket.default_value)[:3], dtype=np.float64) * strength
            if socket.is_linked:
                source = socket.links[0].from_node
                image = getattr(source, "image", None)
                if source.bl_idname == "ShaderNodeTexEnvironment" and image is not None and image.size[0] > 0:
                    pixels = np.empty(len(image.pixels), dtype=np.float32)
                    image.pixels.foreach_get(pixels)
                    pixels = pixels.reshape(image.size[1], image.size[0], image.channels)
                    if source.projection != "EQUIRECTANGULAR":
                        warnings.append(f"world: the {source.projection.lower()} environment image {image.name} "
                                        "is lit as its mean colour")
                        color = pixels[..., :3].reshape(-1, 3).mean(axis=0).astype(np.float64) * strength
                    else:
                        if source.inputs["Vector"].is_linked:
                            warnings.append(f"world: the texture coordinates of {image.name} are not mapped "
                                            "(the image is placed as with none)")
                        if strength <= 0:
                            return None
                        doc.files[ENVIRONMENT_FILE] = ImageData(environment_pixels(pixels))
                        return {"type": "environment", "file": ENVIRONMENT_FILE, "intensity": strength}
                else:
                    warnings.append(f"world: {source.bl_idname} linked to the background colour is not mapped")
    if not np.any(color > 0):
        return None
    return {"type": "environment", "radiance": color.tolist()}


def object_visibility(obj) -> dict[str, bool]:
    """The object's ray visibility (Object Properties > Visibility > Ray Visibility: Camera,
    Shadow) and Holdout as the entry's visibility switches, as Cycles honours them; the
    other ray types (diffuse, glossy, transmission, volume) have no tress switch."""
    return visibility(obj.visible_camera, obj.visible_shadow, obj.is_holdout)


def _slot_material(obj, index):
    slots = obj.material_slots
    return slots[index].material if 0 <= index < len(slots) else None


def mesh_entries(obj, eval_obj, doc: SceneDoc, warnings):
    """``[[mesh]]`` entries of a mesh object, one per material slot used."""
    me = eval_obj.to_mesh()
    try:
        me.calc_loop_triangles()
        n_tris = len(me.loop_triangles)
        if n_tris == 0:
            return
        m = _matrix(eval_obj.matrix_world)
        co = np.empty(len(me.vertices) * 3, dtype=np.float32)
        me.vertices.foreach_get("co", co)
        points = _apply(m, co.reshape(-1, 3).astype(np.float64)).astype(np.float32)
        tris = np.empty(n_tris * 3, dtype=np.int64)
        me.loop_triangles.foreach_get("vertices", tris)
        tris = tris.reshape(-1, 3)
        mat_index = np.empty(n_tris, dtype=np.int64)
        me.loop_triangles.foreach_get("material_index", mat_index)
        smooth = np.zeros(len(me.polygons), dtype=bool)
        if len(me.polygons):
            flags = np.empty(len(me.polygons), dtype=bool)
            me.polygons.foreach_get("use_smooth", flags)
            smooth = flags
        normals = None
        if smooth.any():
            vn = np.empty(len(me.vertices) * 3, dtype=np.float32)
            me.vertices.foreach_get("normal", vn)
            n = vn.reshape(-1, 3).astype(np.float64) @ np.linalg.inv(m[:3, :3])
            n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-20)
            normals = n.astype(np.float32)
        for index in np.unique(mat_index):
            part = tris[mat_index == index]
            used, remap = np.unique(part, return_inverse=True)
            material, w = materials.from_material(_slot_material(obj, int(index)), DEFAULT_SURFACE)
            warnings.extend(w)
            name = _unique_name(doc, obj.name, "obj")
            doc.files[name] = MeshData(
                points[used], remap.reshape(-1, 3).astype(np.uint32), None if normals is None else normals[used]
            )
            doc.meshes.append({"file": name, "material": material, **object_visibility(obj)})
    finally:
        eval_obj.to_mesh_clear()


def _unique_name(doc: SceneDoc, base: str, ext: str) -> str:
    safe = "".join(c if c.isalnum() or c in "-_" else "_" for c in base) or "object"
    name, i = f"{safe}.{ext}", 1
    while name in doc.files:
        i += 1
        name = f"{safe}_{i}.{ext}"
    return name


def _point_attribute(curves, name, width):
    attr = curves.attributes.get(name)
    if attr is None or attr.domain != "POINT":
        return None
    out = np.empty(len(curves.points) * width, dtype=np.float32)
    key = "value" if width == 1 else ("color" if attr.data_type in ("FLOAT_COLOR", "BYTE_COLOR") else "vector")
    attr.data.foreach_get(key, out)
    return out.reshape(-1, width) if width > 1 else out


def curves_strands(eval_obj) -> StrandData:
    """The strands of an evaluated hair curves object, in world space."""
    curves = eval_obj.data
    n = len(curves.points)
    co = np.empty(n * 3, dtype=np.float32)
    curves.points.foreach_get("position", co)
    m = _matrix(eval_obj.matrix_world)
    points = _apply(m, co.reshape(-1, 3).astype(np.float64)).astype(np.float32)
    radius = _point_attribute(curves, "radius", 1)
    if radius is None:
        radius = np.full(n, DEFAULT_CURVE_RADIUS, dtype=np.float32)
    radius = (radius.astype(np.float64) * _radius_scale(m)).astype(np.float32)
    offsets = np.empty(len(curves.curves) + 1, dtype=np.int64)
    curves.curve_offset_data.foreach_get("value", offsets)
    colors = _point_attribute(curves, "color", 4)
    if colors is not None:
        colors = np.clip(colors[:, :3], 0.0, None)
    return StrandData(points, radius, offsets.astype(np.uint32), colors)


def particle_strands(eval_obj, psys, render: bool) -> StrandData | None:
    """Parents and children of a hair particle system, as Blender evaluates them (with the
    render or viewport step count, as the depsgraph was evaluated for)."""
    settings = psys.settings
    steps = 2 ** (settings.render_step if render else settings.display_step) + 1
    parents = len(psys.particles)
    children = len(psys.child_particles)
    total = parents + children if settings.child_type != "NONE" else parents
    if total == 0:
        return None
    first = parents if settings.child_type != "NONE" and children > 0 else 0
    indices = range(first, total) if first else range(parents)
    pts = []
    for i in indices:
        for s in range(steps):
            pts.append(tuple(psys.co_hair(object=eval_obj, particle_no=i, step=s)))
    points = np.array(pts, dtype=np.float32).reshape(-1, 3)
    count = len(points) // steps
    t = np.linspace(0.0, 1.0, steps)
    r = 0.5 * (settings.root_radius * (1 - t) + settings.tip_radius * t) * settings.radius_scale
    radius = np.tile(r, count).astype(np.float32)
    offsets = (np.arange(count + 1) * steps).astype(np.uint32)
    return StrandData(points, radius, offsets)


def build(depsgraph, settings=None):
    """The depsgraph's scene as a :class:`SceneDoc` and the warnings of what is not
    mapped. ``settings``: the ``[render]`` keys to set (spp, integrator, ...)."""
    if np is None:
        raise RuntimeError("the tress add-on needs NumPy")
    scene = depsgraph.scene_eval if hasattr(depsgraph, "scene_eval") else depsgraph.scene
    warnings: list[str] = []
    if scene.camera is None:
        raise RuntimeError("the scene has no camera")
    w, h = resolution(scene)
    doc = SceneDoc(render={"resolution": [w, h], **(settings or {})})
    doc.camera = camera(scene.camera.evaluated_get(depsgraph), scene, warnings)
    env = world(scene, doc, warnings)
    for inst in depsgraph.object_instances:
        obj = inst.object
        original = obj.original
        if inst.is_instance and obj.type != "MESH":
            continue
        if obj.type == "LIGHT":
            entry = light(obj, warnings)
            if entry:
                doc.lights.append(entry)
        elif obj.type == "MESH":
            if inst.show_self:
                mesh_entries(original, obj, doc, warnings)
            for psys in obj.particle_systems:
                ps = psys.settings
                if ps.type != "HAIR" or ps.render_type != "PATH" or not inst.show_particles:
                    continue
                strands = particle_strands(obj, psys, getattr(depsgraph, "mode", "RENDER") == "RENDER")
                if strands is None:
                    continue
                name = _unique_name(doc, f"{original.name}_{psys.name}", "hair")
                doc.files[name] = strands
                slot = ps.material - 1
                material, mw = materials.from_material(_slot_material(original, slot), DEFAULT_HAIR, hair=True)
                warnings.extend(mw)
                doc.hair.append({"file": name, "material": material, "file_colors": False, **object_visibility(original)})
        elif obj.type == "CURVES":
            strands = curves_strands(obj)
            if strands.strand_count == 0:
                continue
            name = _unique_name(doc, original.name, "hair")
            doc.files[name] = strands
            material, mw = materials.from_material(_slot_material(original, 0), DEFAULT_HAIR, hair=True)
            warnings.extend(mw)
            entry = {"file": name, "material": material, **object_visibility(original)}
            if strands.colors is not None and material.get("type") == "physical":
                entry["material"] = {k: v for k, v in material.items() if k not in ("eumelanin", "pheomelanin", "color")}
                entry["material"]["from_file"] = True
            doc.hair.append(entry)
    if env is not None:
        doc.lights.append(env)
    return doc, warnings
