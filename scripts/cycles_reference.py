#!/usr/bin/env python3
"""Renders a reference scene directory of scripts/gen_scenes.py with Blender Cycles
(the `bpy` module, CPU, direct lighting), for an end-to-end time beside `tress render DIR`.

Usage: python3 scripts/cycles_reference.py DIR OUT.exr [--spp N] [--threads N]
Needs `pip install bpy` (Blender as a Python module; 5.0 needs Python 3.11) and numpy.
Prints the render time in seconds: Cycles' own scene sync and BVH build are included,
reading the files and making the Blender objects are not.

The hair is a Curves object of poly (linear) curves with per-point radius, drawn as 3D
tubes (`THICK`), shaded diffuse like the other peers; `max_bounces = 0` leaves camera rays
and light sampling only. The film filter is a 1-pixel box, as in Mitsuba and tress.
"""
import argparse, json, math, os, time

import bpy
import numpy as np
from mathutils import Vector


def read_hair(path):
    """(points [n, m, 3], radii [n, m]) of a gen_scenes.py .hair file (all strands one length)."""
    with open(path, "rb") as f:
        hdr = f.read(128)
        assert hdr[:4] == b"HAIR", f"{path}: not a HAIR file"
        n, total, flags, segs = np.frombuffer(hdr[4:20], "<u4")
        assert flags & 7 == 7, f"{path}: needs segment, point and thickness arrays"
        counts = np.frombuffer(f.read(2 * n), "<u2")
        assert (counts == counts[0]).all(), f"{path}: strands of one length expected"
        pts = np.frombuffer(f.read(12 * total), "<f4").reshape(n, -1, 3)
        width = np.frombuffer(f.read(4 * total), "<f4").reshape(n, -1)
    return pts, width / 2  # the file stores diameters


def diffuse(name, color):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nodes = m.node_tree.nodes
    nodes.clear()
    bsdf = nodes.new("ShaderNodeBsdfDiffuse")
    bsdf.inputs["Color"].default_value = (*color, 1.0)
    out = nodes.new("ShaderNodeOutputMaterial")
    m.node_tree.links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    return m


def read_obj(path):
    verts, faces = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                verts.append(tuple(float(x) for x in line.split()[1:4]))
            elif line.startswith("f "):
                faces.append(tuple(int(x.split("/")[0]) - 1 for x in line.split()[1:]))
    return verts, faces


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir")
    ap.add_argument("out")
    ap.add_argument("--spp", type=int, default=None)
    ap.add_argument("--threads", type=int, default=0, help="0 = every core")
    a = ap.parse_args()
    s = json.load(open(os.path.join(a.dir, "scene.json")))
    film, cam = s["film"], s["camera"]
    spp = a.spp or film["spp"]

    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.samples = spp
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.max_bounces = 0  # direct lighting: no bounce beyond the light samples
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    c.seed = 0
    scene.cycles_curves.shape = "THICK"
    scene.render.threads_mode = "FIXED" if a.threads else "AUTO"
    if a.threads:
        scene.render.threads = a.threads
    scene.render.resolution_x, scene.render.resolution_y = film["width"], film["height"]
    scene.render.resolution_percentage = 100
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.view_settings.view_transform = "Standard"

    cam_data = bpy.data.cameras.new("camera")
    cam_data.sensor_fit = "VERTICAL"
    cam_data.angle_y = math.radians(cam["vfov_deg"])
    cam_obj = bpy.data.objects.new("camera", cam_data)
    eye, target, up = Vector(cam["eye"]), Vector(cam["target"]), Vector(cam["up"])
    # Blender cameras look down their -Z with +Y up.
    fwd = (target - eye).normalized()
    right = fwd.cross(up).normalized()
    true_up = right.cross(fwd)
    from mathutils import Matrix
    rot = Matrix((right, true_up, -fwd)).transposed()
    cam_obj.matrix_world = Matrix.Translation(eye) @ rot.to_4x4()
    scene.collection.objects.link(cam_obj)
    scene.camera = cam_obj

    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    scene.world = world
    for light in s["lights"]:
        if light["type"] == "distant":
            sun = bpy.data.lights.new("sun", "SUN")
            sun.energy = light["radiance"][0]  # irradiance in W/m^2, as the peers read it
            sun.color = tuple(x / light["radiance"][0] for x in light["radiance"])
            sun.angle = 0.0
            obj = bpy.data.objects.new("sun", sun)
            # A sun shines down its -Z: point +Z towards the light.
            obj.rotation_euler = Vector(light["direction_to_light"]).to_track_quat("Z", "Y").to_euler()
            scene.collection.objects.link(obj)
        else:
            bg = world.node_tree.nodes["Background"]
            bg.inputs["Color"].default_value = (*light["radiance"], 1.0)
            bg.inputs["Strength"].default_value = 1.0

    for i, m in enumerate(s["meshes"]):
        verts, faces = read_obj(os.path.join(a.dir, m["obj"]))
        mesh = bpy.data.meshes.new(f"mesh{i}")
        mesh.from_pydata(verts, [], faces)
        mesh.materials.append(diffuse(f"mesh{i}", m["diffuse"]))
        scene.collection.objects.link(bpy.data.objects.new(f"mesh{i}", mesh))

    for i, h in enumerate(s["hair"]):
        pts, radius = read_hair(os.path.join(a.dir, h["file"]))
        n, m = radius.shape
        curves = bpy.data.hair_curves.new(f"hair{i}")
        curves.add_curves([m] * n)
        curves.set_types(type="POLY")
        curves.attributes["position"].data.foreach_set("vector", pts.reshape(-1).astype(np.float32))
        r = curves.attributes.get("radius") or curves.attributes.new("radius", "FLOAT", "POINT")
        r.data.foreach_set("value", radius.reshape(-1).astype(np.float32))
        curves.materials.append(diffuse(f"hair{i}", h["diffuse"]))
        scene.collection.objects.link(bpy.data.objects.new(f"hair{i}", curves))

    scene.render.filepath = os.path.abspath(a.out)
    t0 = time.time()
    bpy.ops.render.render(write_still=True)
    print(f"cycles render {time.time() - t0:.3f} s ({film['width']}x{film['height']}, {spp} spp)")


if __name__ == "__main__":
    main()
