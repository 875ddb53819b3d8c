"""KHR_materials_iridescence written from its specification and held to the CPU mirror.

The film's Fresnel, F_i (the specification's "Iridescence Fresnel", after Belcour and Barla 2017),
is evaluated here in float64 from the specification's text, not from the renderer's shader:
  R12 = F_schlick(((eta_f - 1) / (eta_f + 1))^2, cos1),  T121 = 1 - R12,  phi21 = pi
  base_ior = (1 + sqrt(f0 + 1e-4)) / (1 - sqrt(f0 + 1e-4)),  R23 = F_schlick(((base_ior - eta_f) / (base_ior + eta_f))^2, cos2)
  phi23 = pi where base_ior < eta_f,  cos2 = sqrt(1 - (1 - cos1^2) / eta_f^2)        (Snell, air outside)
  OPD = 2 eta_f d cos2                     (Belcour and Barla's and the Sample Viewer's; the
                                            specification's listing writes cos1 there)
  R123 = clamp(R12 R23, 1e-5, 0.9999),  Rs = T121^2 R23 / (1 - R123)
  I = R12 + Rs + sum over m = 1, 2 of  2 (Rs - T121) R123^(m/2) S(m OPD, m phi)
  F_i = max(I, 0),  S the colour matching functions' Fourier transform (its Gaussian fit) in Rec. 709
and the material (the specification's iridescent_dielectric_layer and iridescent_conductor_layer,
KHR_materials_ior's base_ior, specular weight 1, white specular colour):
  dielectric  rgb_mix(base / pi, D Vis, mix(F_schlick(f0_ior, 1), F_i(f0_ior), k))
              with rgb_mix(b, s, a) = (1 - max(a)) b + a s
  metal       mix(F_schlick(base, 1), F_i(base), k) D Vis
each at cos1 = |V.H| (the microfacet's angle, where F_schlick takes it), times N.L, under one sun.
Renderer convention (glTF has no ambient): the ambient fill reflects off the film at N.V:
ambient (diffuse + mix(f0, F_i(|N.V|), k)). A thickness of 0 is no film.

The check prints the largest relative difference over the cases and fails above MIRROR_TOLERANCE;
it also prints how far F_i's hue swings (its channels' spread) so that a film that changed
nothing cannot pass. It then checks the specification's spectral integration itself: each order's
closed-form sensitivity against the integral over wavenumber done numerically with the colour
matching functions' Gaussians (fails above FORM_TOLERANCE), and prints how much the sum's
truncation at two orders leaves out against 40.

  check_iridescence.py --mirror build-test/tests/ml_shading_mirror
"""
import math
import sys

import numpy as np

from shading_mirror_io import as_float32, dot, mirror_arguments, normalize, random_views, run_mirror, sunlit_row

MIN_ALPHA = 0.002         # renderer convention: GGX's alpha floor (ML_GGX_MIN_ALPHA)
MIRROR_TOLERANCE = 2e-4
FORM_TOLERANCE = 1e-4     # the closed form against the numerical spectral integral   # relative, float32 (the mirror) against float64, plus 1e-6 absolute
XYZ_TO_REC709 = np.array([[3.2404542, -1.5371385, -0.4985314],
                          [-0.9692660, 1.8760108, 0.0415560],
                          [0.0556434, -0.2040259, 1.0572252]])


def schlick(f0, cos):
    return f0 + (1.0 - f0) * (1.0 - cos) ** 5


def sensitivity(opd_nm, shift):
    """S: the specification's evalSensitivity, (N,) OPD in nm and (N, 3) phase shifts -> (N, 3)."""
    phase = 2.0 * math.pi * opd_nm * 1e-9
    val = np.array([5.4856e-13, 4.4201e-13, 5.2481e-13])
    pos = np.array([1.6810e+06, 1.7953e+06, 2.2084e+06])
    var = np.array([4.3278e+09, 9.3046e+09, 6.6121e+09])
    p = phase[:, None]
    xyz = val * np.sqrt(2.0 * math.pi * var) * np.cos(pos * p + shift) * np.exp(-(p ** 2) * var)
    xyz[:, 0] += 9.7470e-14 * math.sqrt(2.0 * math.pi * 4.5282e+09) * np.cos(2.2399e+06 * phase + shift[:, 0]) * \
        np.exp(-4.5282e+09 * phase ** 2)
    xyz /= 1.0685e-7
    return xyz @ XYZ_TO_REC709.T


def iridescent_fresnel(cos1, eta, d, f0):
    """F_i for (N,) cos1, film IOR eta, thickness d (nm) and (N, 3) base F0."""
    sin2sq = (1.0 - cos1 ** 2) / eta ** 2
    cos2 = np.sqrt(1.0 - sin2sq)
    r12 = schlick(((eta - 1.0) / (eta + 1.0)) ** 2, cos1)[:, None]
    t121 = 1.0 - r12
    sqrt_f0 = np.sqrt(f0 + 1e-4)
    base_ior = (1.0 + sqrt_f0) / (1.0 - sqrt_f0)
    e = eta[:, None]
    r23 = schlick(((base_ior - e) / (base_ior + e)) ** 2, cos2[:, None])
    phi = math.pi + np.where(base_ior < e, math.pi, 0.0)
    opd = 2.0 * eta * d * cos2
    r123 = np.clip(r12 * r23, 1e-5, 0.9999)
    rs = t121 ** 2 * r23 / (1.0 - r123)
    i = r12 + rs
    for m in (1, 2):
        i = i + (rs - t121) * r123 ** (m / 2.0) * 2.0 * sensitivity(m * opd, m * phi)
    return np.maximum(i, 0.0)


def airy_terms(cos1, eta, d, f0):
    """The Airy sum's terms as the specification sets them up: C0, the m >= 1 amplitude (Rs - T121),
    sqrt(R123), the phase shift phi and the OPD (nm), for one case (f0 (3,))."""
    cos2 = math.sqrt(1.0 - (1.0 - cos1 ** 2) / eta ** 2)
    r12 = schlick(((eta - 1.0) / (eta + 1.0)) ** 2, cos1)
    sqrt_f0 = np.sqrt(f0 + 1e-4)
    base_ior = (1.0 + sqrt_f0) / (1.0 - sqrt_f0)
    r23 = schlick(((base_ior - eta) / (base_ior + eta)) ** 2, cos2)
    r123 = np.clip(r12 * r23, 1e-5, 0.9999)
    rs = (1.0 - r12) ** 2 * r23 / (1.0 - r123)
    return r12 + rs, rs - (1.0 - r12), np.sqrt(r123), math.pi + np.where(base_ior < eta, math.pi, 0.0), 2.0 * eta * d * cos2


def numeric_sensitivity(opd_nm, shift, k, g):
    """evalSensitivity by numerical integration: each colour matching function, the Gaussian in
    wavenumber k (1/m) whose Fourier transform the specification's closed form is,
    g(k) = val / sqrt(2) exp(-(k - pos)^2 / (4 var)), times cos(2 pi k OPD + shift), over k,
    normalised by 1.0685e-7, XYZ to Rec. 709."""
    xyz = np.zeros(3)
    for lobe, channel in ((0, 0), (1, 1), (2, 2), (3, 0)):
        xyz[channel] += np.trapz(g[lobe] * np.cos(2.0 * math.pi * k * opd_nm * 1e-9 + shift[channel]), k) / 1.0685e-7
    return XYZ_TO_REC709 @ xyz


def spectral_sum(cos1, eta, d, f0, orders):
    """F_i with every order's sensitivity integrated numerically, the Airy sum to `orders` orders."""
    k = np.linspace(0.2e6, 4.5e6, 20001)
    val = np.array([5.4856e-13, 4.4201e-13, 5.2481e-13, 9.7470e-14])
    pos = np.array([1.6810e+06, 1.7953e+06, 2.2084e+06, 2.2399e+06])
    var = np.array([4.3278e+09, 9.3046e+09, 6.6121e+09, 4.5282e+09])
    g = val[:, None] / math.sqrt(2.0) * np.exp(-(k[None, :] - pos[:, None]) ** 2 / (4.0 * var[:, None]))
    c0, cm, ratio, phi, opd = airy_terms(cos1, eta, d, f0)
    total = c0.copy()
    for m in range(1, orders + 1):
        cm = cm * ratio
        total = total + cm * 2.0 * numeric_sensitivity(m * opd, m * phi, k, g)
    return np.maximum(total, 0.0)


def check_spectral_integration(rng, cases=30):
    """The specification's closed form against its spectral integral done numerically (two orders),
    and the Airy sum's truncation at two orders against 40."""
    worst_form, worst_truncation = 0.0, 0.0
    for _ in range(cases):
        cos1, eta, d = rng.uniform(0.05, 1.0), rng.uniform(1.05, 2.3), rng.uniform(100.0, 1200.0)
        f0 = rng.uniform(0.02, 0.9, size=3)
        closed = iridescent_fresnel(np.array([cos1]), np.array([eta]), np.array([d]), f0[None, :])[0]
        two = spectral_sum(cos1, eta, d, f0, 2)
        worst_form = max(worst_form, np.abs(two - closed).max())
        worst_truncation = max(worst_truncation, np.abs(spectral_sum(cos1, eta, d, f0, 40) - two).max())
    return worst_form, worst_truncation


def ggx_dv(n, v, l, roughness):
    nl = np.maximum(dot(n, l), 0.0)
    nv = np.abs(dot(n, v))
    nh = dot(n, normalize(l + v))
    a2 = np.maximum(roughness ** 2, MIN_ALPHA) ** 2  # renderer convention: alpha floored
    return a2 * (nh > 0.0) / (math.pi * (nh * nh * (a2 - 1.0) + 1.0) ** 2) * \
        0.5 / (nl * np.sqrt(nv * nv * (1.0 - a2) + a2) + nv * np.sqrt(nl * nl * (1.0 - a2) + a2))


def radiance(n, v, l, sun, ambient, base, metallic, roughness, ior, k, d, eta):
    """The specification's material under the sun plus the renderer's ambient fill (N, 3)."""
    cos1 = np.abs(dot(v, normalize(l + v)))
    nl = np.maximum(dot(n, l), 0.0)[:, None]
    dv = ggx_dv(n, v, l, roughness)[:, None]
    f0_ior = np.repeat((((ior - 1.0) / (ior + 1.0)) ** 2)[:, None], 3, axis=1)
    metal = (metallic > 0.5)[:, None]
    f0 = np.where(metal, base, f0_ior)
    film = (k > 0.0) & (d > 0.0)
    kk = np.where(film, k, 0.0)[:, None]
    fi = iridescent_fresnel(cos1, eta, np.where(film, d, 1.0), f0)
    f = (1.0 - kk) * schlick(f0, cos1[:, None]) + kk * fi
    dielectric = (1.0 - f.max(axis=1, keepdims=True)) * base / math.pi + f * dv
    conductor = f * dv
    lit = np.where(metal, conductor, dielectric) * nl * sun
    fi_v = iridescent_fresnel(np.abs(dot(n, v)), eta, np.where(film, d, 1.0), f0)
    fill = ambient * (np.where(metal, 0.0, base) + (1.0 - kk) * f0 + kk * fi_v)
    return lit + fill


def main():
    args = mirror_arguments(__doc__.splitlines()[0])
    rng = np.random.default_rng(7)
    count = args.cases
    n, v, l = random_views(rng, count)
    base = rng.uniform(0.05, 0.95, size=(count, 3))
    metallic = (rng.uniform(size=count) < 0.35).astype(float)
    roughness = rng.uniform(0.1, 1.0, size=count)
    ior = rng.uniform(1.2, 2.5, size=count)
    k = np.where(rng.uniform(size=count) < 0.1, 0.0, rng.uniform(0.2, 1.0, size=count))
    d = np.where(rng.uniform(size=count) < 0.05, 0.0, rng.uniform(50.0, 1200.0, size=count))
    eta = rng.uniform(1.0, 2.3, size=count)
    sun_color = np.array([1.5, 1.3, 1.1])
    ambient = 0.05
    eye_distance = 3.0
    position = np.zeros((count, 3))
    eye = position + v * eye_distance
    rows = []
    for i in range(count):
        rows.append(sunlit_row(eye[i], position[i], n[i], base[i], metallic[i], roughness[i], ior[i], ambient, -l[i], sun_color) + [
            k[i], d[i], eta[i]])
    got = run_mirror(args.mirror, rows)
    f32 = as_float32
    v32 = normalize(f32(eye) - f32(position))
    expected = radiance(n, v32, normalize(f32(l)), f32(sun_color), ambient, f32(base), metallic, f32(roughness),
                        f32(ior), f32(k), f32(d), f32(eta))
    if got.shape != expected.shape:
        print(f"FAIL: the mirror answered {got.shape[0]} lines for {count} cases")
        return 1
    rel = np.abs(got - expected) / (np.abs(expected) + 1e-6)
    worst = np.unravel_index(np.argmax(rel), rel.shape)[0]
    film = (k > 0.0) & (d > 0.0)
    fi = iridescent_fresnel(np.linspace(0.05, 1.0, count), eta, np.maximum(d, 1.0), np.repeat(f32(((ior - 1) / (ior + 1)) ** 2)[:, None], 3, 1))
    print(f"iridescence: numpy (specification) against the CPU mirror over {count} cases ({int(film.sum())} with a film, "
          f"{int(metallic.sum())} metals): max relative difference {rel.max():.2e} (film {rel[film].max():.2e}, none "
          f"{rel[~film].max():.2e})")
    print(f"iridescence: F_i's channel spread up to {np.ptp(fi, axis=1).max():.3f} (F_i from {fi.min():.3f} to {fi.max():.3f})")
    form, truncation = check_spectral_integration(rng)
    print(f"iridescence: the specification's closed-form sensitivity against the spectral integral done numerically: "
          f"max {form:.2e}; the Airy sum's two orders against 40: up to {truncation:.3f} (the specification's truncation)")
    if form > FORM_TOLERANCE:
        print(f"FAIL: the closed form is {form:.2e} off the numerical integral")
        return 1
    if rel.max() > MIRROR_TOLERANCE:
        print(f"FAIL: case {worst}: numpy {expected[worst]}, mirror {got[worst]}, k {k[worst]}, d {d[worst]}, eta {eta[worst]}, "
              f"metallic {metallic[worst]}, ior {ior[worst]}")
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
