#!/usr/bin/python3
"""Issue 65's independent check of KHR_materials_ior, KHR_materials_specular,
KHR_materials_unlit, KHR_materials_clearcoat, KHR_materials_sheen and KHR_materials_anisotropy: their
formulas in numpy from the specifications (material_extensions.py), held to

- the shader's CPU mirror (renderer/reference/shading_reference.cpp, run through
  ml_shading_mirror) on every material below, each under a sun at random directions and at
  grazing ones (light and view a few degrees above the surface, where Schlick's term is mostly
  F90, so an F90 that is not the specular weight shows), at most MIRROR_TOLERANCE relative apart;
  the coated materials' coat normal tilted off the surface's in some cases, so that a lobe or a
  Fresnel taken from the wrong normal shows; the anisotropic materials' geometric normal (the one
  the lobe's bitangent is made from) tilted off the shading normal in every other case, their
  tangents turned about it, their maps' directions and rotations various;
- the frame `manylights render` draws in every method (as check_cpu_reference.py does GGX's):
  strips of those materials on a floor seen at grazing angles, lit by a low sun from behind them,
  the float output (before the tonemap) at most PIXEL_TOLERANCE relative apart on every pixel
  away from a strip's edge; the unlit strip shows its base colour.

The sheen's directional albedo E is integrated over the hemisphere here; the renderer takes Conty
Estevez and Kulla's fit of it. The check prints how far the fit is from the integral, and holds the
sheen materials to the integral within what that error can move a pixel (sheen_allowance), and to
the same formulas with the fit's E at MIRROR_TOLERANCE / PIXEL_TOLERANCE: everything but E exactly.

It also verifies that where metallic is 0 or 1 the specification's diffuse weight and the
renderer's convention (appendix B's, material_extensions.brdf_times_cos) give the same numbers
exactly, and reports how far apart they are on the half metal.

  check_material_extensions.py --manylights build-test/manylights --mirror build-test/tests/ml_shading_mirror --work /tmp/mx
"""
import argparse
import math
import os
import sys
from typing import NamedTuple

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import analytic_gltf  # noqa: E402
import check_cpu_reference as cpu_check  # noqa: E402
import cpu_reference as ref  # noqa: E402
import material_extensions as mx  # noqa: E402
from shading_mirror_io import run_mirror  # noqa: E402

MIRROR_TOLERANCE = 1e-4   # relative, float32 (the mirror) against float64
PIXEL_TOLERANCE = 1e-3    # relative: the rasterizer's interpolated positions at grazing view
AMBIENT = 0.03            # Renderer convention: a glTF file's ambient fill (cpu_reference.AMBIENT)
GRAZING_Q5 = 0.5          # a grazing case's (1 - |V.H|)^5 is at least this: F is mostly F90


class Mat(NamedTuple):
    """A material's glTF factors: pbrMetallicRoughness and the three extensions."""
    name: str
    base: tuple
    metallic: float
    roughness: float
    ior: float = 1.5
    specular: float = 1.0
    specular_color: tuple = (1.0, 1.0, 1.0)
    unlit: bool = False
    clearcoat: float = 0.0
    clearcoat_roughness: float = 0.0
    sheen_color: tuple = (0.0, 0.0, 0.0)
    sheen_roughness: float = 0.0
    anisotropy: float = 0.0
    anisotropy_rotation: float = 0.0
    anisotropy_direction: tuple = (1.0, 0.0)   # a map's RG in [-1, 1] (the mirror's input; no map in gltf())

    def gltf(self):
        if self.unlit:
            ext = {"KHR_materials_unlit": {}}
        else:
            ext = {"KHR_materials_ior": {"ior": self.ior},
                   "KHR_materials_specular": {"specularFactor": self.specular,
                                              "specularColorFactor": list(self.specular_color)}}
            if self.clearcoat > 0.0:
                ext["KHR_materials_clearcoat"] = {"clearcoatFactor": self.clearcoat,
                                                  "clearcoatRoughnessFactor": self.clearcoat_roughness}
            if max(self.sheen_color) > 0.0:
                ext["KHR_materials_sheen"] = {"sheenColorFactor": list(self.sheen_color),
                                              "sheenRoughnessFactor": self.sheen_roughness}
            if self.anisotropy > 0.0:
                ext["KHR_materials_anisotropy"] = {"anisotropyStrength": self.anisotropy,
                                                   "anisotropyRotation": self.anisotropy_rotation}
        return ref.Material(base=self.base, metallic=self.metallic, roughness=self.roughness, extensions=ext)


MATERIALS = [
    Mat("defaults", (0.8, 0.3, 0.2), 0.0, 0.4),
    Mat("weight_half", (0.5, 0.6, 0.7), 0.0, 0.3, specular=0.5),
    Mat("coloured_f0", (0.3, 0.6, 0.2), 0.0, 0.5, ior=2.4, specular=0.8, specular_color=(1.0, 0.4, 0.1)),
    Mat("ior0_clamped", (0.7, 0.7, 0.7), 0.0, 0.25, ior=0.0, specular=0.6, specular_color=(0.5, 1.0, 2.0)),
    Mat("ior1_no_specular", (0.2, 0.4, 0.9), 0.0, 0.6, ior=1.0),
    Mat("metal", (0.9, 0.6, 0.3), 1.0, 0.35, ior=1.33, specular=0.3, specular_color=(0.2, 0.5, 1.0)),
    Mat("half_metal", (0.6, 0.4, 0.8), 0.5, 0.45, ior=1.7, specular=0.7, specular_color=(0.9, 1.0, 0.6)),
    Mat("unlit", (0.9, 0.5, 0.25), 0.0, 0.5, ior=2.0, specular=0.2, unlit=True),
    Mat("coat_smooth", (0.7, 0.1, 0.1), 0.0, 0.5, clearcoat=1.0, clearcoat_roughness=0.15),
    Mat("coat_rough_half", (0.2, 0.3, 0.8), 0.0, 0.3, clearcoat=0.5, clearcoat_roughness=0.55),
    Mat("coat_on_metal", (0.9, 0.7, 0.2), 1.0, 0.6, ior=1.8, specular=0.7, clearcoat=0.8, clearcoat_roughness=0.2),
    Mat("sheen_rough", (0.2, 0.3, 0.6), 0.0, 0.5, sheen_color=(0.9, 0.8, 0.7), sheen_roughness=0.8),
    Mat("sheen_smooth", (0.5, 0.5, 0.5), 0.0, 0.7, sheen_color=(1.0, 0.2, 0.2), sheen_roughness=0.3),
    Mat("sheen_coated", (0.3, 0.6, 0.3), 0.0, 0.4, clearcoat=1.0, clearcoat_roughness=0.2, sheen_color=(0.7, 0.7, 0.7),
        sheen_roughness=0.5),
]
# KHR_materials_anisotropy: strips of their own (the floor has room for no more), and the mirror's cases.
ANISOTROPIC = [
    Mat("aniso_0.6_turned", (0.8, 0.6, 0.4), 0.0, 0.3, anisotropy=0.6, anisotropy_rotation=0.7),
    Mat("aniso_full_metal", (0.9, 0.8, 0.6), 1.0, 0.25, anisotropy=1.0, anisotropy_rotation=-1.2),
    Mat("aniso_rough_mapped", (0.4, 0.5, 0.7), 0.3, 0.6, anisotropy=0.35, anisotropy_rotation=2.5,
        anisotropy_direction=(0.55, -0.7)),
    Mat("aniso_coat_sheen", (0.5, 0.3, 0.3), 0.0, 0.2, clearcoat=0.7, clearcoat_roughness=0.3, sheen_color=(0.4, 0.4, 0.5),
        sheen_roughness=0.5, anisotropy=0.8, anisotropy_rotation=1.57),
]
COATED = [m.name for m in MATERIALS + ANISOTROPIC if m.clearcoat > 0.0]
SHEENED = [m.name for m in MATERIALS + ANISOTROPIC if max(m.sheen_color) > 0.0]
SHEEN_SURVEY_ROUGHNESS = (0.07, 0.15, 0.3, 0.5, 0.75, 1.0)
SUN_COLOR = (1.5, 1.4, 1.3)


def factor_arrays(mats):
    """Per-point factor arrays, as material_extensions' functions take them."""
    def col(f, dtype=float):
        return np.array([f(m) for m in mats], dtype=dtype)
    return dict(base=col(lambda m: m.base), metallic=col(lambda m: m.metallic), roughness=col(lambda m: m.roughness),
                ior=col(lambda m: m.ior), specular=col(lambda m: m.specular),
                specular_color=col(lambda m: m.specular_color), unlit=col(lambda m: m.unlit, bool),
                clearcoat=col(lambda m: m.clearcoat), clearcoat_roughness=col(lambda m: m.clearcoat_roughness),
                sheen_color=col(lambda m: m.sheen_color), sheen_roughness=col(lambda m: m.sheen_roughness))


def anisotropy_of(mats, ng, tangent):
    """(strength, T, B) for material_extensions.radiance: the specification's directions from the
    geometric normals ng and tangents (N, 4)."""
    strength = np.array([m.anisotropy for m in mats], np.float32).astype(float)
    rotation = np.array([m.anisotropy_rotation for m in mats], np.float32).astype(float)
    direction = np.array([m.anisotropy_direction for m in mats], np.float32).astype(float)
    t, b = mx.anisotropy_directions(ng, tangent, rotation, direction)
    return strength, t, b


def sheen_fit_error(mu, roughness):
    """|E_fit - E_integral| at each cosine and roughness."""
    return np.abs(mx.sheen_albedo_fit(mu, roughness) - mx.SHEEN_ALBEDO(mu, roughness))


def sheen_allowance(n, v, l, sun_color, f, anisotropy=None):
    """How far the fit's E error at a case's own N.V and N.L can move each channel (N, 3): E enters
    the albedo scaling as max3(c) E (the material's light: the larger of the two cosines' errors;
    the ambient fill: N.V's), and the ambient's reflection as c E(N.V)."""
    sheen = f["sheen_color"].max(axis=-1) > 0.0
    err_v, err_l = np.zeros(len(n)), np.zeros(len(n))
    err_v[sheen] = sheen_fit_error(np.abs(ref.dot(n, v))[sheen], f["sheen_roughness"][sheen])
    err_l[sheen] = sheen_fit_error(np.clip(ref.dot(n, l), 0.0, 1.0)[sheen], f["sheen_roughness"][sheen])
    material = np.asarray(sun_color) * mx.brdf_times_cos(n, v, l, f["base"], f["metallic"], f["roughness"], f["ior"],
                                                         f["specular"], f["specular_color"], anisotropy=anisotropy)
    fill = mx.ambient_fill(AMBIENT, f["base"], f["metallic"], f["ior"], f["specular"], f["specular_color"])
    m = f["sheen_color"].max(axis=-1, keepdims=True)
    return m * (np.maximum(err_v, err_l)[:, None] * np.abs(material) + err_v[:, None] * fill) + \
        AMBIENT * f["sheen_color"] * err_v[:, None]


def report_sheen_fit():
    """The fit against the integral over the survey's roughnesses and N.V."""
    mu = mx.SheenAlbedoTable.MU
    worst = (0.0, 0.0, 0.0)
    usual = 0.0
    for r in SHEEN_SURVEY_ROUGHNESS:
        err = sheen_fit_error(mu, np.full(mu.shape, r))
        k = int(err.argmax())
        if err[k] > worst[0]:
            worst = (err[k], r, mu[k])
        if r >= 0.3:
            usual = max(usual, err[mu >= 0.1].max())
    print(f"sheen: the fit's E against the integral: max |error| {worst[0]:.3f} at roughness {worst[1]}, N.V {worst[2]:.3f}; "
          f"{usual:.3f} at roughness >= 0.3 and N.V >= 0.1; the integral's largest E "
          f"{max(mx.SHEEN_ALBEDO(mu, np.full(mu.shape, r)).max() for r in SHEEN_SURVEY_ROUGHNESS):.3f} (above 1: the "
          f"specification's fitted visibility gains energy at grazing N.V and low roughness)")
    print("sheen: E integral at roughness " + ", ".join(
        f"{r}: N.V 1 {mx.SHEEN_ALBEDO(1.0, r):.3f} (fit {mx.sheen_albedo_fit(1.0, r):.3f})" for r in (0.3, 0.5, 1.0)))


def directions(rng):
    """(normal, view, light) triples: random ones (the light anywhere, so some are below the
    horizon) and grazing ones, light and view a few degrees above the surface on opposite sides."""
    cases = []
    for _ in range(48):
        n = ref.normalize(rng.normal(size=3))
        v = ref.normalize(rng.normal(size=3))
        cases.append((n, v if np.dot(v, n) > 0.05 else -v, ref.normalize(rng.normal(size=3))))
    n = ref.normalize([0.2, 1.0, -0.1])
    t = ref.normalize(np.cross(n, [0.0, 0.0, 1.0]))
    b = np.cross(n, t)
    for view_deg, light_deg, side in [(2, 3, 0.0), (5, 1, 0.1), (1, 8, -0.2), (8, 6, 0.05), (3, 3, 0.3)]:
        ev, el = math.radians(view_deg), math.radians(light_deg)
        v = math.sin(ev) * n + math.cos(ev) * t
        l = ref.normalize(math.sin(el) * n - math.cos(el) * t + side * math.sin(el) * b)
        cases.append((n, v, l))
    return cases


def relative(got, expected):
    return np.abs(got - expected) / np.maximum(np.abs(expected), 1e-3)


def check_mirror(mirror, failures):
    """numpy against the CPU mirror on every material and direction triple."""
    rng = np.random.default_rng(65)
    trip = directions(rng)
    every = MATERIALS + ANISOTROPIC
    mats = [m for m in every for _ in trip]
    n, v, l = (np.array([t[k] for _ in every for t in trip], np.float32).astype(float) for k in range(3))
    q5 = ref.schlick_weight(v, l)
    grazing = np.array([k >= 48 for _ in every for k in range(len(trip))])
    if not (q5[grazing] >= GRAZING_Q5).all():
        failures.append(f"mirror: a grazing case has (1 - |V.H|)^5 {q5[grazing].min():.3f} < {GRAZING_Q5}")
    f = factor_arrays(mats)
    f32 = {k: a.astype(np.float32).astype(float) if a.dtype != bool else a for k, a in f.items()}
    # Every other case's coat normal tilted off the surface's (a coat normal map's work).
    tilt = np.array([k % 2 == 1 for _ in every for k in range(len(trip))])
    coat_n = np.where(tilt[:, None], ref.normalize(n + 0.35 * ref.normalize(np.cross(n, v + 0.3))), n)
    coat_n = coat_n.astype(np.float32).astype(float)
    # The anisotropic frame: the geometric normal tilted off the shading one in every other case (a
    # normal map's work), a tangent across it turned by the case, its bitangent's sign alternating.
    ng = np.where(tilt[:, None], ref.normalize(n - 0.3 * ref.normalize(np.cross(n, l + 0.2))), n)
    ng = ng.astype(np.float32).astype(float)
    seed = ref.normalize(np.cross(ng, ref.normalize(rng.normal(size=(len(mats), 3)))))
    tangent = np.concatenate([seed, np.where(np.arange(len(mats)) % 4 < 2, 1.0, -1.0)[:, None]], axis=-1)
    tangent = tangent.astype(np.float32).astype(float)
    # The tangent as the renderer takes it: made orthogonal to ng (float32 left it a hair off).
    tangent_orth = np.concatenate([ref.normalize(tangent[:, :3] - ng * ref.dot(ng, tangent[:, :3])[:, None]), tangent[:, 3:]], axis=-1)
    anisotropy = anisotropy_of(mats, ng, tangent_orth)
    eye = 3.0 * v                                     # the point at the origin, seen from 3 units along v
    rows = [list(eye[i]) + [0.0, 0.0, 0.0] + list(n[i]) + list(f32["base"][i]) +
            [f32["metallic"][i], f32["roughness"][i], f32["ior"][i], f32["specular"][i]] +
            list(f32["specular_color"][i]) + [int(f["unlit"][i]), f32["clearcoat"][i], f32["clearcoat_roughness"][i]] +
            list(coat_n[i]) + list(f32["sheen_color"][i]) + [f32["sheen_roughness"][i], AMBIENT] + list(-l[i]) +
            list(SUN_COLOR) + [mats[i].anisotropy, mats[i].anisotropy_rotation] + list(tangent[i]) + list(ng[i]) +
            list(mats[i].anisotropy_direction)
            for i in range(len(mats))]
    got = run_mirror(mirror, rows)
    eye32 = eye.astype(np.float32).astype(float)      # what the mirror reads, and so sees
    v32 = ref.normalize(eye32)
    expected = mx.radiance(n, v32, l, SUN_COLOR, AMBIENT, clearcoat_normal=coat_n, anisotropy=anisotropy, **f32)
    # The sheen's E by the fit: every other formula to MIRROR_TOLERANCE. By the integral: within sheen_allowance.
    fitted = mx.radiance(n, v32, l, SUN_COLOR, AMBIENT, clearcoat_normal=coat_n, sheen_albedo=mx.sheen_albedo_fit,
                         anisotropy=anisotropy, **f32)
    allowance = sheen_allowance(n, v32, l, SUN_COLOR, f32, anisotropy)
    rel = np.maximum(relative(got, fitted), relative(got, expected) - allowance / np.maximum(np.abs(expected), 1e-3)).max(axis=-1)
    for name in dict.fromkeys(m.name for m in mats):
        sel = np.array([m.name == name for m in mats])
        worst = int(np.flatnonzero(sel)[np.argmax(rel[sel])])
        print(f"mirror {name:18s} max rel {rel[sel].max():.2e} (grazing {rel[sel & grazing].max():.2e})"
              + ("  FAIL" if rel[sel].max() > MIRROR_TOLERANCE else ""), flush=True)
        if rel[sel].max() > MIRROR_TOLERANCE:
            failures.append(f"mirror {name}: relative {rel[worst]:.2e} at n {n[worst]}, v {v[worst]}, l {l[worst]}: "
                            f"numpy {expected[worst]}, mirror {got[worst]}")
    print(f"mirror: numpy against the CPU mirror, max relative difference {rel.max():.2e} over {len(rel)} cases")
    anisotropic = np.array([m.anisotropy > 0.0 for m in mats])
    isotropic = mx.radiance(n, v32, l, SUN_COLOR, AMBIENT, clearcoat_normal=coat_n, sheen_albedo=mx.sheen_albedo_fit, **f32)
    print(f"mirror: anisotropic cases {int(anisotropic.sum())} ({int((anisotropic & tilt).sum())} with Ng off N): max rel "
          f"{relative(got, fitted)[anisotropic].max():.2e}; the stretched lobe moves them by up to "
          f"{np.abs(isotropic - fitted)[anisotropic].max():.3f} (linear radiance) from the isotropic one")
    sheens = np.isin([m.name for m in mats], SHEENED)
    print(f"mirror: sheen cases {int(sheens.sum())}: with the fit's E max rel {relative(got, fitted)[sheens].max():.2e}; "
          f"with the integral's {relative(got, expected)[sheens].max():.2e}, away from grazing "
          f"{relative(got, expected)[sheens & ~grazing].max():.2e} (allowed by the fit's error: up to "
          f"{(allowance / np.maximum(np.abs(expected), 1e-3))[sheens].max():.2e})")

    # The specification's diffuse weight against the renderer's convention: the same at metallic 0 and 1.
    coats = np.isin([m.name for m in mats], COATED)
    print(f"mirror: coated cases {int(coats.sum())}, {int((coats & tilt).sum())} with the coat's normal tilted; coat share "
          f"{mx.clearcoat_share(v, f['clearcoat'], coat_n)[coats].min():.3f} to {mx.clearcoat_share(v, f['clearcoat'], coat_n)[coats].max():.3f}")
    args = (n, v, l, f["base"], f["metallic"], f["roughness"], f["ior"], f["specular"], f["specular_color"])
    spec, conv = mx.brdf_times_cos(*args, convention=False), mx.brdf_times_cos(*args, convention=True)
    ends = np.isin(f["metallic"], (0.0, 1.0))
    if not np.array_equal(spec[ends], conv[ends]):
        failures.append("the specification's diffuse weight and the renderer's convention differ at metallic 0 or 1")
    mid = ~ends
    print(f"convention: the BRDF identical to the specification's at metallic 0 and 1 ({int(ends.sum())} cases); at "
          f"metallic 0.5 up to {relative(conv[mid], spec[mid]).max():.1%} off it (the diffuse's Fresnel weight)")


def strips_scene(mats, name):
    """One floor strip per material along x, seen from a low camera, a low sun shining from behind them."""
    rects = [ref.Rect((0.7 * (k - (len(mats) - 1) / 2.0), 0.0, -2.0), (0.34, 0.0, 0.0), (0.0, 0.0, -5.0), m.gltf())
             for k, m in enumerate(mats)]
    sun = ref.Light("directional", color=(1.0, 1.0, 1.0), intensity=0.6, direction=(0.15, -0.12, 1.0))
    return ref.Scene(name, cpu_check.look_at((0.0, 0.7, 9.0), (0.0, 0.0, -3.0), 0.55),
                     rects=rects, lights=[sun])


def expected_frame(scene, mats, width, height):
    origin, dirs = ref.primary_rays(scene.camera, width, height)
    _, ids, points, normals = ref.cast(scene, origin, dirs)
    hit = ids >= 0
    sun = scene.lights[0]
    l = np.broadcast_to(-ref.normalize(sun.direction), (int(hit.sum()), 3))
    sun_color = np.asarray(sun.color) * sun.intensity
    hit_mats = [mats[i]._replace(anisotropy_direction=(1.0, 0.0)) for i in ids[hit]]   # the file has no maps
    f = factor_arrays(hit_mats)
    # The strips' TANGENT (analytic_gltf): each rectangle's t1, +x, bitangent sign 1.
    tangent = np.tile([1.0, 0.0, 0.0, 1.0], (len(hit_mats), 1))
    anisotropy = anisotropy_of(hit_mats, normals[hit], tangent)
    frame, fitted, allowance = (np.zeros((height, width, 3)) for _ in range(3))
    frame[hit] = mx.radiance(normals[hit], -dirs[hit], l, sun_color, AMBIENT, clearcoat_normal=normals[hit],
                             anisotropy=anisotropy, **f)
    fitted[hit] = mx.radiance(normals[hit], -dirs[hit], l, sun_color, AMBIENT, clearcoat_normal=normals[hit],
                              sheen_albedo=mx.sheen_albedo_fit, anisotropy=anisotropy, **f)
    allowance[hit] = sheen_allowance(normals[hit], -dirs[hit], l, sun_color, f, anisotropy)
    return frame, fitted, allowance, ids


def check_pixels(manylights, work, failures):
    for mats, name in ((MATERIALS, "material_extensions"), (ANISOTROPIC, "material_anisotropy")):
        check_strips(manylights, work, failures, mats, name)


def check_strips(manylights, work, failures, mats, name):
    scene = strips_scene(mats, name)
    gltf = os.path.join(work, scene.name + ".gltf")
    analytic_gltf.write_gltf(scene, gltf)
    expected, fitted, allowance, ids = expected_frame(scene, mats, cpu_check.WIDTH, cpu_check.HEIGHT)
    compared = (ids >= 0) & ~cpu_check.coverage_edges(ids)
    for k, m in enumerate(mats):
        if (compared & (ids == k)).sum() < 2000:
            failures.append(f"pixels: the {m.name} strip covers only {(compared & (ids == k)).sum()} compared pixels")
    for method in cpu_check.METHODS:
        got = cpu_check.render(manylights, gltf, method, "off", work)
        # As the mirror's: the fit's E to PIXEL_TOLERANCE, the integral's within the fit's error.
        rel = np.maximum(relative(got, fitted), relative(got, expected) - allowance / np.maximum(np.abs(expected), 1e-3)).max(axis=-1)
        per = {m.name: rel[compared & (ids == k)].max() for k, m in enumerate(mats)}
        worst = max(per, key=per.get)
        d8 = np.abs(ref.tonemap_8bit(got).astype(int) - ref.tonemap_8bit(expected)).max(axis=-1)[compared].max()
        bad = per[worst] > PIXEL_TOLERANCE
        sheens = compared & np.isin(ids, [k for k, m in enumerate(mats) if m.name in SHEENED])
        print(f"pixels {name} {method:13s} max rel {per[worst]:.2e} ({worst}), 8-bit max {d8}/255, "
              f"{int(compared.sum())} px; sheen strips with the fit's E {relative(got, fitted)[sheens].max():.2e}, "
              f"the integral's {relative(got, expected)[sheens].max():.2e}" + ("  FAIL" if bad else ""), flush=True)
        if bad:
            failures.append(f"pixels {method}: relative {per[worst]:.2e} on {worst} " +
                            ", ".join(f"{k} {v:.1e}" for k, v in per.items()))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--manylights", required=True)
    parser.add_argument("--mirror", required=True, help="ml_shading_mirror")
    parser.add_argument("--work", default="material_extensions_reference")
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    failures = []
    report_sheen_fit()
    check_mirror(args.mirror, failures)
    check_pixels(args.manylights, args.work, failures)
    if failures:
        print("FAILED:\n" + "\n".join(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
