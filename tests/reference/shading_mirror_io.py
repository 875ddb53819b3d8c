"""Talking to ml_shading_mirror (tests/reference/shading_mirror_cli.cpp) from the numpy checks:
one case a line in, one "r g b" line out, and the inputs as the mirror reads them (float32)."""
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
