"""An independent CPU rendering of simple analytic scenes (issue 61): a ray cast through each
pixel centre against exact rectangles, boxes and spheres, shaded by glTF 2.0's metallic-roughness
BRDF (specification, appendix B) under KHR_lights_punctual's point, spot and directional lights.

Nothing here comes from the renderer's shading code: the BRDF and the lights are written from the
two specifications, so a fault the renderer's methods share (naive included) shows as a difference.
Where glTF leaves a choice to the renderer, the renderer's documented choice is taken, and each is
marked "Renderer convention" below:

- the falloff of a point or spot light: the renderer's smooth window
  saturate(1 - (d/r)^4)^2 / (d^2 + 1), r the glTF `range` (docs/lights-and-shading.md, "Units
  from glTF"); KHR_lights_punctual only recommends a window at the range;
- Smith's visibility in its height-correlated form (docs/lights-and-shading.md, "The BRDF"); the
  appendix writes the separable form, and the two differ at grazing angles;
- alpha = max(roughness^2, 0.002) (the renderer's floor; no scene here goes near it);
- the ambient fill, ambient x (diffuse + f0), ambient 0.03 for a glTF file (glTF has none);
- the camera: the frame's own aspect ratio (width / height), not the file's aspectRatio, and a
  pixel's ray through its centre (OpenGL's rasterization rule);
- the 8-bit output: exposure 2^EV, Reinhard per channel, the sRGB transfer function, rounded
  (renderer/reference/tonemap_reference.h, docs/lights-and-shading.md "Exposure");
- shadows (`--shadows rays`, issue 62): a light counts at a point only where nothing lies strictly
  between them, on the segment to a point or spot light's position, or on a ray towards a
  directional light longer than the scene; every surface casts from both sides (the renderer's
  rays are two-sided, while its rasterization culls back faces). glTF has no shadows; the rays are
  the renderer's feature, so this frame is what they must give on the exact shapes. A rectangle or
  sphere never hides a light from a point on itself where it faces the light, so a point's own
  surface is not tested (the renderer moves its ray's origin off the surface instead).

Everything is numpy, vectorised over the pixels, in float64.
"""
import math
from dataclasses import dataclass, field

import numpy as np

AMBIENT = 0.03            # Renderer convention: the fill of a glTF file's frame (FrameSettings::ambient)
MIN_ALPHA = 0.002         # Renderer convention: GGX's alpha floor (ML_GGX_MIN_ALPHA)


def normalize(v):
    v = np.asarray(v, dtype=np.float64)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


@dataclass
class Material:
    """glTF pbrMetallicRoughness factors, no textures; `extensions` the material's glTF extensions
    as the file writes them (shade() models none: check_material_extensions.py shades those)."""
    base: tuple = (0.8, 0.8, 0.8)
    metallic: float = 0.0
    roughness: float = 0.5
    extensions: dict = field(default_factory=dict)


@dataclass
class Rect:
    """A one-sided rectangle: centre c, half-edge vectors t1 and t2 (orthogonal); its front side
    faces n = t1 x t2 / |t1 x t2| (glTF's counter-clockwise front faces, culled from behind as a
    single-sided material's are)."""
    centre: tuple
    t1: tuple
    t2: tuple
    material: Material

    @property
    def normal(self):
        return normalize(np.cross(self.t1, self.t2))


@dataclass
class Sphere:
    centre: tuple
    radius: float
    material: Material


def box_faces(centre, half, material):
    """The six outward-facing rectangles of an axis-aligned box (centre, half-sizes)."""
    c, h = np.asarray(centre, float), np.asarray(half, float)
    faces = []
    for axis in range(3):
        a1, a2 = (axis + 1) % 3, (axis + 2) % 3          # e_a1 x e_a2 = e_axis
        for sign in (1.0, -1.0):
            t1, t2 = np.zeros(3), np.zeros(3)
            t1[a1] = h[a1]
            t2[a2] = sign * h[a2]                          # flips the normal with the face
            offset = np.zeros(3)
            offset[axis] = sign * h[axis]
            faces.append(Rect(tuple(c + offset), tuple(t1), tuple(t2), material))
    return faces


@dataclass
class Light:
    """A KHR_lights_punctual light as the file states it: colour times intensity (candela for point
    and spot, lux for directional), the range (0: none given), the direction it points in (spot,
    directional) and the spot's cone angles in radians."""
    type: str                      # point, spot, directional
    color: tuple = (1.0, 1.0, 1.0)
    intensity: float = 1.0
    position: tuple = (0.0, 0.0, 0.0)
    direction: tuple = (0.0, -1.0, 0.0)
    range: float = 0.0
    inner: float = 0.0
    outer: float = math.pi / 4.0


@dataclass
class Camera:
    """A glTF perspective camera: its node's position and rotation (unit quaternion x, y, z, w);
    it looks down the node's -z with +y up."""
    position: tuple
    rotation: tuple
    yfov: float
    znear: float = 0.1
    zfar: float = 100.0

    def basis(self):
        x, y, z, w = np.asarray(self.rotation, float) / np.linalg.norm(self.rotation)
        rot = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])
        return rot[:, 0], rot[:, 1], rot[:, 2]       # right, up, back (+z; the view is along -z)


@dataclass
class Scene:
    name: str
    camera: Camera
    rects: list = field(default_factory=list)
    spheres: list = field(default_factory=list)
    lights: list = field(default_factory=list)
    ambient: float = AMBIENT

    def surfaces(self):
        """Every surface, rectangles then spheres: the index is the surface id of the frame."""
        return list(self.rects) + list(self.spheres)


def quaternion_looking(direction, up_hint=(0.0, 1.0, 0.0)):
    """The unit quaternion (x, y, z, w) of a node whose -z points along `direction`, its +y as near
    `up_hint` as the direction allows: how a glTF camera, spot or sun is aimed."""
    back = -normalize(direction)
    up_hint = np.asarray(up_hint, float)
    if abs(np.dot(back, normalize(up_hint))) > 0.99:
        up_hint = np.array([0.0, 0.0, -1.0])
    right = normalize(np.cross(up_hint, back))
    up = np.cross(back, right)
    m = np.column_stack([right, up, back])
    trace = m[0, 0] + m[1, 1] + m[2, 2]
    if trace > 0:
        s = 2.0 * math.sqrt(1.0 + trace)
        q = ((m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s, 0.25 * s)
    else:
        i = int(np.argmax([m[0, 0], m[1, 1], m[2, 2]]))
        j, k = (i + 1) % 3, (i + 2) % 3
        s = 2.0 * math.sqrt(1.0 + m[i, i] - m[j, j] - m[k, k])
        q = [0.0, 0.0, 0.0, (m[k, j] - m[j, k]) / s]
        q[i] = 0.25 * s
        q[j] = (m[j, i] + m[i, j]) / s
        q[k] = (m[k, i] + m[i, k]) / s
    q = np.asarray(q)
    return tuple(float(v) for v in q / np.linalg.norm(q))


def primary_rays(camera, width, height):
    """One ray per pixel centre, rows top first: origins (3,) and unit directions (H, W, 3).
    Renderer convention: the aspect ratio is the frame's, width / height."""
    right, up, back = camera.basis()
    tan_half = math.tan(0.5 * camera.yfov)
    aspect = width / height
    x = (2.0 * (np.arange(width) + 0.5) / width - 1.0) * tan_half * aspect
    y = (1.0 - 2.0 * (np.arange(height) + 0.5) / height) * tan_half
    d = x[None, :, None] * right + y[:, None, None] * up - back
    return np.asarray(camera.position, float), normalize(d)


def cast(scene, origin, dirs):
    """Nearest hit of every ray among the scene's surfaces: distance t (inf on a miss), surface id
    (-1 on a miss), hit point and unit normal (H, W, ...)."""
    shape = dirs.shape[:-1]
    t_best = np.full(shape, np.inf)
    ids = np.full(shape, -1, dtype=np.int32)
    normals = np.zeros(shape + (3,))
    for sid, s in enumerate(scene.surfaces()):
        if isinstance(s, Rect):
            n = s.normal
            c, t1, t2 = (np.asarray(v, float) for v in (s.centre, s.t1, s.t2))
            denom = dirs @ n
            with np.errstate(divide="ignore", invalid="ignore"):
                t = np.where(denom < 0.0, np.dot(c - origin, n) / denom, np.inf)
            p = origin + np.where(np.isfinite(t), t, 0.0)[..., None] * dirs - c
            a = (p @ t1) / np.dot(t1, t1)
            b = (p @ t2) / np.dot(t2, t2)
            hit = np.isfinite(t) & (t > 0.0) & (np.abs(a) <= 1.0) & (np.abs(b) <= 1.0) & (t < t_best)
            t_best = np.where(hit, t, t_best)
            ids[hit] = sid
            normals[hit] = n
        else:
            oc = origin - np.asarray(s.centre, float)
            b = dirs @ oc
            disc = b * b - (np.dot(oc, oc) - s.radius * s.radius)
            with np.errstate(invalid="ignore"):
                t = -b - np.sqrt(disc)
            hit = (disc >= 0.0) & (t > 0.0) & (t < t_best)
            t_best = np.where(hit, t, t_best)
            ids[hit] = sid
            normals[hit] = (origin + t[hit][:, None] * dirs[hit] - np.asarray(s.centre, float)) / s.radius
    points = origin + np.where(np.isfinite(t_best), t_best, 0.0)[..., None] * dirs
    return t_best, ids, points, normals


def dot(a, b):
    return np.sum(a * b, axis=-1)


SUN_RAY_LENGTH = 1.0e4    # towards a directional light: far past every generated scene's surfaces


def segments_blocked(scene, origins, ends, own):
    """Whether any surface but the point's own (`own`: surface ids, (N,)) crosses each segment from
    origins to ends (N, 3) strictly between its two ends. Rectangles are hit from either side."""
    d = ends - origins
    blocked = np.zeros(len(origins), dtype=bool)
    for sid, s in enumerate(scene.surfaces()):
        test = (own != sid) & ~blocked
        if not test.any():
            continue
        o, dd = origins[test], d[test]
        if isinstance(s, Rect):
            n = s.normal
            c, t1, t2 = (np.asarray(v, float) for v in (s.centre, s.t1, s.t2))
            denom = dd @ n
            with np.errstate(divide="ignore", invalid="ignore"):
                t = (c - o) @ n / denom
            q = o + np.where(np.isfinite(t), t, 0.0)[:, None] * dd - c
            hit = (np.isfinite(t) & (t > 0.0) & (t < 1.0) & (np.abs(q @ t1) <= np.dot(t1, t1)) &
                   (np.abs(q @ t2) <= np.dot(t2, t2)))
        else:
            oc = o - np.asarray(s.centre, float)
            a = dot(dd, dd)
            b = dot(dd, oc)
            disc = b * b - a * (dot(oc, oc) - s.radius * s.radius)
            root = np.sqrt(np.maximum(disc, 0.0))
            near, far = (-b - root) / a, (-b + root) / a
            hit = (disc >= 0.0) & (((near > 0.0) & (near < 1.0)) | ((far > 0.0) & (far < 1.0)))
        blocked[np.flatnonzero(test)[hit]] = True
    return blocked


def ggx_brdf_times_cos(n, v, l, base, metallic, roughness):
    """glTF 2.0 appendix B for unit vectors n, v, l (N, 3) and per-pixel material arrays: the BRDF
    times N.L, with N.L <= 0 giving zero. Returns (N, 3).

      c_diff = lerp(base, black, metallic)     f0 = lerp(0.04, base, metallic)     alpha = roughness^2
      F = f0 + (1 - f0) (1 - |V.H|)^5                                   (Schlick)
      D = alpha^2 chi+(N.H) / (pi ((N.H)^2 (alpha^2 - 1) + 1)^2)      (Trowbridge-Reitz / GGX)
      V = G / (4 |N.L| |N.V|), height-correlated Smith G (renderer convention, see the module):
          V = 0.5 / (N.L sqrt((N.V)^2 (1 - alpha^2) + alpha^2) + N.V sqrt((N.L)^2 (1 - alpha^2) + alpha^2))
      f = (1 - F) c_diff / pi + F D V          (the metal-roughness material's fresnel_mix / conductor mix)
    """
    nl_pos = np.maximum(dot(n, l), 0.0)
    c_diff = base * (1.0 - metallic)[:, None]
    f0 = 0.04 * (1.0 - metallic)[:, None] + base * metallic[:, None]
    fresnel = f0 + (1.0 - f0) * schlick_weight(v, l)[:, None]
    f = (1.0 - fresnel) * c_diff / math.pi + fresnel * ggx_distribution_visibility(n, v, l, roughness)[:, None]
    return f * nl_pos[:, None]


def schlick_weight(v, l):
    """Schlick's (1 - |V.H|)^5, H the half vector: F = f0 + (f90 - f0) times this."""
    return (1.0 - np.abs(dot(v, normalize(l + v)))) ** 5


def ggx_distribution_visibility(n, v, l, roughness):
    """D x Vis of ggx_brdf_times_cos's docstring (N,), N.L clamped at 0 as there: what the
    specular lobe's Fresnel multiplies."""
    nl_pos = np.maximum(dot(n, l), 0.0)
    nv = np.abs(dot(n, v))
    nh = dot(n, normalize(l + v))
    alpha = np.maximum(roughness * roughness, MIN_ALPHA)
    a2 = alpha * alpha
    d = a2 * (nh > 0.0) / (math.pi * (nh * nh * (a2 - 1.0) + 1.0) ** 2)
    vis = 0.5 / (nl_pos * np.sqrt(nv * nv * (1.0 - a2) + a2) + nv * np.sqrt(nl_pos * nl_pos * (1.0 - a2) + a2))
    return d * vis


def range_window(d2, radius):
    """Renderer convention: the smooth falloff saturate(1 - (d/r)^4)^2 / (d^2 + 1), zero at r."""
    x2 = d2 / (radius * radius)
    w = np.clip(1.0 - x2 * x2, 0.0, 1.0)
    return np.where(d2 < radius * radius, w * w / (d2 + 1.0), 0.0)


def unbounded_radius(color):
    """Renderer convention for a light without a range: where max(c) / d^2 falls to 1/255."""
    return math.sqrt(255.0 * max(color))


@dataclass
class Frame:
    """A CPU frame: the linear HDR image (H, W, 3), rows top first; the surface id of every pixel
    (-1: background, which is black); and two masks (H, W) for each light: where it adds light
    (`reached`), and where it would but a surface stands in its way (`hidden`, with shadows only)."""
    hdr: np.ndarray
    ids: np.ndarray
    reached: list
    hidden: list


def shade(scene, width, height, shadows=False):
    """The scene's Frame, with a shadow ray per (pixel, light) that adds light when `shadows`."""
    origin, dirs = primary_rays(scene.camera, width, height)
    _, ids, points, normals = cast(scene, origin, dirs)
    surfaces = scene.surfaces()
    lit = ids >= 0
    sid = ids[lit]
    p, n = points[lit], normals[lit]
    v = -dirs[lit]
    base = np.array([s.material.base for s in surfaces], float)[sid]
    metallic = np.array([s.material.metallic for s in surfaces], float)[sid]
    roughness = np.array([s.material.roughness for s in surfaces], float)[sid]

    # The ambient fill (renderer convention): ambient x (diffuse + f0), with no 1/pi.
    diffuse = base * (1.0 - metallic)[:, None]
    f0 = 0.04 * (1.0 - metallic)[:, None] + base * metallic[:, None]
    radiance = scene.ambient * (diffuse + f0)

    reached, hidden = [], []
    for light in scene.lights:
        c = np.asarray(light.color, float) * light.intensity      # KHR_lights_punctual: color x intensity
        if light.type == "directional":
            l = np.broadcast_to(-normalize(light.direction), p.shape)
            weight = np.ones(len(p))
            target = p + SUN_RAY_LENGTH * l
        else:
            target = np.broadcast_to(np.asarray(light.position, float), p.shape)
            to_light = np.asarray(light.position, float) - p
            d2 = dot(to_light, to_light)
            l = to_light / np.sqrt(d2)[:, None]
            radius = light.range if light.range > 0.0 else unbounded_radius(c)
            weight = range_window(d2, radius)
            if light.type == "spot":
                # KHR_lights_punctual's angular attenuation: a linear ramp in the cosine between
                # the outer and the inner cone, squared; zero outside the outer cone.
                cos_theta = dot(-l, normalize(light.direction))
                cos_outer, cos_inner = math.cos(light.outer), math.cos(light.inner)
                scale = 1.0 / max(cos_inner - cos_outer, 1e-3)
                t = np.clip((cos_theta - cos_outer) * scale, 0.0, 1.0)
                weight = weight * t * t
        added = c * weight[:, None] * ggx_brdf_times_cos(n, v, l, base, metallic, roughness)
        adds = np.any(added != 0.0, axis=-1)
        blocked = np.zeros(len(p), dtype=bool)
        if shadows:
            blocked[adds] = segments_blocked(scene, p[adds], target[adds], sid[adds])
        radiance = radiance + np.where(blocked[:, None], 0.0, added)
        reached.append(np.zeros((height, width), dtype=bool))
        reached[-1][lit] = adds & ~blocked
        hidden.append(np.zeros((height, width), dtype=bool))
        hidden[-1][lit] = blocked

    frame = np.zeros((height, width, 3))
    frame[lit] = radiance
    return Frame(frame, ids, reached, hidden)


def tonemap_8bit(hdr, exposure_ev=0.0):
    """The renderer's 8-bit output (renderer convention): 2^EV, Reinhard per channel, sRGB, rounded."""
    c = np.maximum(hdr * 2.0 ** exposure_ev, 0.0)
    mapped = np.clip(c / (1.0 + c), 0.0, 1.0)
    srgb = np.where(mapped < 0.0031308, 12.92 * mapped, 1.055 * np.power(mapped, 1.0 / 2.4) - 0.055)
    return np.floor(srgb * 255.0 + 0.5).astype(np.int16)


def project(camera, point, width, height):
    """The pixel (column, row; rows top first) a world point lands on, or None behind the camera."""
    right, up, back = camera.basis()
    rel = np.asarray(point, float) - np.asarray(camera.position, float)
    z = -np.dot(rel, back)
    if z <= 0.0:
        return None
    tan_half = math.tan(0.5 * camera.yfov)
    x = np.dot(rel, right) / (z * tan_half * width / height)
    y = np.dot(rel, up) / (z * tan_half)
    return int((x + 1.0) * 0.5 * width), int((1.0 - y) * 0.5 * height)
