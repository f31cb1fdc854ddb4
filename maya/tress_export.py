"""Export a Maya scene to a tress scene folder (scene.toml, OBJ meshes, .hair strands), for
binary ``.mb`` scenes and live sessions (tress reads ``.ma`` files itself).

Run it in ``mayapy`` or Maya's Script Editor, with this folder on ``sys.path``::

    import tress_export
    tress_export.export("/path/to/folder")            # the current scene
    # or, from a shell:  mayapy tress_export.py scene.mb /path/to/folder

It exports: polygon meshes (triangulated, world space, Lambert/Blinn/Phong colour ×
diffuse), hair systems (each with the curves of its follicles as guides, sampled
uniformly, and its attributes as ``[[hair_system]]`` keys), fur descriptions (as
``[[fur]]`` entries on the meshes they are attached to), the render camera (the first
renderable perspective camera) and directional, point, spot, ambient and area lights.
Meshes and hair systems keep their render stats (Primary Visibility, Casts Shadows) and
MtoA's Matte as the entries' visibility switches.

**This script has not been run in Maya**: Maya was not available where it was written.
Its Maya-independent part (``tress_maya_convert.py``: conversions and the entries it
writes) is tested; the calls to ``maya.cmds`` here follow Maya's documented commands and
may need fixes on first use. Report what fails with the Maya version.
"""

from __future__ import annotations

import sys

import tress_maya_convert as convert

# Samples per guide curve span: enough for smooth clumps, as tress's .ma reader samples.
SAMPLES_PER_SPAN = 8


def _cmds():
    from maya import cmds  # only inside Maya

    return cmds


def _matrix(cmds, node):
    return cmds.xform(node, query=True, worldSpace=True, matrix=True)


def _resolution(cmds):
    return (int(cmds.getAttr("defaultResolution.width")), int(cmds.getAttr("defaultResolution.height")))


def _camera(cmds, resolution):
    shapes = [c for c in cmds.ls(type="camera") if not cmds.getAttr(c + ".orthographic")]
    renderable = [c for c in shapes if cmds.getAttr(c + ".renderable")] or shapes
    if not renderable:
        raise RuntimeError("the scene has no perspective camera")
    shape = renderable[0]
    transform = cmds.listRelatives(shape, parent=True, fullPath=True)[0]
    vfov = convert.vertical_fov(
        cmds.getAttr(shape + ".focalLength"), cmds.getAttr(shape + ".horizontalFilmAperture"),
        cmds.getAttr(shape + ".verticalFilmAperture"), cmds.getAttr(shape + ".filmFit"), *resolution,
    )
    return convert.camera_table(_matrix(cmds, transform), vfov)


def _mesh_color(cmds, shape):
    groups = cmds.listConnections(shape, type="shadingEngine") or []
    for sg in groups:
        shaders = cmds.listConnections(sg + ".surfaceShader") or []
        for s in shaders:
            if cmds.nodeType(s) in ("lambert", "blinn", "phong", "phongE"):
                color = cmds.getAttr(s + ".color")[0]
                diffuse = cmds.getAttr(s + ".diffuse")
                return [c * diffuse for c in color]
    return [0.4, 0.4, 0.4]


def _visibility(cmds, shape):
    """The shape's render stats and ``aiMatte`` (present with MtoA) as entry keys."""
    values = {a: cmds.getAttr(f"{shape}.{a}") for a in convert.VISIBILITY_ATTRIBUTES
              if cmds.attributeQuery(a, node=shape, exists=True)}
    return convert.shape_visibility(values)


def _meshes(cmds, doc, warnings):
    """Exports every visible mesh; returns the 1-based entry number by shape name."""
    from maya.api import OpenMaya as om

    numbers = {}
    for shape in cmds.ls(type="mesh", long=True, noIntermediate=True):
        if not cmds.getAttr(shape + ".visibility"):
            continue
        sel = om.MSelectionList()
        sel.add(shape)
        fn = om.MFnMesh(sel.getDagPath(0))
        points = [[p.x, p.y, p.z] for p in fn.getPoints(om.MSpace.kWorld)]
        counts, vertices = fn.getTriangles()
        tris = [list(vertices[i:i + 3]) for i in range(0, len(vertices), 3)]
        if not tris:
            continue
        name = f"{shape.split('|')[-1]}.obj"
        doc.files[name] = convert.mesh(points, tris)
        doc.meshes.append({"file": name, "material": {"type": "diffuse", "color": _mesh_color(cmds, shape)},
                           **_visibility(cmds, shape)})
        numbers[shape] = len(doc.meshes)
    return numbers


def _sample_curve(cmds, curve):
    from maya.api import OpenMaya as om

    sel = om.MSelectionList()
    sel.add(curve)
    fn = om.MFnNurbsCurve(sel.getDagPath(0))
    lo, hi = fn.knotDomain
    n = max(2, fn.numSpans * SAMPLES_PER_SPAN + 1)
    return [list(fn.getPointAtParam(lo + (hi - lo) * i / (n - 1), om.MSpace.kWorld))[:3] for i in range(n)]


def _ramp_values(cmds, node, attr):
    out = []
    for i in cmds.getAttr(f"{node}.{attr}", multiIndices=True) or []:
        base = f"{node}.{attr}[{i}]"
        children = cmds.attributeQuery(attr, node=node, listChildren=True) or []
        pos = cmds.getAttr(f"{base}.{children[0]}")
        value = cmds.getAttr(f"{base}.{children[1]}")
        interp = cmds.getAttr(f"{base}.{children[2]}")
        out.append((pos, value[0] if isinstance(value, list) else value, interp))
    return out


def _hair_systems(cmds, doc, warnings):
    for system in cmds.ls(type="hairSystem"):
        follicles = cmds.listConnections(system + ".inputHair", type="follicle", shapes=True) or []
        curves = []
        for f in follicles:
            out = cmds.listConnections(f + ".outCurve", shapes=True) or cmds.listConnections(
                f + ".startPosition", shapes=True
            ) or []
            if out:
                curves.append(_sample_curve(cmds, out[0]))
        if not curves:
            warnings.append(f"{system}: no follicle curves; skipped")
            continue
        values = {}
        for name, (_, kind) in convert.HAIR_SYSTEM_ATTRIBUTES.items():
            if not cmds.attributeQuery(name, node=system, exists=True):
                continue
            values[name] = _ramp_values(cmds, system, name) if "ramp" in kind else cmds.getAttr(f"{system}.{name}")
        guides = f"{system}_guides.hair"
        doc.files[guides] = convert.strands(curves)
        entry, w = convert.hair_system_entry(values, guides)
        warnings.extend(w)
        doc.hair_systems.append({**entry, **_visibility(cmds, system)})


def _furs(cmds, doc, mesh_numbers, warnings):
    for desc in cmds.ls(type="FurDescription"):
        feedbacks = cmds.listConnections(desc, type="FurFeedback") or []
        for fb in feedbacks:
            surfaces = cmds.listConnections(fb + ".inputSurface", shapes=True) or []
            for s in surfaces:
                full = (cmds.ls(s, long=True) or [s])[0]
                if full not in mesh_numbers:
                    continue
                values = {}
                for attr in convert.FUR_ATTRIBUTES:
                    maya = "".join(part.capitalize() for part in attr.split("_"))
                    if cmds.attributeQuery(maya, node=desc, exists=True):
                        values[maya] = cmds.getAttr(f"{desc}.{maya}")
                entry, w = convert.fur_entry(mesh_numbers[full], values)
                warnings.extend(w)
                doc.fur.append(entry)


def _lights(cmds, doc, warnings):
    for kind in ("directionalLight", "pointLight", "spotLight", "ambientLight", "areaLight"):
        for shape in cmds.ls(type=kind):
            transform = cmds.listRelatives(shape, parent=True, fullPath=True)[0]
            extra = {}
            if kind == "spotLight":
                extra = {"cone_angle": cmds.getAttr(shape + ".coneAngle"),
                         "penumbra": cmds.getAttr(shape + ".penumbraAngle")}
            entry = convert.light_entry(kind, _matrix(cmds, transform), cmds.getAttr(shape + ".color"),
                                        cmds.getAttr(shape + ".intensity"), **extra)
            if entry:
                doc.lights.append(entry)


def export(folder: str) -> str:
    """Writes the current Maya scene to ``folder``; returns the scene file's path."""
    cmds = _cmds()
    warnings: list[str] = []
    resolution = _resolution(cmds)
    doc = convert.scene_doc(_camera(cmds, resolution), resolution)
    numbers = _meshes(cmds, doc, warnings)
    _hair_systems(cmds, doc, warnings)
    _furs(cmds, doc, numbers, warnings)
    _lights(cmds, doc, warnings)
    for w in warnings:
        print(f"tress export: warning: {w}")
    return doc.write(folder)


def main(argv: list[str]) -> int:
    if len(argv) != 3:
        print("usage: mayapy tress_export.py SCENE.mb FOLDER", file=sys.stderr)
        return 2
    import maya.standalone

    maya.standalone.initialize()
    _cmds().file(argv[1], open=True, force=True)
    print(export(argv[2]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
