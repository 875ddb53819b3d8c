"""KHR_materials_ior, KHR_materials_specular, KHR_materials_unlit and KHR_materials_clearcoat
written from their specifications (issue 65), for check_material_extensions.py; GGX's D and Vis are
cpu_reference's (glTF appendix B). Nothing here comes from the renderer's shading code.

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
"""
import numpy as np

from cpu_reference import dot, ggx_distribution_visibility, schlick_weight


def dielectric_f0(ior, specular_color):
    """(N,) ior and (N, 3) specularColorFactor: the dielectric's F0 colour, clamped at 1."""
    return np.minimum(((ior - 1.0) / (ior + 1.0))[:, None] ** 2 * specular_color, 1.0)


def brdf_times_cos(n, v, l, base, metallic, roughness, ior, specular, specular_color, convention=True):
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
    dv = ggx_distribution_visibility(n, v, l, roughness)[:, None]
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
             clearcoat, clearcoat_roughness, clearcoat_normal):
    """A point's linear radiance under one directional light (towards it: sun_l) and the ambient
    fill; an unlit material's is its base colour (KHR_materials_unlit). Under a coat, the ambient
    fill (a renderer convention) is layered as the emission is, and the coat reflects the fill
    as a mirror of albedo one would (its Fresnel is in the share)."""
    k = clearcoat_share(v, clearcoat, clearcoat_normal)
    coat = ggx_distribution_visibility(clearcoat_normal, v, sun_l, clearcoat_roughness) * np.maximum(dot(clearcoat_normal, sun_l), 0.0)
    fill = ambient_fill(ambient, base, metallic, ior, specular, specular_color)
    lit = (1.0 - k) * (fill + np.asarray(sun_color) * brdf_times_cos(n, v, sun_l, base, metallic, roughness, ior, specular,
                                                                    specular_color)) \
        + k * (ambient + np.asarray(sun_color) * coat[:, None])
    return np.where(unlit[:, None], base, lit)
