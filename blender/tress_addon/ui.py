"""The tress settings (render properties panel), the add-on's preferences and the
File > Export > tress scene folder operator."""

from __future__ import annotations

import bpy
from bpy.props import BoolProperty, EnumProperty, IntProperty, PointerProperty, StringProperty

from . import engine, export


class TressSettings(bpy.types.PropertyGroup):
    """The ``[render]`` keys of a tress scene (``docs/scene-format.md``)."""

    spp: IntProperty(name="Samples", description="Camera samples per pixel", default=16, min=1, max=1 << 20)
    seed: IntProperty(name="Seed", description="Seed of every random decision", default=0, min=0)
    integrator: EnumProperty(
        name="Integrator",
        items=[
            ("direct", "Direct", "Direct light, hard and soft shadows, mirror and glass recursion"),
            ("final-gather", "Final Gather", "Direct light plus one gathered bounce"),
            ("path", "Path", "Unbiased path tracing"),
        ],
        default="direct",
    )
    lod: BoolProperty(name="Level of Detail", description="Level of detail for the strand sets that ask for it",
                      default=True)
    transparency_layers: IntProperty(
        name="Transparency Layers", description="Partial hits collected per traversal through semi-transparent hair",
        default=8, min=1, max=64,
    )
    max_depth: IntProperty(name="Max Depth", description="Mirror and glass bounces", default=5, min=0, max=64)
    threads: IntProperty(name="Threads", description="Worker threads, 0 for every core", default=0, min=0)
    hair_passes: BoolProperty(
        name="Hair Passes",
        description="Render passes strandId, strandAlong (0 root to 1 tip), rootUV, clumpId and strandRandom, "
        "beside Blender's Depth, Normal and Object Index passes of the view layer",
        default=False,
    )
    use_module: BoolProperty(
        name="Use Python Module", default=True,
        description="Render in Blender's process with the tress Python module when it is installed, "
                    "else with the tress command",
    )


class TRESS_PT_settings(bpy.types.Panel):
    bl_label = "tress"
    bl_space_type = "PROPERTIES"
    bl_region_type = "WINDOW"
    bl_context = "render"
    COMPAT_ENGINES = {"TRESS"}

    @classmethod
    def poll(cls, context):
        return context.engine in cls.COMPAT_ENGINES

    def draw(self, context):
        t = context.scene.tress
        layout = self.layout
        layout.use_property_split = True
        for name in ("spp", "integrator", "lod", "transparency_layers", "max_depth", "seed", "threads", "hair_passes", "use_module"):
            layout.prop(t, name)


class TressPreferences(bpy.types.AddonPreferences):
    bl_idname = __package__

    cli_path: StringProperty(
        name="tress Command", subtype="FILE_PATH",
        description="The tress command, used when the tress Python module is not installed (default: tress on PATH)",
    )

    def draw(self, context):
        self.layout.prop(self, "cli_path")
        module = engine.tress_module()
        self.layout.label(text="Python module: " + ("found" if module else "not installed, the command is used"))


class TRESS_OT_export_scene(bpy.types.Operator):
    """Export the scene to a tress scene folder (scene.toml with .hair and .obj files)"""

    bl_idname = "export_scene.tress"
    bl_label = "Export tress Scene Folder"

    directory: StringProperty(subtype="DIR_PATH")

    def execute(self, context):
        if not self.directory:
            self.report({"ERROR"}, "choose a folder")
            return {"CANCELLED"}
        depsgraph = context.evaluated_depsgraph_get()
        try:
            doc, warnings = export.build(depsgraph, engine.render_settings(context.scene))
            path = doc.write(bpy.path.abspath(self.directory))
        except (RuntimeError, OSError, ValueError) as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        for w in warnings:
            self.report({"WARNING"}, w)
        self.report({"INFO"}, f"wrote {path}")
        return {"FINISHED"}

    def invoke(self, context, event):
        context.window_manager.fileselect_add(self)
        return {"RUNNING_MODAL"}


def menu_export(self, context):
    self.layout.operator(TRESS_OT_export_scene.bl_idname, text="tress Scene Folder")


CLASSES = (TressSettings, TRESS_PT_settings, TressPreferences, TRESS_OT_export_scene)


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Scene.tress = PointerProperty(type=TressSettings)
    bpy.types.TOPBAR_MT_file_export.append(menu_export)


def unregister():
    bpy.types.TOPBAR_MT_file_export.remove(menu_export)
    del bpy.types.Scene.tress
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
