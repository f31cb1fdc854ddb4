"""Reading the EXR images the ``tress`` command writes (32-bit float channels, scanlines,
no compression or ZIP), for the engine's command-line path: Blender's own image reader
does not take tress's channel set. Layout from the OpenEXR file format description."""

from __future__ import annotations

import struct
import zlib

import numpy as np

_LINES_PER_CHUNK = {0: 1, 2: 1, 3: 16}
_FLOAT = 2


def _header(data: bytes):
    if data[:4] != b"\x76\x2f\x31\x01":
        raise ValueError("not an OpenEXR file")
    if struct.unpack_from("<I", data, 4)[0] & 0x1E00:
        raise ValueError("only single-part scanline EXR files are read")
    at, attrs = 8, {}
    while data[at] != 0:
        end = data.index(b"\0", at)
        name = data[at:end].decode()
        tend = data.index(b"\0", end + 1)
        kind = data[end + 1:tend].decode()
        (size,) = struct.unpack_from("<i", data, tend + 1)
        attrs[name] = (kind, data[tend + 5:tend + 5 + size])
        at = tend + 5 + size
    return attrs, at + 1


def _channels(value: bytes):
    out, at = [], 0
    while value[at] != 0:
        end = value.index(b"\0", at)
        name = value[at:end].decode()
        (pixel_type,) = struct.unpack_from("<i", value, end + 1)
        out.append((name, pixel_type))
        at = end + 1 + 16
    return out


def _unzip(raw: bytes) -> bytes:
    d = np.frombuffer(zlib.decompress(raw), dtype=np.uint8).astype(np.int64)
    # Undo the predictor, t[0] = d[0] and t[i] = t[i-1] + d[i] - 128 (mod 256), then the
    # split of the bytes into two halves.
    t = ((np.cumsum(d - 128) + 128) % 256).astype(np.uint8)
    half = (len(t) + 1) // 2
    out = np.empty_like(t)
    out[0::2] = t[:half]
    out[1::2] = t[half:]
    return out.tobytes()


def read_channels(path: str) -> dict[str, np.ndarray]:
    """Every channel of a tress EXR by name, each float32 (height, width), top row first."""
    with open(path, "rb") as f:
        data = f.read()
    attrs, at = _header(data)
    compression = attrs["compression"][1][0]
    if compression not in _LINES_PER_CHUNK:
        raise ValueError(f"{path}: EXR compression {compression} is not read (tress writes none or ZIP)")
    x0, y0, x1, y1 = struct.unpack("<iiii", attrs["dataWindow"][1])
    width, height = x1 - x0 + 1, y1 - y0 + 1
    channels = _channels(attrs["channels"][1])
    if any(t != _FLOAT for _, t in channels):
        raise ValueError(f"{path}: only 32-bit float channels are read")
    lines = _LINES_PER_CHUNK[compression]
    chunks = (height + lines - 1) // lines
    offsets = struct.unpack_from(f"<{chunks}Q", data, at)
    names = [n for n, _ in channels]
    image = np.zeros((height, width, len(names)), dtype=np.float32)
    for offset in offsets:
        y, size = struct.unpack_from("<ii", data, offset)
        block = data[offset + 8:offset + 8 + size]
        n = min(lines, y1 + 1 - y)
        if compression != 0 and size < n * width * 4 * len(names):
            block = _unzip(block)
        values = np.frombuffer(block, dtype="<f4").reshape(n, len(names), width)
        image[y - y0:y - y0 + n] = values.transpose(0, 2, 1)
    return {name: image[..., i] for i, name in enumerate(names)}
