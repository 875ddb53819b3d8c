"""KHR_materials_ior, KHR_materials_specular, KHR_materials_unlit, KHR_materials_clearcoat and
KHR_materials_sheen written from their specifications (issue 65), for check_material_extensions.py;
GGX's D and Vis are cpu_reference's (glTF appendix B). Nothing here comes from the renderer's
shading code.

KHR_materials_specular's BRDF, with alpha, D and Vis as in appendix B:
  dielectric_f0  = min(((ior - 1) / (ior + 1))^2 * specularColorFactor, 1)             (with KHR_materials_ior)
  F_schlick(f0, f90) = f0 + (f90 - f0) (1 - |V.H|)^5
  dielectric_brdf = (1 - w max_value(F_schlick(dielectric_f0, 1))) base / pi
                    + w F_schlick(dielectric_f0, 1) D Vis,          w = specularFactor  (fresnel_mix)
  metal_brdf     = F_schlick(base, 1) D Vis                                            (conductor_fresnel)
  f = mix(dielectric_brdf, metal_brdf, metallic)
KHR_materials_unlit: the surface shows its base colour, whatever the lights.
KHR_materials_clearcoat (its "Implementation" section), Nc the coat's normal:
  clearcoat_fresnel = 0.04 + (1 - 0.04) (1 - |V.Nc|)^5
  clearcoat_brdf    = D(clearcoatRoughness^2) G / (4 |V.Nc| |L.Nc|)      (appendix B's specular term, no Fresnel)
  coated_material   = mix(material, clearcoat_brdf, clearcoat clearcoat_fresnel)
  coated_emission   = emission (1 - clearcoat clearcoat_fresnel)
each BRDF times its own normal's cosine with the light.
KHR_materials_sheen (its "Implementation Notes"), c the sheen colour, alpha_g = sheenRoughness^2:
  sheen_distribution = (2 + 1 / alpha_g) sin2h^(0.5 / alpha_g) / (2 pi)                   (Charlie)
  sheen_visibility   = 1 / ((1 + lambda_sheen(N.V) + lambda_sheen(N.L)) 4 N.V N.L)       (its fit of Lambda)
  sheen_albedo_scaling = min(1 - max3(c) E(V.N), 1 - max3(c) E(L.N))
  sheen_material     = c sheen_distribution sheen_visibility + material sheen_albedo_scaling
with E the sheen BRDF's directional albedo, here integrated over the hemisphere (sheen_albedo_table),
not fitted; clearcoat layers over sheen_material. Renderer conventions: sheenRoughness floored at
0.07 (the specification's inv_r is infinite at 0), and the ambient fill dimmed by E(V.N) alone and
reflected off the sheen (c E(V.N)).
KHR_materials_anisotropy (its "Implementation" section), strength a, rotation r, the mesh's tangent
t (w its bitangent sign, b = w Ng x t) and the map's direction d (RG in [-1, 1]; (1, 0) without):
  direction      = [cos r  -sin r; sin r  cos r] normalize(d)
  anisotropicT   = normalize(TBN (direction, 0)),   anisotropicB = normalize(Ng x anisotropicT)
  alpha_t = mix(alpha, 1, a^2),  alpha_b = alpha
  D = 1 / (pi alpha_t alpha_b ((T.H / alpha_t)^2 + (B.H / alpha_b)^2 + (N.H)^2)^2)
  V = clamp(1 / (2 (N.L sqrt(alpha_t^2 (T.V)^2 + alpha_b^2 (B.V)^2 + (N.V)^2)
                   + N.V sqrt(alpha_t^2 (T.L)^2 + alpha_b^2 (B.L)^2 + (N.L)^2))), 0, 1)
in place of appendix B's D and Vis. Renderer convention: alpha floored at cpu_reference.MIN_ALPHA.
"""
import numpy as np

from cpu_reference import dot, ggx_distribution_visibility, normalize, schlick_weight


def anisotropy_directions(ng, tangent, rotation, map_direction):
    """(anisotropicT, anisotropicB) (N, 3) each, from the geometric normal ng, tangents (N, 4), the
    rotation (N,) and the map's direction (N, 2), as the specification builds them."""
    d = map_direction / np.linalg.norm(map_direction, axis=-1, keepdims=True)
    c, s = np.cos(rotation), np.sin(rotation)
    direction = np.stack([c * d[:, 0] - s * d[:, 1], s * d[:, 0] + c * d[:, 1]], axis=-1)
    t = tangent[:, :3]
    b = np.cross(ng, t) * tangent[:, 3:4]
    anisotropic_t = normalize(t * direction[:, :1] + b * direction[:, 1:])
    return anisotropic_t, normalize(np.cross(ng, anisotropic_t))


def anisotropic_distribution_visibility(n, v, l, roughness, strength, t, b):
    """The specification's anisotropic D x V (N,), N.L clamped at 0."""
    from cpu_reference import MIN_ALPHA
    nl = np.maximum(dot(n, l), 0.0)
    nv = np.abs(dot(n, v))
    h = normalize(l + v)
    alpha_b = np.maximum(roughness * roughness, MIN_ALPHA)
    alpha_t = alpha_b + (1.0 - alpha_b) * strength * strength
    q = (dot(t, h) / alpha_t) ** 2 + (dot(b, h) / alpha_b) ** 2 + dot(n, h) ** 2
    d = 1.0 / (np.pi * alpha_t * alpha_b * q * q)
    g_v = nl * np.sqrt((alpha_t * dot(t, v)) ** 2 + (alpha_b * dot(b, v)) ** 2 + nv * nv)
    g_l = nv * np.sqrt((alpha_t * dot(t, l)) ** 2 + (alpha_b * dot(b, l)) ** 2 + nl * nl)
    return d * np.clip(1.0 / (2.0 * (g_v + g_l)), 0.0, 1.0)


def dielectric_f0(ior, specular_color):
    """(N,) ior and (N, 3) specularColorFactor: the dielectric's F0 colour, clamped at 1."""
    return np.minimum(((ior - 1.0) / (ior + 1.0))[:, None] ** 2 * specular_color, 1.0)


def brdf_times_cos(n, v, l, base, metallic, roughness, ior, specular, specular_color, convention=True, anisotropy=None):
    """The BRDF above times N.L (zero where N.L <= 0) for unit n, v, l (N, 3) and per-point factors.

    Renderer convention (`convention`, as glTF's appendix B implementation does): the diffuse is
    weighted by 1 - mix(w max_value(F_dielectric), F_metal, metallic), the Fresnel mixed by
    metallic, where the specification takes the dielectric's alone; the two agree exactly where
    metallic is 0 or 1 (a metal has no diffuse), which the check verifies, and differ between.
    """
    nl_pos = np.maximum(dot(n, l), 0.0)
    q5 = schlick_weight(v, l)[:, None]
    w, m = specular[:, None], metallic[:, None]
    f_dielectric = dielectric_f0(ior, specular_color)
    f_dielectric = f_dielectric + (1.0 - f_dielectric) * q5                 # F_schlick(dielectric_f0, 1)
    f_metal = base + (1.0 - base) * q5                                     # F_schlick(base, 1)
    dv = ggx_distribution_visibility(n, v, l, roughness)
    if anisotropy is not None:                                             # (strength, T, B): KHR_materials_anisotropy
        strength, t, b = anisotropy
        dv = np.where(strength > 0.0, anisotropic_distribution_visibility(n, v, l, roughness, strength, t, b), dv)
    dv = dv[:, None]
    diffuse_fresnel = w * f_dielectric.max(axis=-1, keepdims=True)         # max_value(): one weight for all channels
    if convention:
        diffuse_fresnel = (1.0 - m) * diffuse_fresnel + m * f_metal
    dielectric_specular = w * f_dielectric * dv
    f = (1.0 - m) * dielectric_specular + m * f_metal * dv + (1.0 - m) * (1.0 - diffuse_fresnel) * base / np.pi
    return f * nl_pos[:, None]


def ambient_fill(ambient, base, metallic, ior, specular, specular_color):
    """Renderer convention (glTF has no ambient): ambient x (diffuse + F0), F0 the material's
    normal-incidence Fresnel mix(w dielectric_f0, base, metallic)."""
    m = metallic[:, None]
    f0 = (1.0 - m) * specular[:, None] * dielectric_f0(ior, specular_color) + m * base
    return ambient * ((1.0 - m) * base + f0)


def clearcoat_share(v, clearcoat, clearcoat_normal):
    """clearcoat x clearcoat_fresnel (N, 1): what the coat takes of the layers below."""
    return (clearcoat * (0.04 + 0.96 * (1.0 - np.abs(dot(v, clearcoat_normal))) ** 5))[:, None]


def radiance(n, v, sun_l, sun_color, ambient, base, metallic, roughness, ior, specular, specular_color, unlit,
             clearcoat, clearcoat_roughness, clearcoat_normal, sheen_color, sheen_roughness, sheen_albedo=None,
             anisotropy=None):
    """A point's linear radiance under one directional light (towards it: sun_l) and the ambient
    fill; an unlit material's is its base colour (KHR_materials_unlit). Under a coat, the ambient
    fill (a renderer convention) is layered as the emission is, and the coat reflects the fill
    as a mirror of albedo one would (its Fresnel is in the share)."""
    k = clearcoat_share(v, clearcoat, clearcoat_normal)
    coat = ggx_distribution_visibility(clearcoat_normal, v, sun_l, clearcoat_roughness) * np.maximum(dot(clearcoat_normal, sun_l), 0.0)
    fill = ambient_fill(ambient, base, metallic, ior, specular, specular_color)
    material = brdf_times_cos(n, v, sun_l, base, metallic, roughness, ior, specular, specular_color, anisotropy=anisotropy)
    material, fill = sheen_layer(n, v, sun_l, material, fill, ambient, sheen_color, sheen_roughness,
                                 SHEEN_ALBEDO if sheen_albedo is None else sheen_albedo)
    lit = (1.0 - k) * (fill + np.asarray(sun_color) * material) + k * (ambient + np.asarray(sun_color) * coat[:, None])
    return np.where(unlit[:, None], base, lit)


SHEEN_MIN_ROUGHNESS = 0.07  # renderer convention (Khronos' Sample Viewer's floor)


def sheen_alpha(sheen_roughness):
    return np.maximum(sheen_roughness, SHEEN_MIN_ROUGHNESS) ** 2


def sheen_distribution(n_dot_h, alpha_g):
    inv_r = 1.0 / alpha_g
    sin2h = np.maximum(1.0 - n_dot_h * n_dot_h, 0.0)
    return (2.0 + inv_r) * sin2h ** (inv_r * 0.5) / (2.0 * np.pi)


def _sheen_l(x, alpha_g):
    t = (1.0 - alpha_g) ** 2
    a = 21.5473 + (25.3245 - 21.5473) * t
    b = 3.82987 + (3.32435 - 3.82987) * t
    c = 0.19823 + (0.16801 - 0.19823) * t
    d = -1.97760 + (-1.27393 + 1.97760) * t
    e = -4.32054 + (-4.85967 + 4.32054) * t
    return a / (1.0 + b * np.abs(x) ** c) + d * x + e


def lambda_sheen(cos_theta, alpha_g):
    return np.where(np.abs(cos_theta) < 0.5, np.exp(_sheen_l(cos_theta, alpha_g)),
                    np.exp(2.0 * _sheen_l(0.5, alpha_g) - _sheen_l(1.0 - cos_theta, alpha_g)))


def sheen_brdf(n_dot_v, n_dot_l, n_dot_h, sheen_roughness):
    """The Charlie BRDF D V (colour 1) for N.V, N.L > 0."""
    alpha_g = sheen_alpha(sheen_roughness)
    visibility = 1.0 / ((1.0 + lambda_sheen(n_dot_v, alpha_g) + lambda_sheen(n_dot_l, alpha_g)) * (4.0 * n_dot_v * n_dot_l))
    return sheen_distribution(n_dot_h, alpha_g) * visibility


def sheen_albedo_integral(mu, sheen_roughness, steps=(512, 256)):
    """E(mu): the sheen BRDF times N.L integrated over the hemisphere of light directions, the view
    at cosine mu; midpoint rule in cos(theta_L) and in phi over [0, pi] (the lobe is symmetric)."""
    u = (np.arange(steps[0]) + 0.5) / steps[0]                  # cos(theta_L)
    phi = (np.arange(steps[1]) + 0.5) / steps[1] * np.pi
    u, phi = np.meshgrid(u, phi, indexing="ij")
    s = np.sqrt(1.0 - u * u)
    l = np.stack([s * np.cos(phi), s * np.sin(phi), u], axis=-1)
    v = np.array([np.sqrt(1.0 - mu * mu), 0.0, mu])
    h = l + v
    n_dot_h = h[..., 2] / np.linalg.norm(h, axis=-1)
    f = sheen_brdf(mu, u, n_dot_h, sheen_roughness) * u
    return 2.0 * f.sum() * (1.0 / steps[0]) * (np.pi / steps[1])


def sheen_albedo_fit(mu, sheen_roughness):
    """Conty Estevez and Kulla's fit of E, as the renderer takes it (sqrt(alpha_g) = the floored roughness)."""
    r = np.maximum(sheen_roughness, SHEEN_MIN_ROUGHNESS)
    return 0.65584461 * (1.0 - mu) ** 3 + 1.0 / (4.16526551 + np.exp(-7.97291361 * r + 6.33516894))


class SheenAlbedoTable:
    """E by integration on a grid of N.V for each roughness it is asked about, interpolated linearly."""
    MU = np.linspace(0.0, 1.0, 129)[1:]

    def __init__(self):
        self.rows = {}

    def __call__(self, mu, sheen_roughness):
        mu, sheen_roughness = np.broadcast_arrays(np.asarray(mu, float), np.asarray(sheen_roughness, float))
        out = np.zeros(mu.shape)
        for r in np.unique(sheen_roughness):
            if r not in self.rows:
                self.rows[r] = np.array([sheen_albedo_integral(m, r) for m in self.MU])
            sel = sheen_roughness == r
            out[sel] = np.interp(mu[sel], self.MU, self.rows[r])
        return out


SHEEN_ALBEDO = SheenAlbedoTable()


def sheen_layer(n, v, sun_l, base_lit, fill, ambient, sheen_color, sheen_roughness, albedo=SHEEN_ALBEDO):
    """The material under its sheen: (the sun's light, the ambient fill), base_lit and fill being the
    material's own; unchanged where the sheen colour is 0."""
    c = np.asarray(sheen_color, float)
    m = c.max(axis=-1)
    n_dot_v, n_dot_l = np.abs(dot(n, v)), dot(n, sun_l)
    lit = n_dot_l > 0.0
    nl = np.where(lit, n_dot_l, 1.0)
    sheen = m > 0.0
    e_v, e_l = np.zeros(m.shape), np.zeros(m.shape)                        # E only where there is a sheen
    e_v[sheen] = albedo(n_dot_v[sheen], sheen_roughness[sheen])
    e_l[sheen] = albedo(np.clip(nl[sheen], 0.0, 1.0), sheen_roughness[sheen])
    scaling = np.minimum(1.0 - m * e_v, 1.0 - m * e_l)
    h = normalize(v + sun_l)
    lobe = np.where(lit, sheen_brdf(n_dot_v, nl, dot(n, h), sheen_roughness) * nl, 0.0)
    lit_out = np.where(sheen[:, None], c * lobe[:, None] + base_lit * scaling[:, None], base_lit)
    fill_out = np.where(sheen[:, None], fill * (1.0 - m * e_v)[:, None] + ambient * c * e_v[:, None], fill)
    return lit_out, fill_out
