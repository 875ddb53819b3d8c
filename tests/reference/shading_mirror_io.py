"""Talking to ml_shading_mirror (tests/reference/shading_mirror_cli.cpp) from the numpy checks:
one case a line in, one "r g b" line out, and the inputs as the mirror reads them (float32)."""
import argparse
import subprocess

import numpy as np


def run_mirror(mirror, rows):
    """The mirror's linear radiance for each row of input columns, (N, 3)."""
    text = "\n".join(" ".join(f"{x:.9g}" for x in row) for row in rows) + "\n"
    out = subprocess.run([mirror], input=text, capture_output=True, text=True, check=True).stdout
    return np.array([[float(x) for x in line.split()] for line in out.splitlines()])


def as_float32(a):
    """What the mirror reads, and so sees: the float32 of every input, back in float64."""
    return np.asarray(a, np.float32).astype(float)


def sunlit_row(eye, position, normal, base, metallic, roughness, ior, ambient, sun_direction, sun_color):
    """The mirror's leading columns for a material with glTF's default specular colour and weight,
    no unlit, coat, sheen or anisotropy, under one sun travelling along sun_direction."""
    return [*eye, *position, *normal, *base, metallic, roughness, ior, 1.0, 1.0, 1.0, 1.0, 0,
            0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, ambient, *sun_direction, *sun_color,
            0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0]


def mirror_arguments(description):
    """The numpy checks' command line: the mirror's path and the number of random cases."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--mirror", required=True, help="ml_shading_mirror")
    parser.add_argument("--cases", type=int, default=2000)
    return parser.parse_args()


def dot(a, b):
    return np.sum(a * b, axis=-1)


def normalize(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def random_views(rng, count):
    """count surface points facing +z: the normals, and views and light directions drawn over the
    hemisphere above the surface (never grazing it)."""
    n = np.tile([0.0, 0.0, 1.0], (count, 1))
    v = normalize(rng.normal(size=(count, 3)))
    v[:, 2] = np.abs(v[:, 2]) + 0.05
    v = normalize(v)
    l = normalize(rng.normal(size=(count, 3)))
    l[:, 2] = np.abs(l[:, 2]) + 0.02
    return n, v, normalize(l)
