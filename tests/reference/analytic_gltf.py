"""Writes a cpu_reference.Scene as the glTF 2.0 file the renderer reads: each rectangle as two
triangles, each sphere as a finely tessellated UV sphere (vertex normals the sphere's own), the
camera as a perspective camera node, the lights through KHR_lights_punctual, the materials as
pbrMetallicRoughness factors (and any extensions a material carries). One mesh and one node per surface; geometry in a .bin beside the
.gltf.

A surface may carry vertices no index uses before its own in its accessors (`unused_before`), as
../shared/repro/quad_after_unused_vertices.gltf does: the layout of issue 61's repro.
"""
import json
import math
import os

import numpy as np

import cpu_reference as ref

SPHERE_SEGMENTS = (256, 128)  # longitude, latitude: the chord sags 7.5e-5 of the radius


def rect_triangles(r):
    c, t1, t2 = (np.asarray(v, float) for v in (r.centre, r.t1, r.t2))
    positions = np.array([c - t1 - t2, c + t1 - t2, c + t1 + t2, c - t1 + t2])
    normals = np.tile(r.normal, (4, 1))
    return positions, normals, np.array([0, 1, 2, 0, 2, 3])          # counter-clockwise seen from n


def sphere_triangles(s, segments=SPHERE_SEGMENTS):
    n_lon, n_lat = segments
    theta = np.linspace(0.0, math.pi, n_lat + 1)                     # from +y down
    phi = np.linspace(0.0, 2.0 * math.pi, n_lon + 1)
    st, ct = np.sin(theta)[:, None], np.cos(theta)[:, None]
    normals = np.stack([st * np.sin(phi)[None, :], np.broadcast_to(ct, (n_lat + 1, n_lon + 1)),
                        st * np.cos(phi)[None, :]], axis=-1).reshape(-1, 3)
    normals[np.abs(normals) < 1e-15] = 0.0
    positions = np.asarray(s.centre, float) + s.radius * normals
    row = n_lon + 1
    i, j = np.meshgrid(np.arange(n_lat), np.arange(n_lon), indexing="ij")
    a, b = i * row + j, (i + 1) * row + j
    # Two triangles per cell, counter-clockwise from outside; the poles' degenerate ones dropped.
    upper = np.stack([a, b, a + 1], axis=-1)[1:]
    lower = np.stack([a + 1, b, b + 1], axis=-1)[:-1]
    return positions, normals, np.concatenate([upper.reshape(-1, 3), lower.reshape(-1, 3)]).reshape(-1)


class _Buffer:
    def __init__(self):
        self.data = bytearray()
        self.views = []
        self.accessors = []

    def add(self, array, component, kind, target, minmax=False):
        while len(self.data) % 4:
            self.data.append(0)
        raw = array.tobytes()
        self.views.append({"buffer": 0, "byteOffset": len(self.data), "byteLength": len(raw), "target": target})
        self.data += raw
        accessor = {"bufferView": len(self.views) - 1, "componentType": component,
                    "count": int(array.shape[0]), "type": kind}
        if minmax:
            accessor["min"] = [float(v) for v in array.min(axis=0)]
            accessor["max"] = [float(v) for v in array.max(axis=0)]
        self.accessors.append(accessor)
        return len(self.accessors) - 1


def _light_json(light):
    out = {"type": light.type, "color": [float(c) for c in light.color], "intensity": float(light.intensity)}
    if light.type != "directional" and light.range > 0.0:
        out["range"] = float(light.range)
    if light.type == "spot":
        out["spot"] = {"innerConeAngle": float(light.inner), "outerConeAngle": float(light.outer)}
    return out


def write_gltf(scene, path, unused_before=None):
    """Writes `scene` to `path` (.gltf, with its .bin beside it). `unused_before` maps a surface
    index to positions (k, 3) placed before that surface's vertices in its accessors and never
    indexed (their normals +y)."""
    unused_before = unused_before or {}
    buf = _Buffer()
    materials, material_index, meshes, nodes = [], {}, [], []
    extensions_used = {"KHR_lights_punctual"}
    for k, surface in enumerate(scene.surfaces()):
        m = surface.material
        key = (tuple(m.base), m.metallic, m.roughness, json.dumps(m.extensions, sort_keys=True))
        if key not in material_index:
            material_index[key] = len(materials)
            materials.append({"pbrMetallicRoughness": {"baseColorFactor": [float(c) for c in m.base] + [1.0],
                                                       "metallicFactor": float(m.metallic),
                                                       "roughnessFactor": float(m.roughness)}})
            if m.extensions:
                materials[-1]["extensions"] = m.extensions
                extensions_used.update(m.extensions)
        positions, normals, indices = (rect_triangles(surface) if isinstance(surface, ref.Rect)
                                       else sphere_triangles(surface))
        extra = np.asarray(unused_before.get(k, np.zeros((0, 3))), float)
        if len(extra):
            positions = np.concatenate([extra, positions])
            normals = np.concatenate([np.tile([0.0, 1.0, 0.0], (len(extra), 1)), normals])
            indices = indices + len(extra)
        index_type, component = (np.uint16, 5123) if len(positions) < 65536 else (np.uint32, 5125)
        attributes = {"POSITION": buf.add(positions.astype(np.float32), 5126, "VEC3", 34962, minmax=True),
                      "NORMAL": buf.add(normals.astype(np.float32), 5126, "VEC3", 34962)}
        if isinstance(surface, ref.Rect) and "KHR_materials_anisotropy" in m.extensions:
            # The anisotropic lobe's frame: the rectangle's t1, bitangent n x t1 = t2's direction (w 1).
            tangent = np.append(ref.normalize(np.asarray(surface.t1, float)), 1.0)
            attributes["TANGENT"] = buf.add(np.tile(tangent, (len(positions), 1)).astype(np.float32), 5126, "VEC4", 34962)
        index_accessor = buf.add(indices.astype(index_type), component, "SCALAR", 34963)
        meshes.append({"primitives": [{"attributes": attributes, "indices": index_accessor,
                                       "material": material_index[key]}]})
        nodes.append({"mesh": len(meshes) - 1})

    lights = []
    for light in scene.lights:
        node = {"extensions": {"KHR_lights_punctual": {"light": len(lights)}}}
        if light.type != "directional":
            node["translation"] = [float(v) for v in light.position]
        if light.type != "point":
            node["rotation"] = list(ref.quaternion_looking(light.direction))
        lights.append(_light_json(light))
        nodes.append(node)

    cam = scene.camera
    nodes.append({"camera": 0, "translation": [float(v) for v in cam.position],
                  "rotation": [float(v) for v in cam.rotation]})

    bin_name = os.path.splitext(os.path.basename(path))[0] + ".bin"
    with open(os.path.join(os.path.dirname(path), bin_name), "wb") as f:
        f.write(bytes(buf.data))
    doc = {
        "asset": {"version": "2.0", "generator": "manylights tests/reference/analytic_gltf.py"},
        "extensionsUsed": sorted(extensions_used),
        "extensions": {"KHR_lights_punctual": {"lights": lights}},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "cameras": [{"type": "perspective",
                     "perspective": {"yfov": float(cam.yfov), "znear": float(cam.znear), "zfar": float(cam.zfar),
                                     "aspectRatio": 16.0 / 9.0}}],
        "materials": materials,
        "meshes": meshes,
        "buffers": [{"byteLength": len(buf.data), "uri": bin_name}],
        "bufferViews": buf.views,
        "accessors": buf.accessors,
    }
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)
