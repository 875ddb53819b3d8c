#!/usr/bin/python3
"""A reference that is not naive (issues 61 and 62): simple scenes generated here (rectangles,
boxes, spheres; point, spot and directional lights; a few metallic-roughness materials) are written
as glTF files, rendered by `manylights render` at 1280x720 in every method with the file's own
camera and lights at animation frame 0, with `--shadows off` and with `--shadows rays`, and
compared with an independent CPU rendering of the same analytic scene (cpu_reference.py: a ray
cast per pixel centre, glTF's BRDF from its appendix B, and with shadows an analytic shadow ray
per pixel and light against the exact shapes).

Each method must hold the accuracy contract against the CPU frame on the 8-bit output at
--exposure 0: at most 1/255 off on at least 99.99 % of the compared pixels. Pixels whose coverage
the rasterizer and the tessellation decide (any pixel whose 3x3 neighbourhood in the CPU frame
holds another surface, another face of a box, or the background: edges, contacts, sphere
silhouettes) are left out and counted. Shadow edges are not left out: where a shadow's edge
crosses the pixel grid (a pixel whose 3x3 neighbourhood in the CPU frame holds both a point that a
light reaches and one that a surface hides from it) a ray that grazes the edge may decide either
way (the renderer's spheres are tessellated and its rays leave the surface from an offset origin),
but so few do that they fit in the contract's 0.01 %; those pixels are counted, with how many of
them are over 1/255, so a failure there shows as such. Where a scene names points that must
be lit (issue 61's quad, a box's top face under a light), each such pixel must be well above its
ambient value in the rendered frame, so a dark surface cannot pass by being dark everywhere. Where
it names floor points in a shadow (behind a box, a sphere), each must render darker than half-way
between the CPU's shadowed and unshadowed values with shadows on, and lighter with them off, so the
shadowed comparison cannot pass by the scene having no shadow.

One line per scene, method and shadow setting: max error in 1/255, share of compared pixels over
1/255 (with shadows, how many of them lie on a shadow edge), PSNR of the 8-bit output over the
compared pixels, the pixels left out and the shadow-edge pixels. On failure the CPU frame, the
rendered frame and a diff go to <work>/failures/ as PNGs, and the exit status is 1.

  check_cpu_reference.py --manylights build-test/manylights --work /tmp/cpu_reference
"""
import argparse
import math
import os
import struct
import subprocess
import sys
import time
import zlib
from typing import NamedTuple

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import analytic_gltf  # noqa: E402
import cpu_reference as ref  # noqa: E402
from cpu_reference import Camera, Light, Material, Rect, Scene, Sphere  # noqa: E402

WIDTH, HEIGHT = 1280, 720
METHODS = ["naive", "forward-plus", "deferred", "visibility"]
SHADOWS = ["off", "rays"]
MAX_ABS_8BIT = 1                  # tests/gpu/gpu_test.h, kMaxAbs8Bit: the accuracy contract
MAX_SHARE_OVER = 1e-4             # at most 0.01 % of the compared pixels more than 1/255 off
LIT_MARGIN_8BIT = 64              # a lit check point: at least this far above its ambient value


def look_at(eye, target, yfov):
    return Camera(position=tuple(eye), rotation=ref.quaternion_looking(np.subtract(target, eye)), yfov=yfov)


# Issue 61's repro, ../shared/repro/quad*.gltf: a 2x2 quad at y = 2 (normal +y, grey dielectric of
# roughness 0.9), a point light of intensity 60 and range 40 at (0, 4, 0), the file's camera.
REPRO_CAMERA = Camera(position=(0.0, 14.0, 9.0), rotation=(-0.4871745, 0.0, 0.0, 0.8733046), yfov=0.9)
GREY_ROUGH = Material(base=(0.8, 0.8, 0.8), metallic=0.0, roughness=0.9)
UNUSED_FLOOR = [(-10.0, 0.0, -10.0), (-10.0, 0.0, 10.0), (10.0, 0.0, 10.0), (10.0, 0.0, -10.0)]


def floor(half, material, y=0.0):
    return Rect((0.0, y, 0.0), (half, 0.0, 0.0), (0.0, 0.0, -half), material)


def repro_quad(name):
    quad = Rect((0.0, 2.0, 0.0), (1.0, 0.0, 0.0), (0.0, 0.0, -1.0), GREY_ROUGH)
    light = Light("point", intensity=60.0, position=(0.0, 4.0, 0.0), range=40.0)
    return Scene(name, REPRO_CAMERA, rects=[quad], lights=[light])


def box_under_light(height, material):
    """Issue 61's second case: a box standing on a large floor, a light above its top face."""
    rects = [floor(10.0, Material(base=(0.6, 0.6, 0.6), roughness=0.8))]
    rects += ref.box_faces((0.0, 1.0, 0.0), (1.0, 1.0, 1.0), material)
    light = Light("point", intensity=60.0, position=(0.0, float(height), 0.0), range=40.0)
    return Scene(f"box_light_at_{height}", look_at((5.0, 7.0, 9.0), (0.0, 1.0, 0.0), 0.8), rects=rects, lights=[light])


def spheres_spot_sun():
    rects = [floor(8.0, Material(base=(0.7, 0.7, 0.7), roughness=0.85))]
    rects += ref.box_faces((4.3, 0.75, -2.2), (0.75, 0.75, 0.75), Material(base=(0.95, 0.93, 0.88), metallic=1.0, roughness=0.55))
    spheres = [Sphere((-2.6, 1.0, 0.0), 1.0, Material(base=(0.8, 0.1, 0.08), roughness=0.3)),
               Sphere((0.0, 1.0, 0.0), 1.0, Material(base=(1.0, 0.77, 0.34), metallic=1.0, roughness=0.45)),
               Sphere((2.6, 1.0, 0.0), 1.0, Material(base=(0.9, 0.9, 0.9), roughness=0.6))]
    lights = [Light("directional", color=(1.0, 0.95, 0.85), intensity=1.2, direction=(0.4, -1.0, -0.3)),
              Light("spot", intensity=150.0, position=(0.0, 7.0, 4.0), direction=(0.0, -7.0, -4.0), range=30.0,
                    inner=0.25, outer=0.45),
              Light("point", color=(0.4, 0.6, 1.0), intensity=25.0, position=(-4.0, 3.0, 3.0), range=14.0),
              Light("point", color=(1.0, 0.6, 0.3), intensity=12.0, position=(4.0, 2.0, 2.5))]  # no range
    return Scene("spheres_spot_sun", look_at((0.0, 4.5, 9.5), (0.0, 0.8, 0.0), 0.75), rects=rects, spheres=spheres,
                 lights=lights)


def grid_of_lights():
    """Boxes and spheres on a floor under 24 small coloured point lights and two spots: lights
    whose ranges end on the surfaces, so the clustered methods cull."""
    rng = np.random.default_rng(61)
    rects = [floor(6.0, Material(base=(0.75, 0.72, 0.68), roughness=0.7))]
    spheres = []
    roughness = [0.25, 0.35, 0.45, 0.55, 0.65, 0.75, 0.85, 0.9, 0.3]
    colours = [(0.9, 0.2, 0.2), (0.2, 0.8, 0.3), (0.3, 0.4, 0.9), (0.9, 0.9, 0.9), (0.95, 0.64, 0.54),
               (0.7, 0.7, 0.2), (0.5, 0.2, 0.7), (0.2, 0.7, 0.7), (0.98, 0.82, 0.76)]
    for k in range(9):
        x, z = 3.0 * (k % 3 - 1), 3.0 * (k // 3 - 1)
        m = Material(base=colours[k], metallic=1.0 if k % 4 == 1 else 0.0, roughness=roughness[k])
        if k % 2:
            rects += ref.box_faces((x, 0.6, z), (0.6, 0.6, 0.6), m)
        else:
            spheres.append(Sphere((x, 0.8, z), 0.8, m))
    lights = []
    while len(lights) < 24:
        p = rng.uniform([-5.5, 0.3, -5.5], [5.5, 2.8, 5.5])
        cx, cz = np.round(p[0] / 3.0) * 3.0, np.round(p[2] / 3.0) * 3.0
        if max(abs(p[0] - cx), abs(p[2] - cz)) < 1.1 and p[1] < 1.9:
            continue                                        # not inside or against a box or sphere
        hue = rng.uniform(0.0, 1.0)
        colour = tuple(0.5 + 0.5 * math.cos(2.0 * math.pi * (hue + o)) for o in (0.0, 1.0 / 3.0, 2.0 / 3.0))
        lights.append(Light("point", color=colour, intensity=float(rng.uniform(3.0, 10.0)), position=tuple(p),
                            range=float(rng.uniform(2.5, 6.0))))
    lights.append(Light("spot", color=(1.0, 0.9, 0.7), intensity=60.0, position=(-3.0, 5.0, 3.0),
                        direction=(0.5, -1.0, -0.5), range=12.0, inner=0.2, outer=0.6))
    lights.append(Light("spot", color=(0.6, 0.8, 1.0), intensity=40.0, position=(4.0, 4.0, -1.0),
                        direction=(-0.6, -1.0, 0.2), range=9.0, inner=0.0, outer=0.4))
    return Scene("grid_of_lights", look_at((0.0, 7.0, 10.0), (0.0, 0.5, 0.3), 0.8), rects=rects, spheres=spheres,
                 lights=lights)


class Case(NamedTuple):
    scene: Scene
    unused: dict        # surface index -> vertices no index uses, before the surface's own
    lit: list           # world points that must render lit
    shadowed: tuple = ()  # floor points a surface hides from a light: dark with shadows on, lit off


def box_shadow(height):
    """The floor point in front of the box (+z) half-way across its shadow under a light at
    (0, height, 0): the shadow ends where the ray over the top edge (x or z = 1, y = 2) lands."""
    return ((0.0, 0.0, 0.5 * (1.0 + height / (height - 2.0))),)


def cases():
    top = [(0.0, 2.0, 0.0)]
    return [
        Case(repro_quad("quad"), {}, top),
        Case(repro_quad("quad_after_unused_vertices"), {0: UNUSED_FLOOR}, top),
        Case(box_under_light(3, Material(base=(0.85, 0.45, 0.25), roughness=0.5)), {}, top, box_shadow(3)),
        Case(box_under_light(4, Material(base=(0.9, 0.9, 0.9), roughness=0.35)), {}, top, box_shadow(4)),
        Case(box_under_light(5, Material(base=(0.3, 0.75, 0.35), roughness=0.7)), {}, top, box_shadow(5)),
        # Beside the red and the white sphere's feet, away from the camera: hidden from every light.
        Case(spheres_spot_sun(), {}, [], ((-2.05, 0.0, 0.09), (2.02, 0.0, -0.1))),
        # Beside the middle right box and behind the near left sphere, at least 3 pixels from every
        # coverage and shadow edge (under 26 lights most of the floor near a shadow is near one).
        Case(grid_of_lights(), {}, [], ((2.32, 0.0, 0.2), (-3.0, 0.0, 3.4))),
    ]


def read_pfm(path):
    with open(path, "rb") as f:
        data = f.read()
    header, pos = [], 0
    while len(header) < 4:                                   # "PF", W, H, scale: whitespace separated
        end = data.index(b"\n", pos)
        header += data[pos:end].split()
        pos = end + 1
    if header[0] != b"PF":
        raise ValueError(f"{path}: not an RGB PFM file")
    width, height, scale = int(header[1]), int(header[2]), float(header[3])
    pixels = np.frombuffer(data, dtype="<f4" if scale < 0 else ">f4", count=width * height * 3, offset=pos)
    return np.flipud(pixels.reshape(height, width, 3)).astype(np.float64)   # PFM: bottom row first


def write_png(path, rgb):
    """An 8-bit RGB PNG (H, W, 3) with zlib alone."""
    rgb = np.ascontiguousarray(np.clip(rgb, 0, 255).astype(np.uint8))
    height, width = rgb.shape[:2]
    raw = b"".join(b"\x00" + rgb[y].tobytes() for y in range(height))

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


def neighbourhood(a):
    """The nine shifted copies of a (H, W) array that put each pixel's 3x3 neighbours on it (the
    border repeated)."""
    padded = np.pad(a, 1, mode="edge")
    return [padded[1 + dy:1 + dy + a.shape[0], 1 + dx:1 + dx + a.shape[1]] for dy in (-1, 0, 1) for dx in (-1, 0, 1)]


def coverage_edges(ids):
    """Pixels whose 3x3 neighbourhood holds another surface id (or the background)."""
    return np.logical_or.reduce([n != ids for n in neighbourhood(ids)])


def shadow_edges(frame):
    """Pixels whose 3x3 neighbourhood holds, for some light, a point the light reaches and a point
    a surface hides from it: where a shadow's edge crosses the pixel grid."""
    edge = np.zeros(frame.ids.shape, dtype=bool)
    for reached, hidden in zip(frame.reached, frame.hidden):
        if hidden.any():
            edge |= np.logical_or.reduce(neighbourhood(reached)) & np.logical_or.reduce(neighbourhood(hidden))
    return edge


def render(manylights, gltf, method, shadows, work):
    stem = os.path.join(work, f"{os.path.splitext(os.path.basename(gltf))[0]}_{method}_shadows_{shadows}")
    cmd = [manylights, "render", "--scene", gltf, "--method", method, "--shadows", shadows, "--size", f"{WIDTH}x{HEIGHT}",
           "--exposure", "0", "--lights", "0", "--out", stem + ".png", "--out-float", stem + ".pfm"]
    result = subprocess.run(cmd, capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)}: exit {result.returncode}\n{result.stdout}{result.stderr}")
    return read_pfm(stem + ".pfm")


def compare(expected8, got8, excluded):
    diff = np.abs(got8.astype(np.int32) - expected8.astype(np.int32)).max(axis=-1)
    compared = ~excluded
    count = int(compared.sum())
    d = diff[compared]
    over = int((d > MAX_ABS_8BIT).sum())
    mse = float(np.mean((got8[compared].astype(np.float64) - expected8[compared]) ** 2)) if count else 0.0
    psnr = math.inf if mse == 0.0 else 10.0 * math.log10(255.0 ** 2 / mse)
    return {"max": int(d.max()) if count else 0, "over": over, "share": over / max(count, 1), "psnr": psnr,
            "diff": diff, "compared": count}


def write_failure_images(work, name, expected8, got8, diff, excluded):
    out = os.path.join(work, "failures")
    os.makedirs(out, exist_ok=True)
    stem = os.path.join(out, name)
    write_png(stem + "_cpu.png", expected8)
    write_png(stem + "_rendered.png", got8)
    # The diff: |error| x 32 in grey, pixels over the contract in red, pixels left out in dark blue.
    vis = np.repeat(np.minimum(diff * 32, 255)[..., None], 3, axis=-1)
    vis[diff > MAX_ABS_8BIT] = (255, 0, 0)
    vis[excluded] = (0, 0, 96)
    write_png(stem + "_diff.png", vis)
    return stem + "_{cpu,rendered,diff}.png"


class Probe(NamedTuple):
    """A world point whose pixel a frame must show lit or shadowed, and the 8-bit values it is held to."""
    point: tuple
    x: int
    y: int
    low: int            # lit: the ambient value; shadowed: the CPU's value with shadows on
    high: int = 0       # shadowed: the CPU's value with shadows off


def probes(scene, points, low8, high8=None):
    out = []
    for point in points:
        x, y = ref.project(scene.camera, point, WIDTH, HEIGHT)
        out.append(Probe(point, x, y, int(low8[y, x].max()), int(high8[y, x].max()) if high8 is not None else 0))
    return out


def check_cpu_frames(case, expected8, ambient8, edges):
    """The scene's own claims, on the CPU frames: its lit points are lit, and its shadowed points
    lie in a shadow (well darker with shadows on), away from every coverage and shadow edge (`edges`)."""
    failures = []
    for shadows, frame8 in expected8.items():
        for p in probes(case.scene, case.lit, ambient8):
            if not frame8[p.y, p.x].max() >= p.low + LIT_MARGIN_8BIT:
                failures.append(f"{case.scene.name}: the CPU reference (shadows {shadows}) is not lit at {p.point} "
                                f"(pixel {p.x},{p.y})")
    for p in probes(case.scene, case.shadowed, expected8["rays"], expected8["off"]):
        if edges[p.y, p.x] or p.high < p.low + LIT_MARGIN_8BIT:
            failures.append(f"{case.scene.name}: the CPU reference has no clear shadow at {p.point} (pixel {p.x},{p.y}: "
                            f"{p.low}/255 with shadows, {p.high}/255 without{', on an edge' if edges[p.y, p.x] else ''})")
    return failures


def check_probes(label, got8, lit, shadowed, shadows):
    """Notes for the line and failures: a lit point well above its ambient value; a shadowed point on
    the CPU's shadowed side of half-way between its two values with shadows on, on the other side off."""
    notes, failures = [], []
    for p in lit:
        value = int(got8[p.y, p.x].max())
        notes.append(f"lit at {p.point}: {value}/255 (ambient {p.low})")
        if value < p.low + LIT_MARGIN_8BIT:
            failures.append(f"{label}: pixel ({p.x},{p.y}) at {p.point} is {value}/255, not lit (ambient alone {p.low}/255)")
    for p in shadowed:
        value, half = int(got8[p.y, p.x].max()), 0.5 * (p.low + p.high)
        notes.append(f"shadow at {p.point}: {value}/255 (cpu {p.low} with, {p.high} without)")
        if (value < half) != (shadows == "rays"):
            failures.append(f"{label}: pixel ({p.x},{p.y}) at {p.point} is {value}/255, "
                            f"{'not in shadow' if shadows == 'rays' else 'shadowed'} (the CPU frame: {p.low}/255 with "
                            f"shadows, {p.high}/255 without)")
    return notes, failures


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--manylights", required=True)
    parser.add_argument("--work", default=os.path.join(os.environ.get("ML_TEST_TMP", "."), "cpu_reference"))
    parser.add_argument("--methods", default=",".join(METHODS))
    parser.add_argument("--shadows", default=",".join(SHADOWS), help="comma-separated --shadows settings to render")
    parser.add_argument("--scenes", default="", help="comma-separated scene names (default: all)")
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    methods = args.methods.split(",")
    chosen = set(filter(None, args.scenes.split(",")))
    failures = []
    start = time.monotonic()
    for case in cases():
        scene = case.scene
        if chosen and scene.name not in chosen:
            continue
        gltf = os.path.join(args.work, scene.name + ".gltf")
        analytic_gltf.write_gltf(scene, gltf, unused_before=case.unused)
        frames = {shadows: ref.shade(scene, WIDTH, HEIGHT, shadows=shadows == "rays") for shadows in SHADOWS}
        expected8 = {shadows: ref.tonemap_8bit(frame.hdr) for shadows, frame in frames.items()}
        ambient8 = ref.tonemap_8bit(ref.shade(Scene(scene.name, scene.camera, scene.rects, scene.spheres, []),
                                              WIDTH, HEIGHT).hdr)
        excluded = coverage_edges(frames["off"].ids)   # a box's faces are rectangles of their own, so its edges count
        edges = shadow_edges(frames["rays"]) & ~excluded
        failures += check_cpu_frames(case, expected8, ambient8, excluded | edges)
        lit = probes(scene, case.lit, ambient8)
        shadowed = probes(scene, case.shadowed, expected8["rays"], expected8["off"])
        for shadows in args.shadows.split(","):
            for method in methods:
                label = f"{scene.name} {method} shadows {shadows}"
                try:
                    got8 = ref.tonemap_8bit(render(args.manylights, gltf, method, shadows, args.work))
                except (RuntimeError, OSError, ValueError) as e:
                    print(f"{scene.name:28s} {method:13s} {shadows:4s} FAIL: {e}", flush=True)
                    failures.append(f"{label}: {e}")
                    continue
                r = compare(expected8[shadows], got8, excluded)
                notes, probe_failures = check_probes(label, got8, lit, shadowed, shadows)
                holds = r["share"] <= MAX_SHARE_OVER and not probe_failures
                on_edges = f", {int((r['diff'][edges] > MAX_ABS_8BIT).sum())} on shadow edges" if shadows == "rays" else ""
                print(f"{scene.name:28s} {method:13s} {shadows:4s} max {r['max']:3d}/255  over 1/255 "
                      f"{100.0 * r['share']:.4f} % ({r['over']} px{on_edges})  PSNR {r['psnr']:6.1f} dB  "
                      f"excluded {int(excluded.sum())} px" + (f", shadow edges {int(edges.sum())} px" if shadows == "rays" else "")
                      + (f"  {'; '.join(notes)}" if notes else "") + ("" if holds else "  FAIL"), flush=True)
                failures += probe_failures
                if r["share"] > MAX_SHARE_OVER:
                    worst = np.unravel_index(np.argmax(np.where(excluded, -1, r["diff"])), r["diff"].shape)
                    wy, wx = int(worst[0]), int(worst[1])
                    failures.append(f"{label}: {100.0 * r['share']:.4f} % of {r['compared']} compared pixels over "
                                    f"1/255 (max {r['max']}/255; worst at pixel ({wx},{wy}): expected "
                                    f"{expected8[shadows][wy, wx].tolist()}, got {got8[wy, wx].tolist()})")
                if not holds:
                    where = write_failure_images(args.work, label.replace(" ", "_"), expected8[shadows], got8,
                                                 r["diff"], excluded)
                    failures.append(f"  images: {where}")
    print(f"{time.monotonic() - start:.0f} s")
    if failures:
        print("FAILED:\n" + "\n".join(failures))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
