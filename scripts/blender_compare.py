#!/usr/bin/env python3
"""Renders a Blender scene with Cycles and its USD export with tress, and prints how far
apart they are (docs/interop.md, "Blender"). Not run in CI.

Usage:
  python3 scripts/blender_compare.py SCENE OUTDIR [TRESS]

SCENE is one of
  sun       400 hair curves on a ground plane, a sun of strength 3 and 2 degrees
  lamps     the same lit by a 60 W point light, a 40 W square area light and the world
  particles legacy particle hair on a sphere, the sun
  cm        the sun scene at unit scale 0.01 (100 times larger), with a point light
OUTDIR receives scene.blend, scene.usda, cycles.png, tress.png and side.png. TRESS is
the binary (target/release/tress by default). Needs Blender as a Python module
(`import bpy`, with numpy) and scripts/compare_reference.py's packages.
"""
import math
import os
import subprocess
import sys

import bpy
import numpy as np


def principled(name, rgb):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    bsdf = m.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (*rgb, 1)
    bsdf.inputs["Roughness"].default_value = 0.5
    return m


def light(sc, kind, name, energy, location=(0, 0, 0), rotation=(0, 0, 0)):
    data = bpy.data.lights.new(name, kind)
    data.energy = energy
    ob = bpy.data.objects.new(name, data)
    sc.collection.objects.link(ob)
    ob.location, ob.rotation_euler = location, [math.radians(a) for a in rotation]
    return data


def build(scene):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.cycles.device, sc.cycles.samples, sc.cycles.use_denoising = "CPU", 64, False
    sc.render.resolution_x, sc.render.resolution_y, sc.render.resolution_percentage = 160, 120, 100
    # tress writes plain sRGB: no filmic or AgX tone curve on Blender's side.
    sc.view_settings.view_transform, sc.view_settings.look = "Standard", "None"
    s = 0.01 if scene == "cm" else 1.0
    sc.unit_settings.scale_length = s
    world = bpy.data.worlds.new("World")
    sc.world, world.use_nodes = world, True
    background = world.node_tree.nodes["Background"]
    background.inputs["Strength"].default_value = 0.0
    bpy.ops.mesh.primitive_plane_add(size=6 / s)
    bpy.context.object.data.materials.append(principled("GroundMat", (0.6, 0.6, 0.6)))
    hair = principled("HairMat", (0.8, 0.3, 0.1))
    rng = np.random.default_rng(1)
    if scene == "particles":
        bpy.ops.mesh.primitive_uv_sphere_add(radius=0.5, location=(0, 0, 0.5))
        head = bpy.context.object
        head.data.materials.append(principled("HeadMat", (0.2, 0.4, 0.8)))
        head.data.materials.append(hair)
        part = head.modifiers.new("hair", "PARTICLE_SYSTEM").particle_system.settings
        part.type, part.count, part.hair_length, part.hair_step, part.material = "HAIR", 300, 0.4, 4, 2
        part.root_radius, part.tip_radius, part.radius_scale = 0.02, 0.005, 1.0
    else:
        n, k = 400, 5
        curves = bpy.data.hair_curves.new("Hair")
        curves.add_curves([k] * n)
        points = []
        for root in np.c_[rng.uniform(-0.5, 0.5, (n, 2)), np.zeros(n)]:
            lean = rng.normal(0, 0.15, 2)
            points += [root + np.array([lean[0] * t, lean[1] * t, 0.8 * t]) for t in np.linspace(0, 1, k)]
        curves.points.foreach_set("position", (np.array(points) / s).astype(np.float32).ravel())
        curves.points.foreach_set("radius", (np.tile(np.linspace(0.012, 0.004, k), n) / s).astype(np.float32))
        curves.materials.append(hair)
        sc.collection.objects.link(bpy.data.objects.new("Hair", curves))
    camera = bpy.data.objects.new("Camera", bpy.data.cameras.new("Cam"))
    camera.data.lens, camera.data.sensor_width = 35, 36
    sc.collection.objects.link(camera)
    sc.camera = camera
    camera.location, camera.rotation_euler = (0, -3.2 / s, 1.6 / s), (math.radians(67), 0, 0)
    if scene == "lamps":
        light(sc, "POINT", "Point", 60.0, (1.5, -1.0, 2.0)).shadow_soft_size = 0.1
        area = light(sc, "AREA", "Area", 40.0, (-1.5, -0.5, 2.0), (-30, -30, 0))
        area.size, area.shape = 1.0, "SQUARE"
        background.inputs["Color"].default_value = (0.3, 0.4, 0.6, 1)
        background.inputs["Strength"].default_value = 0.5
    else:
        light(sc, "SUN", "Sun", 3.0, rotation=(35, 0, 30)).angle = math.radians(2)
    if scene == "cm":
        point = light(sc, "POINT", "Point", 40.0 / s**2, (-1.5 / s, -1.0 / s, 2.0 / s))
        point.shadow_soft_size = 0.1 / s
    return sc


def main():
    scene, out = sys.argv[1], os.path.abspath(sys.argv[2])
    here = os.path.dirname(os.path.abspath(__file__))
    tress = sys.argv[3] if len(sys.argv) > 3 else os.path.join(here, "..", "target", "release", "tress")
    os.makedirs(out, exist_ok=True)
    sc = build(scene)
    bpy.ops.wm.save_as_mainfile(filepath=os.path.join(out, "scene.blend"))
    usda = os.path.join(out, "scene.usda")
    bpy.ops.wm.usd_export(filepath=usda, export_materials=True, export_hair=True)
    sc.render.filepath = os.path.join(out, "cycles.png")
    bpy.ops.render.render(write_still=True)
    ours = os.path.join(out, "tress.png")
    subprocess.run([tress, "render", usda, "-r", "160x120", "-s", "64", "-f", "-o", ours], check=True)
    compare = os.path.join(here, "compare_reference.py")
    subprocess.run([sys.executable, compare, sc.render.filepath, ours, os.path.join(out, "side.png")], check=True)


if __name__ == "__main__":
    main()
