#!/usr/bin/env python3
"""The hairy torus reference scene, written the same way every time, for comparing tress
with Embree, Mitsuba 3 and Blender Cycles on the same geometry (docs/performance.md).

Writes, into OUTDIR:
  torus.obj          a triangulated torus (major radius 1, minor 0.35, its ring in the xz-plane)
  hairy_torus.hair   strands grown on it, in Cem Yuksel's HAIR format (thickness = diameter)
  hairy_torus.txt    the same strands as text: 'x y z radius' a line, a blank line between strands
  scene.json         the camera, lights, film and materials every renderer uses

`tress render OUTDIR`, `tress bench OUTDIR` and scripts/bench-vs-embree.sh,
scripts/compare-end-to-end.sh and scripts/compare-noise.sh read the directory.

Usage: gen_scenes.py OUTDIR [--strands N] [--segments S]   (default 60,000 strands of 12
segments: 720,000 segments; --strands 600000 gives 7.2 million). Needs numpy.
"""
import argparse, json, math, os, struct
import numpy as np

R, r = 1.0, 0.35


def torus_mesh(nu=96, nv=48):
    verts, faces = [], []
    for i in range(nu):
        u = 2 * math.pi * i / nu
        for j in range(nv):
            v = 2 * math.pi * j / nv
            verts.append(((R + r * math.cos(v)) * math.cos(u), r * math.sin(v), (R + r * math.cos(v)) * math.sin(u)))
    for i in range(nu):
        for j in range(nv):
            a = i * nv + j
            b = ((i + 1) % nu) * nv + j
            c = ((i + 1) % nu) * nv + (j + 1) % nv
            d = i * nv + (j + 1) % nv
            faces.append((a, d, c))
            faces.append((a, c, b))
    return np.array(verts), np.array(faces)


def strands(n, segs, rng):
    # area-uniform roots on the torus: accept v with probability proportional to (R + r cos v)
    u = rng.uniform(0, 2 * math.pi, 4 * n)
    v = rng.uniform(0, 2 * math.pi, 4 * n)
    keep = rng.uniform(0, R + r, 4 * n) < (R + r * np.cos(v))
    u, v = u[keep][:n], v[keep][:n]
    cu, su, cv, sv = np.cos(u), np.sin(u), np.cos(v), np.sin(v)
    root = np.stack([(R + r * cv) * cu, r * sv, (R + r * cv) * su], 1)
    normal = np.stack([cv * cu, sv, cv * su], 1)
    length = 0.22 * rng.uniform(0.8, 1.2, n)
    step = (length / segs)[:, None]
    d = normal + 0.25 * rng.normal(size=(n, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    curl_axis = rng.normal(size=(n, 3))
    curl_axis /= np.linalg.norm(curl_axis, axis=1, keepdims=True)
    pts = [root]
    p = root.copy()
    gravity = np.array([0.0, -1.0, 0.0])
    for k in range(segs):
        # droop under gravity, plus a slow curl about a per-strand axis
        d = d + 0.18 * gravity + 0.12 * np.cross(curl_axis, d)
        d /= np.linalg.norm(d, axis=1, keepdims=True)
        p = p + step * d
        pts.append(p)
    pts = np.stack(pts, 1)  # n, segs+1, 3
    t = np.linspace(0, 1, segs + 1)
    width = 0.0030 * (1 - t) + 0.0008 * t  # diameter, root to tip
    return pts.astype(np.float32), np.broadcast_to(width, (n, segs + 1)).astype(np.float32)


def write_hair(path, pts, width, color):
    n, m, _ = pts.shape
    flags = 1 | 2 | 4  # segments, points, thickness arrays
    info = b"hairy torus reference scene".ljust(88, b"\0")
    hdr = b"HAIR" + struct.pack("<IIIIff3f", n, n * m, flags, m - 1, float(width[0, 0]), 0.0, *color) + info
    assert len(hdr) == 128
    with open(path, "wb") as f:
        f.write(hdr)
        f.write(np.full(n, m - 1, dtype="<u2").tobytes())
        f.write(pts.astype("<f4").tobytes())
        f.write(width.astype("<f4").tobytes())


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--strands", type=int, default=60000)
    ap.add_argument("--segments", type=int, default=12)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    rng = np.random.default_rng(20071)
    V, F = torus_mesh()
    with open(os.path.join(a.out, "torus.obj"), "w") as f:
        f.writelines("v %.6f %.6f %.6f\n" % tuple(x) for x in V)
        f.writelines("f %d %d %d\n" % tuple(x + 1) for x in F)
    hair_color = [0.35, 0.20, 0.10]
    pts, width = strands(a.strands, a.segments, rng)
    write_hair(os.path.join(a.out, "hairy_torus.hair"), pts, width, hair_color)
    with open(os.path.join(a.out, "hairy_torus.txt"), "w") as f:
        for s in range(pts.shape[0]):
            f.writelines("%.6f %.6f %.6f %.6f\n" % (*pts[s, k], width[s, k] / 2) for k in range(pts.shape[1]))
            f.write("\n")
    scene = {
        "film": {"width": 640, "height": 480, "spp": 16},
        "camera": {"eye": [0.0, 1.6, 3.2], "target": [0.0, -0.05, 0.0], "up": [0, 1, 0], "vfov_deg": 35.0},
        "lights": [
            {"type": "distant", "direction_to_light": [0.45, 0.8, 0.4], "radiance": [3.0, 3.0, 3.0]},
            {"type": "constant_environment", "radiance": [0.15, 0.15, 0.15]},
        ],
        "meshes": [{"obj": "torus.obj", "diffuse": [0.5, 0.5, 0.5]}],
        "hair": [{"file": "hairy_torus.hair", "text": "hairy_torus.txt", "diffuse": hair_color,
                  "strands": int(pts.shape[0]), "segments": int(pts.shape[0] * (pts.shape[1] - 1))}],
    }
    with open(os.path.join(a.out, "scene.json"), "w") as f:
        json.dump(scene, f, indent=1)
    print("strands", pts.shape[0], "segments", pts.shape[0] * (pts.shape[1] - 1))


if __name__ == "__main__":
    main()
