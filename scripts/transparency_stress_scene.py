#!/usr/bin/env python3
"""Writes transparency-stress.json: the transparency stress case of docs/transparency.md.

1,000 BLEND quads (0.8 m square panes, alpha 0.15-0.6, random colours and orientations, single- and double-sided)
in a 12 m x 5 m x 12 m block above a floor, seen from its side so that panes overlap many deep, under 4,096 random
point lights (radius 2-4 m) over the block, as a JSON scene (`pbr render --scene DIR/transparency-stress.json`).
Seeded: the same file every run.

Usage: transparency_stress_scene.py OUT_DIR
"""

import json
import os
import random
import sys

QUADS = 1000


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    rng = random.Random(30)
    objects = [{"shape": "plane", "transform": {"scale": [60, 1, 60]},
                "material": {"base_color": 0.5, "roughness": 0.7}}]
    for _ in range(QUADS):
        objects.append({
            "shape": "plane",
            "transform": {"translate": [round(rng.uniform(-6, 6), 4), round(rng.uniform(0.5, 5.5), 4),
                                        round(rng.uniform(-6, 6), 4)],
                          # A plane is y = 0: tipped up by 60-120 degrees about x, then turned about y, it faces
                          # the camera roughly, at every slant.
                          "rotate_deg": [round(rng.uniform(60, 120), 2), round(rng.uniform(-60, 60), 2), 0],
                          "scale": 0.8},
            "material": {"base_color": [round(rng.uniform(0.1, 1.0), 3) for _ in range(3)],
                         "roughness": round(rng.uniform(0.1, 0.8), 3),
                         "alpha": round(rng.uniform(0.15, 0.6), 3), "alpha_mode": "blend",
                         "double_sided": rng.random() < 0.5}})
    scene = {
        "camera": {"position": [0, 4, 16], "target": [0, 2.8, 0], "fov_y_deg": 50, "near": 0.1, "far": 80},
        "ambient": 0.02,
        "objects": objects,
        "random_lights": {"count": 4096, "seed": 30, "bounds": [[-10, 0.3, -10], [10, 7, 10]],
                          "radius": [2, 4], "luminous_power": [1, 6]},
    }
    path = os.path.join(sys.argv[1], "transparency-stress.json")
    with open(path, "w") as out:
        json.dump(scene, out, indent=None, separators=(",", ":"))
        out.write("\n")
    print("wrote", path)


if __name__ == "__main__":
    main()
