"""The tress render engine: F12 and ``blender -b file.blend -f 1`` render with tress.

The scene is exported by :mod:`.export`; it is rendered by the ``tress`` Python module
when Blender's Python can import it (in-process, with progress and the image updated as
tiles finish), otherwise by the ``tress`` command (the preferences' path, or ``tress`` on
PATH) on a scene folder in a temporary directory, whose EXR is loaded into the result.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
import time

import bpy

from . import exr, export
from .scene_folder import ImageData, write_pfm

try:
    import numpy as np
except ImportError:
    np = None


def addon_prefs(context):
    addon = context.preferences.addons.get(__package__)
    return addon.preferences if addon else None


def render_settings(scene) -> dict:
    """The ``[render]`` keys of the tress settings panel."""
    t = scene.tress
    out = {
        "spp": int(t.spp),
        "seed": int(t.seed),
        "integrator": t.integrator,
        "lod": bool(t.lod),
        "transparency_layers": int(t.transparency_layers),
        "max_depth": int(t.max_depth),
        "threads": int(t.threads),
    }
    return out


def tress_module():
    """The ``tress`` Python module, or None when it cannot be imported."""
    try:
        import tress
    except ImportError:
        return None
    return tress


def cli_path(context) -> str | None:
    prefs = addon_prefs(context)
    path = bpy.path.abspath(prefs.cli_path) if prefs and prefs.cli_path else ""
    if path and os.path.isfile(path):
        return path
    return shutil.which("tress")


def to_native(doc, tress, folder):
    """A :class:`SceneDoc` as a ``tress.Scene`` (same tables, geometry as arrays). Images
    (the world's environment map) are written into ``folder``, which must outlive the
    render, and named by their absolute paths."""
    scene = tress.Scene(doc.camera, doc.render)
    for entry in doc.lights:
        entry = dict(entry)
        data = doc.files.get(entry.get("file"))
        if isinstance(data, ImageData):
            path = os.path.join(folder, entry["file"])
            write_pfm(path, data)
            entry["file"] = path
        scene.add_light(**entry)
    for entry in doc.meshes:
        entry = dict(entry)
        data = doc.files.get(entry.get("file"))
        if data is not None:
            entry.pop("file")
            scene.add_mesh(data.points, data.triangles, normals=data.normals, uvs=data.uvs, **entry)
        else:
            scene.add_mesh(**entry)
    for entry in doc.hair:
        entry = dict(entry)
        data = doc.files.get(entry.get("file"))
        if data is not None:
            entry.pop("file")
            scene.add_hair(data.points, data.radius, data.offsets, colors=data.colors, opacity=data.opacity, **entry)
        else:
            scene.add_hair(**entry)
    return scene


def _flip(image):
    """An (h, w[, c]) top-row-first array as the flat bottom-row-first float32 values a
    render pass holds."""
    return np.ascontiguousarray(image[::-1], dtype=np.float32).ravel()


def _layer_flag(name):
    return lambda scene, layer: bool(getattr(layer, name, False))


def _hair_passes(scene, layer):
    return bool(scene.tress.hair_passes)


# The render passes tress fills: (pass name, tress AOV channels, Blender channel ids, kind,
# whether the view layer asks for it). Depth, Normal and Object Index are Blender's own
# passes (View Layer properties); the hair passes are tress's, switched on together in the
# tress panel.
PASSES = (
    ("Depth", ("Z",), "Z", "VALUE", _layer_flag("use_pass_z")),
    ("Normal", ("N.X", "N.Y", "N.Z"), "XYZ", "VECTOR", _layer_flag("use_pass_normal")),
    ("IndexOB", ("objectId",), "X", "VALUE", _layer_flag("use_pass_object_index")),
    ("strandId", ("strandId",), "X", "VALUE", _hair_passes),
    ("strandAlong", ("strandAlong",), "X", "VALUE", _hair_passes),
    ("rootUV", ("rootUV.U", "rootUV.V", "A"), "UVA", "VECTOR", _hair_passes),
    ("clumpId", ("clumpId",), "X", "VALUE", _hair_passes),
    ("strandRandom", ("strandRandom",), "X", "VALUE", _hair_passes),
)


class TressRenderEngine(bpy.types.RenderEngine):
    bl_idname = "TRESS"
    bl_label = "tress"
    bl_use_preview = False
    bl_use_postprocess = True

    def render(self, depsgraph):
        scene = depsgraph.scene
        width, height = export.resolution(scene)
        try:
            doc, warnings = export.build(depsgraph, render_settings(scene))
        except Exception as e:  # noqa: BLE001 - shown to the user, not swallowed
            self.report({"ERROR"}, f"tress: {e}")
            return
        for w in warnings:
            self.report({"WARNING"}, f"tress: {w}")
        tress = tress_module() if scene.tress.use_module else None
        if tress is not None:
            self._render_module(tress, doc, width, height)
        else:
            self._render_cli(doc, width, height)

    def update_render_passes(self, scene=None, renderlayer=None):
        """The passes of :data:`PASSES` the view layer asks for, beside Combined."""
        self.register_pass(scene, renderlayer, "Combined", 4, "RGBA", "COLOR")
        for name, _, chan_id, kind, enabled in PASSES:
            if enabled(scene, renderlayer):
                self.register_pass(scene, renderlayer, name, len(chan_id), chan_id, kind)

    def _put(self, rgba, width, height, result=None, aovs=None):
        """Writes an (h, w, 4) top-row-first array into the render result, and each pass
        of :data:`PASSES` the result has from ``aovs`` (channel name -> (h, w) array)."""
        own = result is None
        if own:
            result = self.begin_result(0, 0, width, height)
        passes = result.layers[0].passes
        passes["Combined"].rect.foreach_set(_flip(rgba))
        for name, channels, _, _, _ in PASSES:
            target = passes.find_by_name(name, "")
            if target is None or aovs is None or any(c not in aovs for c in channels):
                continue
            target.rect.foreach_set(_flip(np.stack([aovs[c] for c in channels], axis=-1)))
        if own:
            self.end_result(result)
        else:
            self.update_result(result)

    def _render_module(self, tress, doc, width, height):
        with tempfile.TemporaryDirectory(prefix="tress-blender-") as folder:
            try:
                scene = to_native(doc, tress, folder)
            except (ValueError, tress.TressError) as e:
                self.report({"ERROR"}, f"tress: {e}")
                return
            self._render_native(tress, scene, width, height)

    def _render_native(self, tress, scene, width, height):
        result = self.begin_result(0, 0, width, height)

        def progress(done, total):
            self.update_progress(done / max(total, 1))
            self.update_stats("tress", f"{done} of {total} tiles")
            return not self.test_break()

        def preview(image):
            self._put(np.asarray(image), width, height, result)

        try:
            image = tress.render(scene, progress=progress, preview=preview, preview_interval=0.5)
        except tress.TressError as e:
            self.end_result(result, cancel=True)
            self.report({"ERROR"}, f"tress: {e}")
            return
        self._put(np.asarray(image), width, height, result, image.aovs())
        self.end_result(result)

    def _render_cli(self, doc, width, height):
        cli = cli_path(bpy.context)
        if cli is None:
            self.report({"ERROR"}, "tress: neither the tress Python module nor the tress command was found; "
                        "set the command's path in the add-on's preferences")
            return
        with tempfile.TemporaryDirectory(prefix="tress-blender-") as folder:
            scene_file = doc.write(folder)
            out = os.path.join(folder, "render.exr")
            process = subprocess.Popen(
                [cli, "render", scene_file, "-o", out, "--quiet"], stderr=subprocess.PIPE, text=True
            )
            while process.poll() is None:
                if self.test_break():
                    process.terminate()
                    process.wait()
                    return
                time.sleep(0.1)
            err = process.stderr.read() if process.stderr else ""
            if process.returncode != 0:
                self.report({"ERROR"}, f"tress: {err.strip()}")
                return
            try:
                channels = exr.read_channels(out)
            except (OSError, ValueError) as e:
                self.report({"ERROR"}, f"tress: {e}")
                return
            self._put(np.stack([channels[c] for c in "RGBA"], axis=-1), width, height, aovs=channels)


def compatible_panels():
    """Blender's own property panels that also apply to tress (output, dimensions,
    camera and light data, materials)."""
    keep = ("RENDER_PT_format", "RENDER_PT_frame_range", "RENDER_PT_output", "DATA_PT_lens", "DATA_PT_camera",
            "DATA_PT_context_light", "DATA_PT_light", "DATA_PT_EEVEE_light", "MATERIAL_PT_preview",
            "EEVEE_MATERIAL_PT_context_material", "EEVEE_MATERIAL_PT_surface", "WORLD_PT_context_world",
            "EEVEE_WORLD_PT_surface", "DATA_PT_camera_dof", "RENDER_PT_color_management")
    for name in keep:
        panel = getattr(bpy.types, name, None)
        if panel is not None and hasattr(panel, "COMPAT_ENGINES"):
            yield panel


def register():
    bpy.utils.register_class(TressRenderEngine)
    for panel in compatible_panels():
        panel.COMPAT_ENGINES.add(TressRenderEngine.bl_idname)


def unregister():
    for panel in compatible_panels():
        panel.COMPAT_ENGINES.discard(TressRenderEngine.bl_idname)
    bpy.utils.unregister_class(TressRenderEngine)
