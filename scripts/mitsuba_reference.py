#!/usr/bin/env python3
"""Renders a reference scene directory of scripts/gen_scenes.py with Mitsuba 3 (the
LLVM variant, direct lighting), for an end-to-end time beside `tress render DIR`.

Usage: python3 scripts/mitsuba_reference.py DIR OUT.exr [--spp N] [--seed N] [--sampler NAME]
                                              [--emitter-samples N] [--bsdf-samples N]
Needs `pip install mitsuba`. Prints the render time in seconds (scene loading excluded).
The defaults are the end-to-end comparison's (Mitsuba's `independent` sampler, its `direct`
integrator's one emitter and one BSDF sample per hit); the options serve the equal-noise
comparison of scripts/compare-noise.sh (e.g. `--sampler multijitter --seed 7`).
"""
import argparse, json, os, time

import mitsuba as mi


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir")
    ap.add_argument("out")
    ap.add_argument("--spp", type=int, default=None)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--sampler", default="independent")
    ap.add_argument("--emitter-samples", type=int, default=1)
    ap.add_argument("--bsdf-samples", type=int, default=1)
    a = ap.parse_args()
    mi.set_variant("llvm_ad_rgb")
    s = json.load(open(os.path.join(a.dir, "scene.json")))
    film, cam = s["film"], s["camera"]
    spp = a.spp or film["spp"]
    scene = {
        "type": "scene",
        "integrator": {"type": "direct", "emitter_samples": a.emitter_samples, "bsdf_samples": a.bsdf_samples},
        "sensor": {
            "type": "perspective",
            "fov": cam["vfov_deg"],
            "fov_axis": "y",
            "to_world": mi.ScalarTransform4f().look_at(origin=cam["eye"], target=cam["target"], up=cam["up"]),
            "sampler": {"type": a.sampler, "sample_count": spp, "seed": a.seed},
            "film": {"type": "hdrfilm", "width": film["width"], "height": film["height"],
                     "rfilter": {"type": "box"}},
        },
    }
    for i, light in enumerate(s["lights"]):
        if light["type"] == "distant":
            scene[f"light{i}"] = {"type": "directional", "direction": [-x for x in light["direction_to_light"]],
                                  "irradiance": {"type": "rgb", "value": light["radiance"]}}
        else:
            scene[f"light{i}"] = {"type": "constant", "radiance": {"type": "rgb", "value": light["radiance"]}}
    for i, m in enumerate(s["meshes"]):
        scene[f"mesh{i}"] = {"type": "obj", "filename": os.path.join(a.dir, m["obj"]),
                             "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": m["diffuse"]}}}
    for i, h in enumerate(s["hair"]):
        scene[f"hair{i}"] = {"type": "linearcurve", "filename": os.path.join(a.dir, h["text"]),
                             "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": h["diffuse"]}}}
    loaded = mi.load_dict(scene)
    mi.render(loaded, spp=1)  # warm-up: JIT compilation of the kernels
    t0 = time.time()
    img = mi.render(loaded, spp=spp)
    mi.Bitmap(img).write(a.out)
    print(f"mitsuba render {time.time() - t0:.3f} s ({film['width']}x{film['height']}, {spp} spp)")


if __name__ == "__main__":
    main()
