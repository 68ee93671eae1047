#!/usr/bin/env python3
"""Writes blender-export.gltf (+ .bin): a small scene as Blender's glTF exporter writes it in its default lighting
mode ("Standard": physical units), for the README and the tests.

A floor, a gold sphere, a red plastic cube and a blue glossy sphere; a sun of 3 W/m^2, a 1000 W spot light aimed
at the cube, 500 W and 200 W point lights; a 50 mm camera on a 36 mm sensor. The exporter turns Blender's watts
into glTF's photometric units with 683 lm/W: a sun's W/m^2 x 683 lux, a point or spot light's W / (4 pi) x 683 cd;
a spot of size S and blend B gets outerConeAngle S/2 and innerConeAngle S/2 (1 - B); lights without a custom
distance get no range. The camera's yfov follows from the lens for a landscape frame: 2 atan(tan(hfov/2) / aspect).

Usage: blender_export_scene.py OUT_DIR
"""

import json
import math
import os
import struct
import sys

WATTS_TO_LUMENS = 683.0


def normalize(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def quat_from_matrix(x, y, z):
    """Unit quaternion (x, y, z, w) of the rotation whose columns are the axes x, y, z."""
    m = [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]]
    t = m[0][0] + m[1][1] + m[2][2]
    if t > 0.0:
        s = 0.5 / math.sqrt(t + 1.0)
        return [(m[2][1] - m[1][2]) * s, (m[0][2] - m[2][0]) * s, (m[1][0] - m[0][1]) * s, 0.25 / s]
    i = max(range(3), key=lambda k: m[k][k])
    j, k = (i + 1) % 3, (i + 2) % 3
    s = 2.0 * math.sqrt(1.0 + m[i][i] - m[j][j] - m[k][k])
    q = [0.0] * 4
    q[i] = 0.25 * s
    q[j] = (m[j][i] + m[i][j]) / s
    q[k] = (m[k][i] + m[i][k]) / s
    q[3] = (m[k][j] - m[j][k]) / s
    return q


def looking_along(direction):
    """Rotation taking the node's -Z (where glTF cameras and lights point) to `direction`, +Y kept up."""
    back = [-c for c in normalize(direction)]
    right = normalize(cross([0.0, 1.0, 0.0], back))
    return quat_from_matrix(right, cross(back, right), back)


def looking_at(eye, target):
    return looking_along([t - e for t, e in zip(target, eye)])


class Writer:
    """Accumulates one binary buffer of vertex and index data with its views and accessors."""

    def __init__(self):
        self.data = bytearray()
        self.views, self.accessors, self.meshes = [], [], []

    def _add(self, fmt, values, count, kind, component, target, bounds=None):
        while len(self.data) % 4:
            self.data.append(0)
        offset = len(self.data)
        self.data += struct.pack("<%d%s" % (len(values), fmt), *values)
        self.views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(self.data) - offset, "target": target})
        accessor = {"bufferView": len(self.views) - 1, "componentType": component, "count": count, "type": kind}
        if bounds:
            accessor["min"], accessor["max"] = bounds
        self.accessors.append(accessor)
        return len(self.accessors) - 1

    def mesh(self, name, positions, normals, uvs, indices, material):
        flat = [c for p in positions for c in p]
        bounds = ([min(p[i] for p in positions) for i in range(3)], [max(p[i] for p in positions) for i in range(3)])
        attributes = {
            "POSITION": self._add("f", flat, len(positions), "VEC3", 5126, 34962, bounds),
            "NORMAL": self._add("f", [c for n in normals for c in n], len(normals), "VEC3", 5126, 34962),
            "TEXCOORD_0": self._add("f", [c for t in uvs for c in t], len(uvs), "VEC2", 5126, 34962),
        }
        index = self._add("H", indices, len(indices), "SCALAR", 5123, 34963)
        self.meshes.append({"name": name, "primitives": [{"attributes": attributes, "indices": index,
                                                          "material": material}]})
        return len(self.meshes) - 1


def plane(half):
    positions = [[-half, 0, half], [half, 0, half], [half, 0, -half], [-half, 0, -half]]
    return positions, [[0, 1, 0]] * 4, [[0, 1], [1, 1], [1, 0], [0, 0]], [0, 1, 2, 0, 2, 3]


def cube(half):
    positions, normals, uvs, indices = [], [], [], []
    for axis in range(3):
        for sign in (1.0, -1.0):
            n = [0.0, 0.0, 0.0]
            n[axis] = sign
            u = [0.0, 0.0, 0.0]
            u[(axis + 1) % 3] = 1.0
            v = cross(n, u)
            base = len(positions)
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                positions.append([half * (n[i] + a * u[i] + b * v[i]) for i in range(3)])
                normals.append(n)
                uvs.append([(a + 1) / 2, (b + 1) / 2])
            indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return positions, normals, uvs, indices


def uv_sphere(radius, segments=48, rings=24):
    positions, normals, uvs, indices = [], [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2.0 * math.pi * s / segments
            n = [math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi)]
            positions.append([radius * c for c in n])
            normals.append(n)
            uvs.append([s / segments, r / rings])
    for r in range(rings):
        for s in range(segments):
            a, b = r * (segments + 1) + s, (r + 1) * (segments + 1) + s
            indices += [a, b, a + 1, a + 1, b, b + 1]
    return positions, normals, uvs, indices


def material(name, base, metallic, roughness):
    return {"name": name, "doubleSided": False,
            "pbrMetallicRoughness": {"baseColorFactor": base + [1.0], "metallicFactor": metallic,
                                     "roughnessFactor": roughness}}


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: blender_export_scene.py OUT_DIR")
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)

    w = Writer()
    materials = [material("Floor", [0.8, 0.8, 0.8], 0.0, 0.6),
                 material("Gold", [1.0, 0.766, 0.336], 1.0, 0.3),
                 material("RedPlastic", [0.7, 0.08, 0.06], 0.0, 0.45),
                 material("BlueGlaze", [0.2, 0.35, 0.8], 0.0, 0.15)]
    nodes = [
        {"name": "Floor", "mesh": w.mesh("Plane", *plane(5.0), 0)},
        {"name": "GoldSphere", "mesh": w.mesh("Sphere", *uv_sphere(0.6), 1), "translation": [-1.0, 0.6, 0.0]},
        {"name": "Cube", "mesh": w.mesh("Cube", *cube(0.5), 2), "translation": [1.0, 0.5, -0.4],
         "rotation": [0.0, math.sin(math.radians(15)), 0.0, math.cos(math.radians(15))]},
        {"name": "SmallSphere", "mesh": w.mesh("Sphere.001", *uv_sphere(0.35), 3), "translation": [0.2, 0.35, 1.0]},
    ]

    # Blender's values, converted as the exporter converts them.
    spot_size, spot_blend = math.radians(40.0), 0.25
    lights = [
        {"name": "Sun", "type": "directional", "color": [1.0, 0.93, 0.82], "intensity": 3.0 * WATTS_TO_LUMENS},
        {"name": "Spot", "type": "spot", "color": [1.0, 0.85, 0.7],
         "intensity": 1000.0 / (4 * math.pi) * WATTS_TO_LUMENS,
         "spot": {"innerConeAngle": spot_size / 2 * (1 - spot_blend), "outerConeAngle": spot_size / 2}},
        {"name": "Point", "type": "point", "color": [0.5, 0.7, 1.0],
         "intensity": 500.0 / (4 * math.pi) * WATTS_TO_LUMENS},
        {"name": "Point.001", "type": "point", "color": [1.0, 0.6, 0.3],
         "intensity": 200.0 / (4 * math.pi) * WATTS_TO_LUMENS},
    ]
    spot_at = [2.5, 3.2, 2.0]
    nodes += [
        {"name": "Sun", "rotation": looking_along([0.4, -0.8, -0.45]),
         "extensions": {"KHR_lights_punctual": {"light": 0}}},
        {"name": "Spot", "translation": spot_at, "rotation": looking_at(spot_at, [1.0, 0.5, -0.4]),
         "extensions": {"KHR_lights_punctual": {"light": 1}}},
        {"name": "Point", "translation": [-2.5, 1.5, 1.5], "extensions": {"KHR_lights_punctual": {"light": 2}}},
        {"name": "Point.001", "translation": [0.5, 0.8, -2.0], "extensions": {"KHR_lights_punctual": {"light": 3}}},
    ]

    aspect = 16.0 / 9.0
    hfov = 2.0 * math.atan(36.0 / 2.0 / 50.0)
    eye = [4.5, 2.8, 5.5]
    nodes.append({"name": "Camera", "translation": eye, "rotation": looking_at(eye, [0.0, 0.5, 0.0]), "camera": 0})
    camera = {"name": "Camera", "type": "perspective",
              "perspective": {"aspectRatio": aspect, "yfov": 2.0 * math.atan(math.tan(hfov / 2.0) / aspect),
                              "znear": 0.1, "zfar": 100.0}}

    name = "blender-export"
    gltf = {
        "asset": {"generator": "Khronos glTF Blender I/O (written by pbr's scripts/blender_export_scene.py)",
                  "version": "2.0"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": lights}},
        "scene": 0,
        "scenes": [{"name": "Scene", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "cameras": [camera],
        "materials": materials,
        "meshes": w.meshes,
        "accessors": w.accessors,
        "bufferViews": w.views,
        "buffers": [{"byteLength": len(w.data), "uri": name + ".bin"}],
    }
    with open(os.path.join(out, name + ".bin"), "wb") as f:
        f.write(w.data)
    with open(os.path.join(out, name + ".gltf"), "w") as f:
        json.dump(gltf, f, indent=1)
    print(os.path.join(out, name + ".gltf"))


if __name__ == "__main__":
    main()
