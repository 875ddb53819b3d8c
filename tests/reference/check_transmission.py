"""KHR_materials_transmission and KHR_materials_volume written from their specifications and held to the CPU mirror.

The extension replaces the dielectric's diffuse by a specular BTDF in proportion to the
transmission t (KHR_materials_transmission, "dielectric_brdf = fresnel_mix(ior,
mix(diffuse_brdf, specular_btdf * baseColor, t), specular_brdf)"); metals transmit nothing.
The BTDF is evaluated as the Khronos Sample Viewer does for a punctual light (its
getPunctualRadianceTransmission): the light direction mirrored through the surface's plane,
  l' = l - 2 (n.l) n,  h' = normalize(l' + v),
  btdf = (1 - F(|v.h'|)) baseColor D(n.h') Vis(n.l', n.v)
with GGX's D and the height-correlated Smith Vis at alpha = roughness^2, F Schlick's from
f0 = ((ior - 1) / (ior + 1))^2. Renderer conventions, stated in docs/lights-and-shading.md:
  * the BTDF is weighted by n.l' (the Sample Viewer leaves the cosine out) and taken only for
    lights behind the surface (n.l < 0);
  * KHR_materials_volume's Beer's law (c_a^(d / d_a), none where d or d_a is 0) over the thickness
    d, for the lights through it and for what is seen behind;
  * glTF has no ambient: the ambient fill is ambient ((1 - t) diffuse + f0), and the radiance B
    seen through the surface (the frame behind it, which the transparent pass samples) reaches the
    eye as t base (1 - metallic) (1 - f0) B tint.
Everything here is float64 from those formulas, not from the renderer's shader. The cases: random
views, materials, transmissions, volumes and one sun, half of them behind the surface. The check
prints the largest relative difference and fails above MIRROR_TOLERANCE; it also fails if the
lights behind add nothing (so a lobe that is never evaluated cannot pass).

  check_transmission.py --mirror build-test/tests/ml_shading_mirror
"""
import math
import sys

import numpy as np

from shading_mirror_io import as_float32, dot, mirror_arguments, normalize, random_views, run_mirror, sunlit_row

MIN_ALPHA = 0.002         # renderer convention: GGX's alpha floor (ML_GGX_MIN_ALPHA)
MIRROR_TOLERANCE = 2e-4   # relative, float32 (the mirror) against float64, plus 1e-6 absolute


def schlick(f0, cos):
    return f0 + (1.0 - f0) * (1.0 - cos) ** 5


def ggx_d_vis(n, v, l, roughness):
    """GGX's D times the height-correlated Smith Vis (glTF's appendix B, the Sample Viewer's V_GGX)."""
    nl = np.maximum(dot(n, l), 0.0)
    nv = np.abs(dot(n, v))
    nh = np.maximum(dot(n, normalize(l + v)), 0.0)
    a2 = np.maximum(roughness ** 2, MIN_ALPHA) ** 2
    d = a2 / (math.pi * (nh * nh * (a2 - 1.0) + 1.0) ** 2)
    vis = 0.5 / (nl * np.sqrt(nv * nv * (1.0 - a2) + a2) + nv * np.sqrt(nl * nl * (1.0 - a2) + a2))
    return d * vis


def radiance(n, v, l, sun, ambient, base, metallic, roughness, ior, t, thickness, distance, color, behind):
    """The material under one sun (direction l towards it) plus the fill and the scene behind (N, 3)."""
    f0_ior = np.repeat((((ior - 1.0) / (ior + 1.0)) ** 2)[:, None], 3, axis=1)
    metal = (metallic > 0.5)[:, None]
    f0 = np.where(metal, base, f0_ior)
    diffuse = np.where(metal, 0.0, base)
    transmitted = diffuse * t[:, None]
    opaque_diffuse = diffuse * (1.0 - t[:, None])
    tinted = (thickness > 0.0) & (distance > 0.0)
    tint = np.where(tinted[:, None], color ** (thickness / np.where(tinted, distance, 1.0))[:, None], 1.0)
    nl = dot(n, l)
    # In front: (1 - F) (1 - t) diffuse / pi + F D Vis, times n.l.
    h = normalize(l + v)
    f = schlick(f0, np.abs(dot(v, h))[:, None])
    front = ((1.0 - f) * opaque_diffuse / math.pi + f * ggx_d_vis(n, v, l, roughness)[:, None]) * np.maximum(nl, 0.0)[:, None]
    # Behind: the BTDF at the mirrored light, times n.l'.
    mirrored = l - 2.0 * nl[:, None] * n
    hm = normalize(mirrored + v)
    fm = schlick(f0, np.abs(dot(v, hm))[:, None])
    through = (1.0 - fm) * transmitted * ggx_d_vis(n, v, mirrored, roughness)[:, None] * np.maximum(-nl, 0.0)[:, None] * tint
    lit = np.where((nl > 0.0)[:, None], front, np.where((nl < 0.0)[:, None], through, 0.0)) * sun
    fill = ambient * (opaque_diffuse + f0) + transmitted * (1.0 - f0) * behind * tint
    return lit + fill, np.where((nl < 0.0)[:, None], through * sun, 0.0)


def main():
    args = mirror_arguments(__doc__.splitlines()[0])
    rng = np.random.default_rng(11)
    count = args.cases
    n, v, l = random_views(rng, count)
    behind_side = rng.uniform(size=count) < 0.5
    l[behind_side, 2] *= -1.0  # half the suns behind the surface
    l = normalize(l)
    base = rng.uniform(0.05, 0.95, size=(count, 3))
    metallic = (rng.uniform(size=count) < 0.15).astype(float)
    roughness = rng.uniform(0.1, 1.0, size=count)
    ior = rng.uniform(1.0, 2.5, size=count)
    t = np.where(rng.uniform(size=count) < 0.1, 0.0, rng.uniform(0.1, 1.0, size=count))
    thickness = np.where(rng.uniform(size=count) < 0.3, 0.0, rng.uniform(0.01, 2.0, size=count))
    distance = np.where(rng.uniform(size=count) < 0.2, 0.0, rng.uniform(0.1, 3.0, size=count))
    color = rng.uniform(0.05, 1.0, size=(count, 3))
    behind = rng.uniform(0.0, 3.0, size=(count, 3))
    sun_color = np.array([1.5, 1.3, 1.1])
    ambient = 0.05
    position = np.zeros((count, 3))
    eye = position + v * 3.0
    rows = []
    for i in range(count):
        rows.append(sunlit_row(eye[i], position[i], n[i], base[i], metallic[i], roughness[i], ior[i], ambient, -l[i], sun_color) + [
            0.0, 0.0, 1.3,  # no film
            t[i], thickness[i], distance[i], *color[i], *behind[i]])
    got = run_mirror(args.mirror, rows)
    f32 = as_float32
    v32 = normalize(f32(eye) - f32(position))
    expected, through = radiance(n, v32, normalize(f32(l)), f32(sun_color), ambient, f32(base), metallic, f32(roughness), f32(ior),
                                 f32(t), f32(thickness), f32(distance), f32(color), f32(behind))
    if got.shape != expected.shape:
        print(f"FAIL: the mirror answered {got.shape[0]} lines for {count} cases")
        return 1
    rel = np.abs(got - expected) / (np.abs(expected) + 1e-6)
    worst = np.unravel_index(np.argmax(rel), rel.shape)[0]
    back = behind_side & (t > 0.0) & (metallic < 0.5)
    print(f"transmission: numpy (specification) against the CPU mirror over {count} cases ({int(back.sum())} lit from behind "
          f"through a dielectric, {int((thickness > 0).sum())} with a volume): max relative difference {rel.max():.2e} "
          f"(from behind {rel[behind_side].max():.2e}, in front {rel[~behind_side].max():.2e})")
    print(f"transmission: the lights behind add up to {through.max():.3f} (median {np.median(through[back].max(axis=1)):.4f})")
    if not through[back].max() > 1e-3:
        print("FAIL: no light behind the surface reached the eye")
        return 1
    if rel.max() > MIRROR_TOLERANCE:
        print(f"FAIL: case {worst}: numpy {expected[worst]}, mirror {got[worst]}, t {t[worst]}, thickness {thickness[worst]}, "
              f"distance {distance[worst]}, metallic {metallic[worst]}, ior {ior[worst]}, behind {behind_side[worst]}")
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
