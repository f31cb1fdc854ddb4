#!/usr/bin/env python3
"""Writes the example scenes of other tools' formats under scenes/:

- maya_hair.ma: a head-like sphere (a polySphere node) on a stored ground mesh, a hair
  system of 160 follicles with degree-3 start curves lying over the head, a FurDescription
  attached through a FurFeedback node, a render camera, a directional and an ambient light.
- pbrt_hair.pbrt (+ pbrt_hair_curves.pbrt, included): a tuft of cubic Bezier and B-spline
  curves with tapering widths and pbrt's hair material over a box (plymesh) and a ground
  trianglemesh, lit by a distant and an infinite light.
- usd_hair.usda: cubic B-spline BasisCurves with vertex widths and colours, linear curves,
  a ground Mesh, a distant and a dome light.

Deterministic (fixed seeds); run from the repository root: python3 scripts/gen_interop_scenes.py
"""
import math
import random


def fmt(x):
    return f"{x:.5g}"


def maya():
    rnd = random.Random(7)
    out = []
    w = out.append
    w("//Maya ASCII 2020 scene")
    w("//Name: maya_hair.ma (written by scripts/gen_interop_scenes.py)")
    w('requires maya "2020";')
    w("currentUnit -l centimeter -a degree -t film;")
    w('fileInfo "application" "maya";')
    # Maya's default cameras (not rendered: a file's own camera wins).
    w('createNode transform -s -n "persp";')
    w('\tsetAttr ".v" no;')
    w('\tsetAttr ".t" -type "double3" 28 21 28 ;')
    w('createNode camera -s -n "perspShape" -p "persp";')
    w('\tsetAttr -k off ".v" no;')
    w('\tsetAttr ".fl" 34.999999999999993;')
    w('createNode transform -s -n "top";')
    w('\tsetAttr ".v" no;')
    w('createNode camera -s -n "topShape" -p "top";')
    w('\tsetAttr ".rnd" no;')
    w('\tsetAttr ".o" yes;')
    # Render camera: at (0, 1.9, 5.2) looking at (0, 1.1, 0).
    pitch = -math.degrees(math.atan2(0.8, 5.2))
    w('createNode transform -n "renderCam";')
    w(f'\tsetAttr ".t" -type "double3" 0 1.9 5.2 ;')
    w(f'\tsetAttr ".r" -type "double3" {fmt(pitch)} 0 0 ;')
    w('createNode camera -n "renderCamShape" -p "renderCam";')
    w('\tsetAttr ".fl" 45;')
    w(f'\tsetAttr ".coi" {fmt(math.hypot(0.8, 5.2))};')
    # Ground: a stored 1-quad mesh, 8 x 8.
    w('createNode transform -n "ground";')
    w('createNode mesh -n "groundShape" -p "ground";')
    w('\tsetAttr ".uvst[0].uvsn" -type "string" "map1";')
    w('\tsetAttr -s 4 ".uvst[0].uvsp[0:3]" -type "float2" 0 0 1 0 0 1 1 1;')
    w('\tsetAttr -s 4 ".vt[0:3]"  -4 0 4 4 0 4 -4 0 -4 4 0 -4;')
    w('\tsetAttr -s 4 ".ed[0:3]"  0 1 0 0 2 0 1 3 0 2 3 0;')
    w('\tsetAttr -ch 4 ".fc[0]" -type "polyFaces" ')
    w("\t\tf 4 0 2 -4 -2")
    w("\t\tmu 0 4 0 1 3 2 ;")
    # Head: a polySphere of radius 1 at y = 1.1.
    w('createNode transform -n "head";')
    w('\tsetAttr ".t" -type "double3" 0 1.1 0 ;')
    w('createNode mesh -n "headShape" -p "head";')
    w('createNode polySphere -n "polySphere1";')
    w('\tsetAttr ".sa" 40;')
    w('\tsetAttr ".sh" 40;')
    w('createNode lambert -n "skin";')
    w('\tsetAttr ".c" -type "float3" 0.9 0.68 0.55 ;')
    w('createNode shadingEngine -n "skinSG";')
    # Hair system.
    w('createNode transform -n "hairSystem1";')
    w('createNode hairSystem -n "hairSystemShape1" -p "hairSystem1";')
    w('\tsetAttr ".hpc" 60;')
    w('\tsetAttr ".cwd" 0.22;')
    w('\tsetAttr ".hwd" 0.006;')
    w('\tsetAttr ".ssg" 2;')
    w('\tsetAttr ".thn" 0.2;')
    w('\tsetAttr -s 2 ".cws[0:1]"  0 1 2 1 0.25 2;')
    w('\tsetAttr -s 2 ".hws[0:1]"  0.8 1 1 1 0.3 1;')
    w('\tsetAttr ".clc[0]"  0 0.5 1;')
    w('\tsetAttr ".noi" 0.6;')
    w('\tsetAttr ".nof" 0.6;')
    w('\tsetAttr ".hcl" -type "float3" 0.33 0.19 0.09 ;')
    w('\tsetAttr ".hcs[0].hcsp" 0;')
    w('\tsetAttr ".hcs[0].hcsc" -type "float3" 0.6 0.6 0.6 ;')
    w('\tsetAttr ".hcs[0].hcsi" 1;')
    w('\tsetAttr ".hcs[1].hcsp" 1;')
    w('\tsetAttr ".hcs[1].hcsc" -type "float3" 1.1 1.05 1 ;')
    w('\tsetAttr ".hcs[1].hcsi" 1;')
    w('\tsetAttr ".spc" -type "float3" 0.3 0.28 0.25 ;')
    w('\tsetAttr ".spp" 30;')
    w('createNode transform -n "hairSystem1Follicles";')
    conns = []
    center = (0.0, 1.1, 0.0)
    count = 0
    # Follicles over the top and back of the head: polar angle up to 80 degrees, the
    # face (towards +z) left bare.
    for i in range(28):
        for j in range(7):
            phi = 2 * math.pi * (i + 0.5 * (j % 2) + 0.3 * rnd.random()) / 28
            theta = math.radians(8 + 72 * (j + 0.5) / 7)
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
            if n[2] > 0.3 and theta > math.radians(40):
                continue
            count += 1
            f = f"follicle{count}"
            w(f'createNode transform -n "{f}" -p "hairSystem1Follicles";')
            root = tuple(c + r for c, r in zip(center, n))
            w(f'\tsetAttr ".t" -type "double3" {fmt(root[0])} {fmt(root[1])} {fmt(root[2])} ;')
            w(f'createNode follicle -n "{f}Shape" -p "{f}";')
            w(f'\tsetAttr ".pu" {fmt(phi / (2 * math.pi))};')
            w(f'\tsetAttr ".pv" {fmt(1 - theta / math.pi)};')
            # The start curve lies over the head along its meridian, lifting off it, then
            # falls: 7 CVs, degree 3, 4 spans, clamped knots.
            length = 2.2 + 0.2 * rnd.random()
            cvs = []
            for k in range(7):
                s = k / 6
                th = theta + s * (math.pi * 0.85 - theta) * min(1.0, 1.4 * s + 0.2)
                r = 1.0 + 0.015 + 0.06 * s
                p = (math.sin(th) * math.cos(phi) * r, math.cos(th) * r, math.sin(th) * math.sin(phi) * r)
                drop = max(0.0, s * length - 1.3)
                p = (p[0], p[1] - drop, p[2])
                if k == 0:
                    p = n
                cvs.append(tuple(pc - nc for pc, nc in zip(p, n)))
            c = f"curve{count}"
            w(f'createNode transform -n "{c}" -p "{f}";')
            w(f'createNode nurbsCurve -n "{c}Shape" -p "{c}";')
            w('\tsetAttr ".cc" -type "nurbsCurve" ')
            w("\t\t3 4 0 no 3")
            w("\t\t9 0 0 0 1 2 3 4 4 4")
            w("\t\t7")
            for p in cvs:
                w(f"\t\t{fmt(p[0])} {fmt(p[1])} {fmt(p[2])}")
            w("\t\t;")
            conns.append(f'connectAttr "{c}Shape.ws" "{f}Shape.sp";')
            conns.append(f'connectAttr "headShape.o" "{f}Shape.inm";')
            conns.append(f'connectAttr "{f}Shape.oha" "hairSystemShape1.ih[{count - 1}]";')
            conns.append(f'connectAttr "hairSystemShape1.oh[{count - 1}]" "{f}Shape.crp";')
    # Fur on the head (read, and grown once tress's fur generator is merged).
    w('createNode FurDescription -n "FurDescription1";')
    w('\tsetAttr ".d" 20000;')
    w('\tsetAttr ".dl" 0.15;')
    w('\tsetAttr ".dbw" 0.01;')
    w('\tsetAttr ".dtw" 0.002;')
    w('\tsetAttr ".dbc" -type "float3" 0.3 0.2 0.1 ;')
    w('\tsetAttr ".di" 0.6;')
    w('createNode transform -n "FurFeedback1";')
    w('createNode FurFeedback -n "FurFeedbackShape1" -p "FurFeedback1";')
    # Lights.
    w('createNode transform -n "key";')
    w('\tsetAttr ".r" -type "double3" -50 35 0 ;')
    w('createNode directionalLight -n "keyShape" -p "key";')
    w('\tsetAttr ".in" 1.1;')
    w('createNode transform -n "fill";')
    w('createNode ambientLight -n "fillShape" -p "fill";')
    w('\tsetAttr ".in" 0.2;')
    w('select -ne :defaultResolution;')
    w('\tsetAttr ".w" 480;')
    w('\tsetAttr ".h" 360;')
    w('connectAttr "polySphere1.out" "headShape.i";')
    w('connectAttr "skin.oc" "skinSG.ss";')
    w('connectAttr "headShape.iog" "skinSG.dsm" -na;')
    w('connectAttr "headShape.w" "FurFeedbackShape1.imsh";')
    w('connectAttr "FurDescription1.dl" "FurFeedbackShape1.dl";')
    out.extend(conns)
    w("// End of maya_hair.ma")
    with open("scenes/maya_hair.ma", "w") as fh:
        fh.write("\n".join(out) + "\n")


def pbrt():
    rnd = random.Random(11)
    with open("scenes/pbrt_hair.pbrt", "w") as fh:
        fh.write("""# A tuft of hair in pbrt-v4's format (written by scripts/gen_interop_scenes.py).
LookAt 0 1.2 4.5   0 0.7 0   0 1 0
Camera "perspective" "float fov" [ 32 ]
Sampler "zsobol" "integer pixelsamples" [ 16 ]
Integrator "volpath" "integer maxdepth" [ 5 ]
Film "rgb" "integer xresolution" [ 480 ] "integer yresolution" [ 360 ] "string filename" [ "pbrt_hair.exr" ]
WorldBegin
LightSource "distant" "point3 from" [ 1 3 2 ] "point3 to" [ 0 0 0 ] "rgb L" [ 3 3 3 ]
LightSource "infinite" "rgb L" [ 0.15 0.16 0.2 ]
AttributeBegin
  Material "diffuse" "rgb reflectance" [ 0.45 0.45 0.45 ]
  Shape "trianglemesh" "integer indices" [ 0 1 2 0 2 3 ]
    "point3 P" [ -4 0 -4  4 0 -4  4 0 4  -4 0 4 ] "point2 uv" [ 0 0 1 0 1 1 0 1 ]
AttributeEnd
AttributeBegin
  Material "diffuse" "rgb reflectance" [ 0.2 0.3 0.5 ]
  Translate 1.3 0.25 -0.4
  Rotate 30 0 1 0
  Scale 0.5 0.5 0.5
  Shape "plymesh" "string filename" "box.ply"
AttributeEnd
AttributeBegin
  Material "hair" "float eumelanin" [ 0.3 ] "float pheomelanin" [ 0.1 ] "float beta_m" [ 0.25 ]
  Include "pbrt_hair_curves.pbrt"
AttributeEnd
""")
    with open("scenes/pbrt_hair_curves.pbrt", "w") as fh:
        fh.write("# The curves of pbrt_hair.pbrt: Bezier strands rising from a disc and bending away.\n")
        for i in range(900):
            r = 0.35 * math.sqrt(rnd.random())
            a = 2 * math.pi * rnd.random()
            x, z = r * math.cos(a), r * math.sin(a)
            bend = 2 * math.pi * rnd.random()
            h = 1.1 + 0.3 * rnd.random()
            lean = 0.25 + 0.5 * r
            pts = [(x, 0, z)]
            for k in range(1, 7):
                s = k / 6
                pts.append((x + lean * s * s * math.cos(bend) + 0.02 * math.sin(7 * s + i),
                            h * (s - 0.25 * s * s * lean),
                            z + lean * s * s * math.sin(bend)))
            basis = "bezier" if i % 2 == 0 else "bspline"
            p = "  ".join(" ".join(fmt(c) for c in q) for q in pts)
            fh.write(f'Shape "curve" "string type" "cylinder" "string basis" "{basis}" "point3 P" [ {p} ] '
                     f'"float width0" [ 0.012 ] "float width1" [ 0.002 ]\n')


def usd():
    rnd = random.Random(5)
    counts, pts, widths, colors = [], [], [], []
    for i in range(400):
        x, z = rnd.uniform(-1.2, 1.2), rnd.uniform(-0.6, 0.6)
        h = 0.8 + 0.5 * rnd.random()
        swirl = rnd.random() * 2 * math.pi
        n = 6
        counts.append(n)
        for k in range(n):
            s = k / (n - 1)
            pts.append((x + 0.15 * s * math.cos(swirl + 3 * s), h * s, z + 0.15 * s * math.sin(swirl + 3 * s)))
            widths.append(0.02 * (1 - 0.85 * s))
            colors.append((0.15 + 0.6 * s, 0.45 + 0.3 * s, 0.1))
    lin_counts, lin_pts = [], []
    for i in range(60):
        a = 2 * math.pi * i / 60
        lin_counts.append(3)
        lin_pts += [(1.8 * math.cos(a), 0, 1.8 * math.sin(a) - 0.5), (1.9 * math.cos(a), 0.3, 1.9 * math.sin(a) - 0.5),
                    (2.1 * math.cos(a), 0.45, 2.1 * math.sin(a) - 0.5)]

    def arr(v):
        return "[" + ", ".join("(" + ", ".join(fmt(c) for c in p) + ")" for p in v) + "]"

    with open("scenes/usd_hair.usda", "w") as fh:
        fh.write(f"""#usda 1.0
(
    defaultPrim = "World"
    doc = "A field of grass-like curves (written by scripts/gen_interop_scenes.py)"
    upAxis = "Y"
)

def Xform "World"
{{
    def Mesh "Ground"
    {{
        int[] faceVertexCounts = [4]
        int[] faceVertexIndices = [0, 3, 2, 1]
        point3f[] points = [(-3, 0, -3), (3, 0, -3), (3, 0, 3), (-3, 0, 3)]
        color3f[] primvars:displayColor = [(0.35, 0.3, 0.25)]
        uniform token subdivisionScheme = "none"
    }}

    def BasisCurves "Grass"
    {{
        uniform token type = "cubic"
        uniform token basis = "bspline"
        uniform token wrap = "pinned"
        int[] curveVertexCounts = [{", ".join(map(str, counts))}]
        point3f[] points = {arr(pts)}
        float[] widths = [{", ".join(fmt(x) for x in widths)}] (
            interpolation = "vertex"
        )
        color3f[] primvars:displayColor = {arr(colors)} (
            interpolation = "vertex"
        )
    }}

    def Xform "Ring"
    {{
        double3 xformOp:translate = (0, 0.01, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]

        def BasisCurves "Stalks"
        {{
            uniform token type = "linear"
            int[] curveVertexCounts = [{", ".join(map(str, lin_counts))}]
            point3f[] points = {arr(lin_pts)}
            float[] widths = [0.03] (
                interpolation = "constant"
            )
            color3f[] primvars:displayColor = [(0.6, 0.5, 0.2)]
        }}
    }}

    def DistantLight "Sun"
    {{
        float inputs:intensity = 3
        float3 xformOp:rotateXYZ = (-55, 30, 0)
        uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]
    }}

    def DomeLight "Sky"
    {{
        float inputs:intensity = 0.2
    }}
}}
""")


if __name__ == "__main__":
    maya()
    pbrt()
    usd()
