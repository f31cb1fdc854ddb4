#!/usr/bin/env python3
"""Writes the assets of the groom showcase (scenes/groom_*.toml) under scenes/groom/:

- head.ply: a procedural head (binary PLY with normals and UVs): an egg-shaped cranium
  with a narrower jaw and chin, brow, eye sockets, nose and ears, by a radius over the
  sphere of directions; latitude-longitude UVs with the poles at the crown and under the
  chin (u = 0 at the back).
- neck.ply, shoulders.ply: a capsule and a flattened ellipsoid for the hair to rest on.
- head_color_brown.png, head_color_blonde.png, head_color_red.png: the head's colour by
  UV: skin, and the scalp tinted towards the hair's colour wherever hair grows, with a
  soft hairline, so no bright skin shows through the hair.
- guides.hair: the guide curves of the hair system (Cem Yuksel's HAIR format): roots
  spread by area over the scalp (denser inside the hairline than at it), a side parting,
  combed away from it over the head and let fall under gravity, sliding over the head,
  neck and shoulders (collision with the same shapes), with a gentle per-guide wave.

Units are decimetres: the head is 1.5 wide and 2.3 tall; the hair falls to the shoulders.
Deterministic (fixed seed); needs only numpy. Run from the repository root:
    python3 scripts/make_groom.py
"""
import os
import struct
import zlib

import numpy as np

OUT = "scenes/groom"
RNG = np.random.default_rng(20)

# The head: radii of the base ellipsoid (x across, y up, z forward: the face looks along +z).
HEAD = np.array([0.76, 1.12, 0.96])
HEAD_CENTER = np.array([0.0, 0.0, 0.0])
NECK = (np.array([0.0, -0.55, -0.12]), np.array([0.0, -2.0, -0.08]), 0.43)  # capsule: ends, radius
SHOULDERS = (np.array([0.0, -2.45, -0.12]), np.array([2.0, 0.62, 0.82]))  # ellipsoid: centre, radii
PART_X = 0.2  # the parting runs from the front hairline to the crown at x = 0.2


def bump(d, center, width, amplitude):
    """A smooth bump over directions: amplitude * exp(-(angle / width)^2)."""
    c = np.asarray(center, dtype=float)
    c = c / np.linalg.norm(c)
    cos = np.clip(d @ c, -1.0, 1.0)
    return amplitude * np.exp(-(np.arccos(cos) / width) ** 2)


def head_surface(d):
    """The head's surface point along unit directions d (shape (..., 3)) from its centre:
    the head is star-shaped, its radius a function of the direction."""
    d = np.asarray(d, dtype=float)
    x, y, z = d[..., 0], d[..., 1], d[..., 2]
    below = np.clip(-y, 0.0, 1.0)
    # The jaw narrows below the cheekbones, the chin comes forward, the skull bulges at the back.
    ax = HEAD[0] * (1.0 - 0.3 * below**1.5)
    az = HEAD[2] * np.where(z < 0, 1.0 - 0.12 * below + 0.06 * np.clip(y + 0.5, 0, 1), 1.0 + 0.1 * below**2)
    r = 1.0 / np.sqrt((x / ax) ** 2 + (y / HEAD[1]) ** 2 + (z / az) ** 2)
    r = r + (
        bump(d, [0.0, -0.12, 1.0], 0.1, 0.16)  # nose
        + bump(d, [0.0, 0.2, 1.0], 0.3, 0.035)  # brow
        - bump(d, [0.34, 0.08, 0.94], 0.11, 0.06)  # eye sockets
        - bump(d, [-0.34, 0.08, 0.94], 0.11, 0.06)
        + bump(d, [0.0, -0.62, 0.78], 0.13, 0.04)  # chin
        + bump(d, [1.0, -0.1, -0.05], 0.12, 0.1)  # ears
        + bump(d, [-1.0, -0.1, -0.05], 0.12, 0.1)
    )
    return HEAD_CENTER + d * r[..., None]


def hairline(d):
    """Signed distance-like measure of how far inside the scalp a direction lies (> 0 is
    scalp): above a hairline high at the forehead, around the ears and low at the nape."""
    az = np.arctan2(d[..., 0], d[..., 2])  # 0 at the face, +-pi at the back
    h = -0.07 + 0.5 * np.cos(az)
    h += 0.16 * np.exp(-(((np.abs(az) - 1.65) / 0.32) ** 2))  # around the ears
    h -= 0.06 * np.exp(-((az / 0.5) ** 2))  # a slight widow's peak
    return d[..., 1] - h


def sphere_grid(nu, nv):
    """Directions and UVs of a latitude-longitude grid (pole at +y), u = 0 at the back."""
    u = np.linspace(0.0, 1.0, nu + 1)
    v = np.linspace(0.0, 1.0, nv + 1)
    uu, vv = np.meshgrid(u, v)
    theta, phi = np.pi * vv, 2.0 * np.pi * uu
    d = np.stack([-np.sin(theta) * np.sin(phi), np.cos(theta), -np.sin(theta) * np.cos(phi)], axis=-1)
    return d, uu, vv


def grid_mesh(points, uv):
    """Triangles of a (rows+1) x (cols+1) grid of points; normals from the faces."""
    rows, cols = points.shape[0] - 1, points.shape[1] - 1
    idx = np.arange((rows + 1) * (cols + 1)).reshape(rows + 1, cols + 1)
    a, b, c, d = idx[:-1, :-1], idx[1:, :-1], idx[1:, 1:], idx[:-1, 1:]
    tris = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)])
    pos = points.reshape(-1, 3)
    # Wind the triangles to face outwards (away from the grid's centroid).
    face = np.cross(pos[tris[:, 1]] - pos[tris[:, 0]], pos[tris[:, 2]] - pos[tris[:, 0]])
    if np.sum(face * (pos[tris[:, 0]] - pos.mean(axis=0))) < 0:
        tris = tris[:, [0, 2, 1]]
    # Drop the triangles collapsed at the poles.
    area = np.linalg.norm(np.cross(pos[tris[:, 1]] - pos[tris[:, 0]], pos[tris[:, 2]] - pos[tris[:, 0]]), axis=1)
    tris = tris[area > 1e-9]
    normals = np.zeros_like(pos)
    face = np.cross(pos[tris[:, 1]] - pos[tris[:, 0]], pos[tris[:, 2]] - pos[tris[:, 0]])
    for k in range(3):
        np.add.at(normals, tris[:, k], face)
    # Vertices on the seam and the poles share positions: sum their normals.
    key = np.round(pos, 6)
    _, inverse = np.unique(key, axis=0, return_inverse=True)
    summed = np.zeros((inverse.max() + 1, 3))
    np.add.at(summed, inverse.ravel(), normals)
    normals = summed[inverse.ravel()]
    normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-12)
    return pos, normals, uv.reshape(-1, 2), tris


def write_ply(path, pos, normals, uv, tris):
    header = (
        "ply\nformat binary_little_endian 1.0\n"
        f"element vertex {len(pos)}\nproperty float x\nproperty float y\nproperty float z\n"
        "property float nx\nproperty float ny\nproperty float nz\nproperty float u\nproperty float v\n"
        f"element face {len(tris)}\nproperty list uchar int vertex_indices\nend_header\n"
    )
    verts = np.concatenate([pos, normals, uv], axis=1).astype("<f4")
    faces = np.zeros(len(tris), dtype=[("n", "u1"), ("i", "<i4", 3)])
    faces["n"] = 3
    faces["i"] = tris
    with open(path, "wb") as f:
        f.write(header.encode())
        f.write(verts.tobytes())
        f.write(faces.tobytes())


def head_mesh():
    d, uu, vv = sphere_grid(112, 84)
    pts = head_surface(d)
    # OBJ/PLY convention: v runs up the image; the crown (v = 0 here) is the image top.
    uv = np.stack([uu, 1.0 - vv], axis=-1)
    return grid_mesh(pts, uv)


def neck_mesh():
    """A capsule's side from inside the head to inside the shoulders: a latitude-longitude
    grid whose upper half is moved to one end and lower half to the other."""
    (a, b, r) = NECK
    d, uu, vv = sphere_grid(48, 24)
    t = np.where(d[..., 1] > 0, 0.0, 1.0)[..., None]
    return grid_mesh(a + (b - a) * t + d * r, np.stack([uu, 1 - vv], -1))


def shoulders_mesh():
    c, radii = SHOULDERS
    d, uu, vv = sphere_grid(72, 36)
    return grid_mesh(c + d * radii, np.stack([uu, 1 - vv], -1))


def smoothstep(e0, e1, x):
    t = np.clip((x - e0) / (e1 - e0), 0.0, 1.0)
    return t * t * (3 - 2 * t)


def write_png(path, rgb8):
    h, w, _ = rgb8.shape
    raw = b"".join(b"\0" + rgb8[y].tobytes() for y in range(h))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


SCALP = {
    "brown": np.array([0.09, 0.055, 0.035]),
    "blonde": np.array([0.42, 0.3, 0.2]),
    "red": np.array([0.3, 0.12, 0.06]),
}


def head_texture(scalp, width=512, height=256):
    """Skin with a little variation; the scalp tinted `scalp`, blended at the hairline."""
    u = (np.arange(width) + 0.5) / width
    v = (np.arange(height) + 0.5) / height
    uu, vv = np.meshgrid(u, v)
    theta, phi = np.pi * vv, 2.0 * np.pi * uu  # image row 0 is v = 1: the crown
    d = np.stack([-np.sin(theta) * np.sin(phi), np.cos(theta), -np.sin(theta) * np.cos(phi)], axis=-1)
    skin = np.array([0.62, 0.42, 0.33])
    # Cheeks and lips a little redder.
    blush = bump(d, [0.45, -0.25, 0.85], 0.25, 1.0)[..., None] + bump(d, [-0.45, -0.25, 0.85], 0.25, 1.0)[..., None]
    lips = bump(d, [0.0, -0.42, 0.9], 0.09, 1.0)[..., None]
    color = skin * (1 - 0.15 * blush) + np.array([0.62, 0.3, 0.27]) * 0.15 * blush
    color = color * (1 - 0.5 * lips) + np.array([0.5, 0.22, 0.2]) * 0.5 * lips
    noise = np.random.default_rng(3).normal(0.0, 0.015, size=color.shape[:2])[..., None]
    color = np.clip(color * (1 + noise), 0, 1)
    w = smoothstep(-0.04, 0.1, hairline(d))[..., None]
    color = color * (1 - w) + scalp * w
    srgb = np.where(color <= 0.0031308, 12.92 * color, 1.055 * color ** (1 / 2.4) - 0.055)
    return (np.clip(srgb, 0, 1) * 255 + 0.5).astype(np.uint8)


def inside_push(p, offset):
    """Pushes points p (n, 3) out of the head, neck and shoulders by at least `offset`;
    returns the new points and the outward normals where they were pushed (zero elsewhere)."""
    normals = np.zeros_like(p)
    offset = offset[:, None]
    # Head: star-shaped around its centre.
    rel = p - HEAD_CENTER
    dist = np.linalg.norm(rel, axis=1, keepdims=True)
    dirs = rel / np.maximum(dist, 1e-9)
    surf = head_surface(dirs)
    rs = np.linalg.norm(surf - HEAD_CENTER, axis=1, keepdims=True)
    inside = (dist < rs + offset)[:, 0]
    p[inside] = HEAD_CENTER + dirs[inside] * (rs[inside] + offset[inside])
    normals[inside] = dirs[inside]
    # Neck capsule.
    a, b, r = NECK
    ab = b - a
    t = np.clip(((p - a) @ ab) / (ab @ ab), 0, 1)[:, None]
    closest = a + ab * t
    rel = p - closest
    dist = np.linalg.norm(rel, axis=1, keepdims=True)
    inside = (dist < r + offset)[:, 0]
    dirs = rel / np.maximum(dist, 1e-9)
    p[inside] = closest[inside] + dirs[inside] * (r + offset[inside])
    normals[inside] = dirs[inside]
    # Shoulders: an ellipsoid, pushed out along its scaled radius.
    c, radii = SHOULDERS
    q = (p - c) / (radii + offset)
    dist = np.linalg.norm(q, axis=1, keepdims=True)
    inside = (dist < 1.0)[:, 0]
    p[inside] = c + (q[inside] / dist[inside]) * (radii + offset[inside])
    n = (p - c) / radii**2
    normals[inside] = n[inside] / np.linalg.norm(n[inside], axis=1, keepdims=True)
    return p, normals


def sample_roots(count):
    """Roots by area over the scalp: directions drawn uniformly on the sphere, weighted by
    the surface's area stretch and by a density that fades out over the hairline."""
    roots, dirs = [], []
    while sum(len(r) for r in roots) < count:
        d = RNG.normal(size=(count * 4, 3))
        d /= np.linalg.norm(d, axis=1, keepdims=True)
        p = head_surface(d)
        stretch = (np.linalg.norm(p, axis=1) / 1.25) ** 2  # area grows as r^2 (roughly)
        density = smoothstep(0.0, 0.12, hairline(d)) * np.clip(stretch, 0, 1)
        # A bare line along the parting: fewer roots within 0.025 of it.
        part = (np.abs(p[:, 0] - PART_X) < 0.025) & (p[:, 2] > -0.35)
        density *= np.where(part, 0.15, 1.0)
        keep = RNG.random(len(d)) < density
        roots.append(p[keep])
        dirs.append(d[keep])
    return np.concatenate(roots)[:count], np.concatenate(dirs)[:count]


def comb_direction(p, n):
    """The direction the hair is combed at root points p with normals n: away from the side
    parting at the front and top, backwards and down behind the crown."""
    side = np.sign(p[:, 0] - PART_X)[:, None] * np.array([1.0, 0.0, 0.0])
    back = np.array([0.0, -0.6, -1.0])
    # Behind the crown the hair goes back; in front of it, sideways; blended over a band.
    w = smoothstep(-0.55, 0.05, p[:, 2])[:, None]
    dirn = side * w + back * (1 - w) + np.array([0.0, 0.0, -0.35]) * w
    dirn = dirn - n * np.sum(dirn * n, axis=1, keepdims=True)
    return dirn / np.maximum(np.linalg.norm(dirn, axis=1, keepdims=True), 1e-9)


def grow_guides(count=2400, points=24):
    roots, dirs = sample_roots(count)
    normals = np.array(dirs)  # the head is star-shaped: close enough to the surface normal
    length = RNG.uniform(2.6, 3.2, size=count)
    length *= 1.0 - 0.25 * smoothstep(0.25, -0.5, roots[:, 1])  # shorter at the nape
    steps = 96
    h = length / steps
    # Each guide rests on the hair beneath it: an offset from the body that varies per
    # guide gives the hair volume.
    offset = RNG.uniform(0.012, 0.07, size=count)
    d = comb_direction(roots, normals) * 0.8 + normals * 0.6
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    p = roots + normals * 0.004
    path = [p.copy()]
    gravity = np.array([0.0, -1.0, 0.0])
    wave_phase = RNG.uniform(0, 2 * np.pi, size=count)
    wave_axis = np.cross(d, gravity)
    wave_axis /= np.maximum(np.linalg.norm(wave_axis, axis=1, keepdims=True), 1e-9)
    for k in range(steps):
        s = (k + 1) / steps
        # Gravity takes over from the comb along the hair.
        d = d + gravity[None, :] * (0.06 + 0.2 * s) + comb_direction(p, normals) * 0.04 * (1 - s)
        d /= np.linalg.norm(d, axis=1, keepdims=True)
        step = d * h[:, None]
        # A gentle wave across the fall, growing towards the tips.
        wave = wave_axis * (0.05 * s * np.cos(wave_phase + 2 * np.pi * 2.2 * s * length / 3.0))[:, None]
        q = p + step
        q, pushed = inside_push(q + wave * h[:, None] * 3, offset * smoothstep(0.0, 0.08, s) + 0.004)
        # Sliding: the direction loses its component into the surface.
        into = np.sum(d * pushed, axis=1, keepdims=True)
        d = d - pushed * np.minimum(into, 0.0)
        d /= np.maximum(np.linalg.norm(d, axis=1, keepdims=True), 1e-9)
        p = q
        path.append(p.copy())
    path = np.stack(path, axis=1)  # (count, steps + 1, 3)
    # Resample to `points` points evenly along each guide.
    out = np.zeros((count, points, 3))
    for i in range(count):
        seg = np.linalg.norm(np.diff(path[i], axis=0), axis=1)
        arc = np.concatenate([[0.0], np.cumsum(seg)])
        t = np.linspace(0.0, arc[-1], points)
        for c in range(3):
            out[i, :, c] = np.interp(t, arc, path[i, :, c])
    return out


def write_hair(path, strands):
    count, points, _ = strands.shape
    info = b"tress groom guides (scripts/make_groom.py)".ljust(88, b"\0")
    header = b"HAIR" + struct.pack("<IIIIff3f", count, count * points, 0x2, points - 1, 0.01, 1.0, 0.5, 0.5, 0.5) + info
    assert len(header) == 128
    with open(path, "wb") as f:
        f.write(header)
        f.write(strands.astype("<f4").tobytes())


def main():
    os.makedirs(OUT, exist_ok=True)
    write_ply(os.path.join(OUT, "head.ply"), *head_mesh())
    write_ply(os.path.join(OUT, "neck.ply"), *neck_mesh())
    write_ply(os.path.join(OUT, "shoulders.ply"), *shoulders_mesh())
    for name, scalp in SCALP.items():
        write_png(os.path.join(OUT, f"head_color_{name}.png"), head_texture(scalp))
    guides = grow_guides()
    write_hair(os.path.join(OUT, "guides.hair"), guides)
    print(f"{OUT}: head, body, head colour, {len(guides)} guides")


if __name__ == "__main__":
    main()
