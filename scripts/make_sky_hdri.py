#!/usr/bin/env python3
"""Writes scenes/sky.exr: a procedural clear sky with a sun disc, as an equirectangular
(latitude-longitude) OpenEXR map of 512x256 half-float RGB pixels (ZIP compressed), for
`[[light]] type = "environment"`.

The sky fades from a deep blue zenith to a pale, hazy horizon, brightens in a glow around
the sun, and meets a dark warm-grey ground at the horizon. The sun is a disc 3 degrees
across (six times the real one, for softer shadows), 35 degrees above the horizon, behind
the left shoulder of a camera on +z looking along -z. Its radiance is chosen so that the
sun gives about three times the irradiance the sky gives a horizontal surface, as on a
clear day. Pixels are averaged over 4x4 sub-samples, so the disc's edge is smooth.

Directions follow tress's map frame (docs/scene-format.md): +y up, the image's centre
column looking along -z and the column a quarter of the width to its right along +x.

Deterministic; needs only numpy. Run from the repository root:
    python3 scripts/make_sky_hdri.py [output.exr] [width]
"""
import struct
import sys
import zlib

import numpy as np

SUN_ELEVATION = np.radians(35.0)
SUN_AZIMUTH = np.radians(-40.0)  # from +z towards +x
SUN_RADIUS = np.radians(1.5)
SUN_COLOR = np.array([1.0, 0.93, 0.82])
ZENITH = np.array([0.16, 0.30, 0.66])
HORIZON = np.array([0.78, 0.84, 0.92])
GROUND = np.array([0.15, 0.13, 0.11])
SUN_TO_SKY = 3.0  # sun irradiance over sky irradiance on a horizontal surface


def directions(width, height, sub):
    """Unit directions of sub x sub sample points in every pixel, shape (h, w, sub*sub, 3)."""
    offsets = (np.arange(sub) + 0.5) / sub
    u = (np.arange(width)[None, :, None, None] + offsets[None, None, None, :]) / width
    v = (np.arange(height)[:, None, None, None] + offsets[None, None, :, None]) / height
    u, v = np.broadcast_arrays(u, v)
    theta, phi = np.pi * v, 2.0 * np.pi * (u + 0.25)
    d = np.stack([np.sin(theta) * np.cos(phi), np.cos(theta), np.sin(theta) * np.sin(phi)], axis=-1)
    return d.reshape(height, width, sub * sub, 3)


def sun_direction():
    e, a = SUN_ELEVATION, SUN_AZIMUTH
    return np.array([np.cos(e) * np.sin(a), np.sin(e), np.cos(e) * np.cos(a)])


def sky(d):
    """Radiance of the sky and ground (without the sun disc) along directions d."""
    y = d[..., 1:2]
    up = np.clip(y, 0.0, 1.0)
    blue = ZENITH + (HORIZON - ZENITH) * (1.0 - up) ** 4
    cos_sun = np.clip(d @ sun_direction(), -1.0, 1.0)[..., None]
    angle = np.arccos(cos_sun)
    # A forward-scattering glow around the sun and a faint Rayleigh-like brightening.
    glow = 1.6 * np.exp(-angle / 0.10) + 0.35 * np.exp(-angle / 0.6)
    above = blue * (1.0 + 0.2 * cos_sun**2) + glow * np.array([1.0, 0.9, 0.75])
    below = GROUND * (0.55 + 0.45 * (1.0 + np.clip(y, -1.0, 0.0)))
    # A smooth step over a degree at the horizon instead of a hard edge.
    t = np.clip(y / 0.02 + 0.5, 0.0, 1.0)
    return above * t + below * (1.0 - t)


def render(width, height, sub=4):
    d = directions(width, height, sub)
    radiance = sky(d)
    # Sky irradiance on a horizontal surface, to scale the sun against.
    theta = np.pi * (np.arange(height) + 0.5) / height
    solid = (2.0 * np.pi / width) * (np.pi / height) * np.sin(theta)
    mean_sky = radiance.mean(axis=2)
    cos_up = np.clip(np.cos(theta), 0.0, None)
    e_sky = float((luminance(mean_sky) * (solid * cos_up)[:, None]).sum())
    cone = 2.0 * np.pi * (1.0 - np.cos(SUN_RADIUS))
    sun_radiance = SUN_TO_SKY * e_sky / (cone * luminance(SUN_COLOR))
    in_sun = (d @ sun_direction()) >= np.cos(SUN_RADIUS)
    radiance = radiance + in_sun[..., None] * (sun_radiance * SUN_COLOR)
    return radiance.mean(axis=2), e_sky, sun_radiance


def luminance(c):
    return c[..., 0] * 0.2126 + c[..., 1] * 0.7152 + c[..., 2] * 0.0722


def attribute(name, kind, value):
    return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value


def write_exr(path, rgb):
    """A single-part scanline OpenEXR file of half-float B, G, R channels, ZIP compressed
    (blocks of 16 lines; the OpenEXR file layout and its ZIP predictor)."""
    height, width, _ = rgb.shape
    half = rgb.astype(np.float16)
    channels = b"".join(name + b"\0" + struct.pack("<iB3xii", 1, 0, 1, 1) for name in (b"B", b"G", b"R")) + b"\0"
    box = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    header = b"".join(
        [
            struct.pack("<ii", 20000630, 2),
            attribute("channels", "chlist", channels),
            attribute("compression", "compression", b"\x03"),
            attribute("dataWindow", "box2i", box),
            attribute("displayWindow", "box2i", box),
            attribute("lineOrder", "lineOrder", b"\x00"),
            attribute("pixelAspectRatio", "float", struct.pack("<f", 1.0)),
            attribute("screenWindowCenter", "v2f", struct.pack("<ff", 0.0, 0.0)),
            attribute("screenWindowWidth", "float", struct.pack("<f", 1.0)),
            b"\0",
        ]
    )
    blocks = []
    for y0 in range(0, height, 16):
        lines = half[y0 : y0 + 16]
        # Each line holds its channels one after another, in the header's (sorted) order.
        raw = b"".join(lines[i, :, c].astype("<f2").tobytes() for i in range(lines.shape[0]) for c in (2, 1, 0))
        data = np.frombuffer(raw, dtype=np.uint8)
        # Bytes split into even and odd halves, then delta-coded.
        split = np.concatenate([data[0::2], data[1::2]])
        delta = split.astype(np.int16)
        delta[1:] = (split[1:].astype(np.int16) - split[:-1].astype(np.int16) + 128) & 0xFF
        packed = zlib.compress(delta.astype(np.uint8).tobytes(), 9)
        if len(packed) >= len(raw):
            packed = raw
        blocks.append(struct.pack("<ii", y0, len(packed)) + packed)
    table_start = len(header)
    offsets, at = [], table_start + 8 * len(blocks)
    for b in blocks:
        offsets.append(at)
        at += len(b)
    with open(path, "wb") as f:
        f.write(header)
        f.write(struct.pack(f"<{len(offsets)}Q", *offsets))
        for b in blocks:
            f.write(b)


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "scenes/sky.exr"
    width = int(sys.argv[2]) if len(sys.argv) > 2 else 512
    rgb, e_sky, sun = render(width, width // 2)
    write_exr(path, rgb)
    print(f"{path}: {width}x{width // 2}, sky irradiance {e_sky:.3f}, sun radiance {sun:.1f}")


if __name__ == "__main__":
    main()
