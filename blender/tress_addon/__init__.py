"""tress as a Blender render engine: hair curves, particle hair, meshes, camera, lights
and world exported to tress and rendered by it; File > Export > tress Scene Folder."""

bl_info = {
    "name": "tress",
    "author": "tress",
    "version": (0, 1, 0),
    "blender": (4, 2, 0),
    "location": "Render Properties > Render Engine > tress; File > Export > tress Scene Folder",
    "description": "Render hair and fur with tress",
    "category": "Render",
}



def register():
    # Imported here, not at the top, so the plain-Python parts (materials, scene_folder)
    # import without Blender.
    from . import engine, ui

    ui.register()
    engine.register()


def unregister():
    from . import engine, ui

    engine.unregister()
    ui.unregister()
