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


def to_native(doc, tress):
    """A :class:`SceneDoc` as a ``tress.Scene`` (same tables, geometry as arrays)."""
    scene = tress.Scene(doc.camera, doc.render)
    for entry in doc.lights:
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

    def _put(self, rgba, width, height, result=None):
        """Writes an (h, w, 4) top-row-first array into the render result."""
        own = result is None
        if own:
            result = self.begin_result(0, 0, width, height)
        flipped = np.ascontiguousarray(rgba[::-1].reshape(-1, 4), dtype=np.float32)
        result.layers[0].passes["Combined"].rect.foreach_set(flipped.ravel())
        if own:
            self.end_result(result)
        else:
            self.update_result(result)

    def _render_module(self, tress, doc, width, height):
        try:
            scene = to_native(doc, tress)
        except (ValueError, tress.TressError) as e:
            self.report({"ERROR"}, f"tress: {e}")
            return
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
        self._put(np.asarray(image), width, height, result)
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
                rgba = exr.read_rgba(out)
            except (OSError, ValueError) as e:
                self.report({"ERROR"}, f"tress: {e}")
                return
            self._put(rgba, width, height)


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
