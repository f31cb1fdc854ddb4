#!/usr/bin/env python3
"""Renders docs/images/blender.png in Blender's Python module (``pip install bpy``) through
the tress engine: a sphere with a hair curves object (Principled Hair, melanin), a
camera, a sun and a sky.

    python3 blender/make_picture.py [OUTPUT.png]
"""

import math
import os
import sys

import bpy
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import tress_addon  # noqa: E402


def groom(count=4000, per=12, length=0.7, seed=5):
    """Strands on the upper part of a unit sphere, drooping under a little gravity."""
    rng = np.random.default_rng(seed)
    roots = rng.normal(size=(count * 2, 3))
    roots /= np.linalg.norm(roots, axis=1, keepdims=True)
    roots = roots[roots[:, 2] > -0.2][:count]
    t = np.linspace(0.0, 1.0, per)[None, :, None]
    outward = roots[:, None, :] * (1.0 + length * t * 0.6)
    droop = np.array([0.0, 0.0, -1.0]) * (t**2) * length * 0.8
    wiggle = rng.normal(scale=0.03, size=(len(roots), 1, 3)) * t
    return (outward + droop + wiggle).reshape(-1, 3), len(roots), per


def main(output):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    tress_addon.register()
    scene = bpy.context.scene
    scene.render.engine = "TRESS"
    scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = 320, 240, 100
    scene.tress.spp = 16
    bpy.ops.mesh.primitive_uv_sphere_add(radius=1.0, segments=48, ring_count=24)
    bpy.ops.object.shade_smooth()
    skin = bpy.data.materials.new("skin")
    skin.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0.55, 0.38, 0.3, 1.0)
    bpy.context.active_object.data.materials.append(skin)

    points, count, per = groom()
    curves = bpy.data.hair_curves.new("groom")
    curves.add_curves([per] * count)
    curves.position_data.foreach_set("vector", points.astype(np.float32).ravel())
    radius = curves.attributes.get("radius") or curves.attributes.new("radius", "FLOAT", "POINT")
    radius.data.foreach_set("value", np.tile(np.linspace(0.006, 0.002, per), count).astype(np.float32))
    hair = bpy.data.materials.new("hair")
    tree = hair.node_tree
    tree.nodes.clear()
    node = tree.nodes.new("ShaderNodeBsdfHairPrincipled")
    node.parametrization = "MELANIN"
    node.inputs["Melanin"].default_value = 0.4
    node.inputs["Melanin Redness"].default_value = 0.6
    node.inputs["Roughness"].default_value = 0.3
    tree.links.new(node.outputs[0], tree.nodes.new("ShaderNodeOutputMaterial").inputs["Surface"])
    curves.materials.append(hair)
    obj = bpy.data.objects.new("groom", curves)
    scene.collection.objects.link(obj)

    cam = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    cam.data.lens = 45.0
    cam.location = (0.0, -6.2, 1.3)
    cam.rotation_euler = (math.radians(80.0), 0.0, 0.0)
    scene.collection.objects.link(cam)
    scene.camera = cam
    sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", "SUN"))
    sun.data.energy = 3.5
    sun.data.angle = math.radians(2.0)
    sun.rotation_euler = (math.radians(50.0), math.radians(-30.0), 0.0)
    scene.collection.objects.link(sun)
    scene.world = bpy.data.worlds.new("sky")
    scene.world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.25, 0.3, 0.38, 1.0)
    scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0

    scene.view_settings.view_transform = "Standard"
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGB"
    scene.render.filepath = output
    bpy.ops.render.render(write_still=True)
    print(output)


if __name__ == "__main__":
    main(os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "docs", "images", "blender.png")))
