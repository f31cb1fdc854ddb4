#!/usr/bin/env python3
"""Renders the hairy torus of scripts/gen_scenes.py with tress and Mitsuba 3, both with the
physical hair BSDF (Chiang et al. 2016: Mitsuba's `hair`, tress's `physical`) and path
tracing, and prints how far apart the images are.

Usage: python3 scripts/compare-mitsuba-hair.py DIR OUTDIR [--resolution W H] [--spp N]
           [--depth D] [--eumelanin E] [--pheomelanin P] [--renders LIST]

DIR is a scene directory of scripts/gen_scenes.py (scene.json, torus.obj, hairy_torus.txt).
The strands become uniform cubic B-splines whose control points are the file's points, with
a phantom point mirrored at each end so each curve starts and ends where its strand does.
Mitsuba renders them as `bsplinecurve` (its `linearcurve` gives the hair BSDF no fibre
axis); tress renders the same curves sampled at 4 points per span (written to
OUTDIR/curves.hair), so both see the same geometry.

`--depth D` is Mitsuba's `max_depth` (path segments: 2 is direct light only); tress's
`max_depth` is D - 2 (scattering vertices after the camera hit). The renders, chosen by
`--renders` (comma separated, default all):
  direct        tress `direct`
  path0         tress `path` with max_depth 0 (direct light by path tracing)
  path          tress `path` at depth D
  mitsuba       Mitsuba `path` at depth D, seed 0
  mitsuba-seed1 the same with seed 1: the noise level of Mitsuba's image
Then, for the pairs that exist, the mean absolute difference of 8x8 block means over the
mean of the second image, in percent (`diff A B = X %`), and each render's time.
Needs `pip install mitsuba numpy`, a release build of tress (`cargo build --release`) and,
for Mitsuba's LLVM variant, a libLLVM Dr.Jit can use (LLVM 19 works, 15 does not), named by
DRJIT_LIBLLVM_PATH (e.g. /usr/lib/x86_64-linux-gnu/libLLVM.so.19.1).
"""
import argparse, json, os, struct, subprocess, sys, time

import numpy as np


def strands(path):
    """The strands of a gen_scenes.py text file: arrays of (x, y, z, radius) rows."""
    out, cur = [], []
    for line in open(path):
        f = line.split()
        if f:
            cur.append([float(x) for x in f])
        elif cur:
            out.append(np.array(cur))
            cur = []
    if cur:
        out.append(np.array(cur))
    return out


def control_points(p):
    """B-spline control points through the strand's ends: the points, plus a phantom point
    mirrored at each end (2 P0 - P1), where the uniform cubic B-spline then starts exactly."""
    return np.vstack([2 * p[0] - p[1], p, 2 * p[-1] - p[-2]])


def sample_bspline(c, per_span):
    """The uniform cubic B-spline of control points `c` at `per_span` points per span
    (and its last point): position and radius, interpolated alike."""
    pts = []
    for i in range(len(c) - 3):
        for k in range(per_span):
            t = k / per_span
            b = np.array([(1 - t) ** 3, 3 * t**3 - 6 * t**2 + 4, -3 * t**3 + 3 * t**2 + 3 * t + 1, t**3]) / 6
            pts.append(b @ c[i : i + 4])
    pts.append((c[-3] + 4 * c[-2] + c[-1]) / 6)
    return np.array(pts)


def write_hair(path, curves):
    """A Cem Yuksel HAIR file: segments, points and thickness (diameter) arrays."""
    n, total = len(curves), sum(len(c) for c in curves)
    hdr = b"HAIR" + struct.pack("<IIIIff3f", n, total, 1 | 2 | 4, 1, 0.0, 0.0, 0.5, 0.5, 0.5)
    hdr += b"B-spline curves".ljust(88, b"\0")
    with open(path, "wb") as f:
        f.write(hdr)
        f.write(np.array([len(c) - 1 for c in curves], dtype="<u2").tobytes())
        f.write(np.concatenate([c[:, :3] for c in curves]).astype("<f4").tobytes())
        f.write(np.concatenate([2 * c[:, 3] for c in curves]).astype("<f4").tobytes())


def block_means(img, b=8):
    h, w = img.shape[0] // b * b, img.shape[1] // b * b
    return img[:h, :w].reshape(h // b, b, w // b, b, -1).mean(axis=(1, 3))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir")
    ap.add_argument("out")
    ap.add_argument("--resolution", type=int, nargs=2, default=[240, 180])
    ap.add_argument("--spp", type=int, default=256)
    ap.add_argument("--depth", type=int, default=8)
    ap.add_argument("--eumelanin", type=float, default=1.3)
    ap.add_argument("--pheomelanin", type=float, default=0.0)
    ap.add_argument("--renders", default="direct,path0,path,mitsuba,mitsuba-seed1")
    a = ap.parse_args()
    renders = a.renders.split(",")
    os.makedirs(a.out, exist_ok=True)
    s = json.load(open(os.path.join(a.dir, "scene.json")))
    cam, (w, h) = s["camera"], a.resolution
    controls = [control_points(p) for p in strands(os.path.join(a.dir, s["hair"][0]["text"]))]
    with open(os.path.join(a.out, "curves.txt"), "w") as f:
        for c in controls:
            f.writelines("%.7f %.7f %.7f %.7f\n" % tuple(x) for x in c)
            f.write("\n")
    write_hair(os.path.join(a.out, "curves.hair"), [sample_bspline(c, 4) for c in controls])
    hair = {"eumelanin": a.eumelanin, "pheomelanin": a.pheomelanin, "beta_m": 0.3, "beta_n": 0.3, "alpha": 2.0,
            "eta": 1.55}
    times, images = {}, {}

    def tress(name, integrator, max_depth):
        toml = os.path.join(a.out, f"{name}.toml")
        lights = ""
        for light in s["lights"]:
            if light["type"] == "distant":
                lights += (f'[[light]]\ntype = "distant"\ndirection = {light["direction_to_light"]}\n'
                           f'irradiance = {light["radiance"]}\n\n')
            else:
                lights += f'[[light]]\ntype = "environment"\nradiance = {light["radiance"]}\n\n'
        material = ", ".join(f"{k} = {v}" for k, v in hair.items())
        with open(toml, "w") as f:
            f.write(f'[camera]\neye = {cam["eye"]}\ntarget = {cam["target"]}\nup = {cam["up"]}\n'
                    f'vfov = {cam["vfov_deg"]}\n\n[render]\nresolution = [{w}, {h}]\nspp = {a.spp}\n'
                    f'integrator = "{integrator}"\nmax_depth = {max_depth}\n'
                    # Unbiased: no path regularization, as Mitsuba's `path`.
                    f'indirect_hair_roughness = 0\n\n{lights}'
                    f'[[mesh]]\nfile = "{os.path.abspath(os.path.join(a.dir, s["meshes"][0]["obj"]))}"\n'
                    f'material = {{ type = "diffuse", color = {s["meshes"][0]["diffuse"]} }}\n\n'
                    f'[[hair]]\nfile = "curves.hair"\nfile_colors = false\n'
                    f'material = {{ type = "physical", {material} }}\n')
        exe = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "target", "release", "tress")
        out = os.path.join(a.out, f"{name}.exr")
        t0 = time.time()
        subprocess.run([exe, "render", toml, "-o", out, "--quiet"], check=True)
        times[name] = time.time() - t0
        images[name] = out

    def mitsuba(name, seed):
        import mitsuba as mi
        mi.set_variant("llvm_ad_rgb")
        scene = {
            "type": "scene",
            "integrator": {"type": "path", "max_depth": a.depth},
            "sensor": {
                "type": "perspective", "fov": cam["vfov_deg"], "fov_axis": "y",
                "to_world": mi.ScalarTransform4f().look_at(origin=cam["eye"], target=cam["target"], up=cam["up"]),
                "sampler": {"type": "independent", "sample_count": a.spp, "seed": seed},
                "film": {"type": "hdrfilm", "width": w, "height": h, "rfilter": {"type": "box"}},
            },
            "torus": {"type": "obj", "filename": os.path.join(a.dir, s["meshes"][0]["obj"]),
                      "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": s["meshes"][0]["diffuse"]}}},
            "hair": {"type": "bsplinecurve", "filename": os.path.join(a.out, "curves.txt"),
                     "bsdf": {"type": "hair", "eumelanin": hair["eumelanin"], "pheomelanin": hair["pheomelanin"],
                              "longitudinal_roughness": hair["beta_m"], "azimuthal_roughness": hair["beta_n"],
                              "scale_tilt": hair["alpha"], "int_ior": hair["eta"]}},
        }
        for i, light in enumerate(s["lights"]):
            if light["type"] == "distant":
                scene[f"light{i}"] = {"type": "directional", "direction": [-x for x in light["direction_to_light"]],
                                      "irradiance": {"type": "rgb", "value": light["radiance"]}}
            else:
                scene[f"light{i}"] = {"type": "constant", "radiance": {"type": "rgb", "value": light["radiance"]}}
        loaded = mi.load_dict(scene)
        t0 = time.time()
        img = mi.render(loaded, spp=a.spp)
        out = os.path.join(a.out, f"{name}.exr")
        mi.Bitmap(img).write(out)
        times[name] = time.time() - t0
        images[name] = out

    jobs = {"direct": lambda: tress("direct", "direct", 0), "path0": lambda: tress("path0", "path", 0),
            "path": lambda: tress("path", "path", a.depth - 2), "mitsuba": lambda: mitsuba("mitsuba", 0),
            "mitsuba-seed1": lambda: mitsuba("mitsuba-seed1", 1)}
    for name in renders:
        jobs[name]()
        print(f"{name}: {times[name]:.1f} s", flush=True)
    import mitsuba as mi
    mi.set_variant("scalar_rgb")
    rgb = {n: block_means(np.array(mi.Bitmap(p))[:, :, :3].astype(np.float64)) for n, p in images.items()}
    for x, y in [("path0", "direct"), ("path", "mitsuba"), ("mitsuba-seed1", "mitsuba")]:
        if x in rgb and y in rgb:
            d = np.abs(rgb[x] - rgb[y]).mean() / rgb[y].mean()
            print(f"diff {x} {y} = {100 * d:.2f} %  (means {rgb[x].mean():.5f} {rgb[y].mean():.5f})")


if __name__ == "__main__":
    sys.exit(main())
