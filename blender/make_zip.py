#!/usr/bin/env python3
"""Builds the Blender add-on zip (Edit > Preferences > Add-ons > Install from Disk):
tress_addon/ with its files, symbolic links replaced by the files they point to.

    python3 blender/make_zip.py [OUTPUT.zip]     # default: blender/tress_addon.zip
"""

import os
import sys
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.join(HERE, "tress_addon")


def make_zip(output: str) -> str:
    tmp = output + ".tmp"
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as z:
        for name in sorted(os.listdir(SOURCE)):
            path = os.path.join(SOURCE, name)
            if name.startswith(".") or name == "__pycache__" or not os.path.isfile(path):
                continue
            z.write(os.path.realpath(path), f"tress_addon/{name}")
    os.replace(tmp, output)
    return output


if __name__ == "__main__":
    print(make_zip(sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "tress_addon.zip")))
