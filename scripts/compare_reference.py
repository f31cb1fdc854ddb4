#!/usr/bin/env python3
"""How far a tress render is from another renderer's reference image: the mean absolute
difference of the 8-bit sRGB values (0 to 255, lower is closer), with both images' means.
The figures of docs/interop.md's real-file comparisons (Arnold's reference renders of its
USD test suite, Cycles renders of Blender scenes) are made with it.

Usage:
  python3 scripts/compare_reference.py REFERENCE OURS [SIDE_BY_SIDE.png]

REFERENCE is a TIFF (8- or 16-bit, or floating point, read as linear and encoded to sRGB)
or a PNG/JPEG; OURS is tress's PNG, resized to the reference's size when they differ.
Alpha is dropped. With a third path, the two are written side by side (reference left).
Needs `pip install numpy pillow tifffile imagecodecs` (imagecodecs reads compressed TIFFs).
"""
import sys

import numpy as np
from PIL import Image


def srgb8(linear):
    """Linear values to 8-bit sRGB code values (the IEC 61966-2-1 transfer function)."""
    c = np.clip(linear, 0.0, 1.0)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * c ** (1 / 2.4) - 0.055) * 255.0


def read_reference(path):
    if path.lower().endswith((".tif", ".tiff")):
        import tifffile

        img = tifffile.imread(path)
        if img.ndim == 2:
            img = img[..., None].repeat(3, -1)
        img = img[..., :3]
        if np.issubdtype(img.dtype, np.floating):
            return srgb8(img.astype(np.float64))
        return img.astype(np.float64) * (255.0 / np.iinfo(img.dtype).max)
    return np.asarray(Image.open(path).convert("RGB")).astype(np.float64)


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    ref = read_reference(sys.argv[1])
    h, w = ref.shape[:2]
    ours = Image.open(sys.argv[2]).convert("RGB")
    if ours.size != (w, h):
        ours = ours.resize((w, h), Image.BILINEAR)
    ours = np.asarray(ours).astype(np.float64)
    mae = np.abs(ref - ours).mean()
    print(f"mae={mae:.1f} ref_mean={ref.mean():.1f} ours_mean={ours.mean():.1f}")
    if len(sys.argv) == 4:
        side = np.concatenate([ref, ours], 1)
        Image.fromarray(np.clip(side, 0, 255).astype(np.uint8)).save(sys.argv[3])


if __name__ == "__main__":
    main()
