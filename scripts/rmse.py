#!/usr/bin/env python3
"""Prints the RMS difference of each image's colour (R, G, B; EXR) from a reference image's.

Usage: python3 scripts/rmse.py REF.exr IMAGE.exr...
One line per image: `IMAGE rmse=X`. Reads EXR through Mitsuba's `Bitmap` (`pip install
mitsuba numpy`), which the end-to-end comparisons need anyway.
"""
import sys

import mitsuba as mi
import numpy as np


def rgb(path):
    return np.array(mi.Bitmap(path))[:, :, :3].astype(np.float64)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    mi.set_variant("scalar_rgb")
    ref = rgb(sys.argv[1])
    for path in sys.argv[2:]:
        img = rgb(path)
        if img.shape != ref.shape:
            sys.exit(f"{path}: {img.shape[1]}x{img.shape[0]} pixels, the reference has {ref.shape[1]}x{ref.shape[0]}")
        print(f"{path} rmse={np.sqrt(np.mean((img - ref) ** 2)):.5f}")


if __name__ == "__main__":
    main()
