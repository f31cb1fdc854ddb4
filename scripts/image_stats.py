#!/usr/bin/env python3
"""Noise, bias and outliers of tress's EXR renders (the figures of docs/validation.md's
path regularization section). Reads EXR with the `OpenEXR` package (`pip install OpenEXR
numpy`).

Usage:
  python3 scripts/image_stats.py noise A.exr B.exr
      two renders with different seeds: their mean, the RMS noise of one (the RMS
      difference over sqrt 2) and that over the mean (the relative noise)
  python3 scripts/image_stats.py bias REF.exr IMAGE.exr
      the image's mean against the reference's, and the mean absolute difference of
      8 x 8-pixel block means, both in percent of the reference's mean
  python3 scripts/image_stats.py outliers THRESHOLD IMAGE.exr...
      per image, how many pixels have a colour channel above THRESHOLD (at 1 spp with
      the box filter, a pixel is one camera sample)
"""
import sys

import numpy as np
import OpenEXR


def rgb(path):
    with OpenEXR.File(path) as f:
        channels = f.channels()
        for name in ("RGB", "RGBA"):
            if name in channels:
                return channels[name].pixels[..., :3].astype(np.float64)
        return np.stack([channels[c].pixels for c in "RGB"], -1).astype(np.float64)


def blocks(img, b=8):
    h, w = img.shape[0] // b * b, img.shape[1] // b * b
    return img[:h, :w].reshape(h // b, b, w // b, b, 3).mean((1, 3))


def main():
    if len(sys.argv) < 4 or sys.argv[1] not in ("noise", "bias", "outliers"):
        sys.exit(__doc__)
    command, args = sys.argv[1], sys.argv[2:]
    if command == "noise":
        a, b = rgb(args[0]), rgb(args[1])
        mean = 0.5 * (a.mean() + b.mean())
        noise = np.sqrt(np.mean((a - b) ** 2) / 2)
        print(f"mean={mean:.5f} noise={noise:.5f} relative={noise / mean:.4f}")
    elif command == "bias":
        ref, img = rgb(args[0]), rgb(args[1])
        diff = 100 * (img.mean() - ref.mean()) / ref.mean()
        block = 100 * np.abs(blocks(img) - blocks(ref)).mean() / blocks(ref).mean()
        print(f"mean={img.mean():.5f} reference={ref.mean():.5f} mean_difference={diff:+.2f}% blocks={block:.2f}%")
    else:
        threshold = float(args[0])
        for path in args[1:]:
            print(f"{path} above={(rgb(path).max(-1) > threshold).sum()}")


if __name__ == "__main__":
    main()
