"""Helpers of the tests of the Python package, the Blender add-on and the Maya exporter:
the command line, small meshes and strand sets as NumPy arrays."""

import os
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]


def _find_cli():
    for candidate in (os.environ.get("TRESS_BIN"), REPO / "target" / "release" / "tress", shutil.which("tress")):
        if candidate and Path(candidate).is_file() and os.access(candidate, os.X_OK):
            return str(candidate)
    return None


def cli_or_skip():
    """Path of the `tress` command (TRESS_BIN, the repository's release build, or PATH);
    skips the test when there is none."""
    cli = _find_cli()
    if cli is None:
        pytest.skip("the tress command is not built: run `cargo build --release` or set TRESS_BIN")
    return cli


def run_cli(cli, *args, check=True):
    """Runs the command line; returns the completed process (stderr as text)."""
    done = subprocess.run([cli, *map(str, args)], capture_output=True, text=True, timeout=600)
    if check and done.returncode != 0:
        raise AssertionError(f"tress {' '.join(map(str, args))} failed: {done.stderr}")
    return done


def uv_sphere(radius=1.0, rings=12, segments=16):
    """A UV sphere as (points, triangles, normals, uvs) arrays."""
    points, normals, uvs = [], [], []
    for i in range(rings + 1):
        theta = np.pi * i / rings
        for j in range(segments + 1):
            phi = 2 * np.pi * j / segments
            n = [np.sin(theta) * np.cos(phi), np.cos(theta), np.sin(theta) * np.sin(phi)]
            normals.append(n)
            points.append([radius * c for c in n])
            uvs.append([j / segments, 1 - i / rings])
    tris = []
    row = segments + 1
    for i in range(rings):
        for j in range(segments):
            a, b = i * row + j, i * row + j + 1
            c, d = a + row, b + row
            if i > 0:
                tris.append([a, b, c])
            if i < rings - 1:
                tris.append([b, d, c])
    return (np.array(points, np.float32), np.array(tris, np.uint32), np.array(normals, np.float32),
            np.array(uvs, np.float32))


def strands_on_sphere(count=60, points_per_strand=5, length=0.4, seed=1):
    """Strands growing out of a unit sphere: (points, radius, offsets, colors)."""
    rng = np.random.default_rng(seed)
    roots = rng.normal(size=(count, 3))
    roots /= np.linalg.norm(roots, axis=1, keepdims=True)
    t = np.linspace(0.0, 1.0, points_per_strand, dtype=np.float64)
    bend = np.array([0.0, -0.3, 0.0])
    pts = roots[:, None, :] * (1.0 + length * t[None, :, None]) + bend * (t[None, :, None] ** 2) * length
    points = pts.reshape(-1, 3).astype(np.float32)
    radius = np.tile(np.linspace(0.02, 0.005, points_per_strand), count).astype(np.float32)
    offsets = (np.arange(count + 1) * points_per_strand).astype(np.uint32)
    colors = rng.uniform(0.1, 0.9, size=(count * points_per_strand, 3)).astype(np.float32)
    return points, radius, offsets, colors
