#!/usr/bin/env python3
"""Renders every built-in scene in a fixed set of configurations to PNG and HDR (PFM), or compares two such folders
pixel by pixel. Refactoring the frame must leave every image bit-identical:

    scripts/frame_identity.py render build/pbr before/
    ... change ...
    scripts/frame_identity.py render build/pbr after/
    scripts/frame_identity.py compare before/ after/

Exit code 0 when every image is identical, 1 otherwise (each differing image is named with its largest difference).
"""
import pathlib
import subprocess
import sys

SCENES = ["default", "sphere-grid", "light-wall", "fresnel-floor", "stress", "helmet"]
# (name, extra arguments): both shading models, both culling paths, an environment, a debug view.
CONFIGS = [
    ("pbr", []),
    ("pbr-brute", ["--culling", "none"]),
    ("blinn-phong", ["--model", "blinn-phong"]),
    ("pbr-sky", ["--environment", "sky"]),
    ("debug-clusters", ["--debug", "clusters"]),
]
SIZE = "192x108"


def render(pbr, out):
    out.mkdir(parents=True, exist_ok=True)
    for scene in SCENES:
        for name, extra in CONFIGS:
            stem = out / f"{scene}-{name}"
            cmd = [pbr, "render", "--scene", scene, "--size", SIZE, "--warmup", "1", "--frames", "1",
                   "--out", f"{stem}.png", "--hdr", f"{stem}.pfm"] + extra
            result = subprocess.run(cmd, capture_output=True, text=True)
            if result.returncode != 0:
                sys.exit(f"{' '.join(cmd)}: {result.stderr.strip()}")
            print(f"rendered {stem.name}")


def read_pixels(path):
    data = path.read_bytes()
    if path.suffix == ".pfm":
        # Header: "PF\nW H\n-1.0\n", then float32 RGB rows.
        parts = data.split(b"\n", 3)
        return parts[3]
    import matplotlib.image  # decodes PNG to floats; 8-bit codes survive exactly as k / 255
    return matplotlib.image.imread(str(path)).tobytes()


def compare(a, b):
    import numpy as np
    names = sorted(p.name for p in a.iterdir() if p.suffix in (".png", ".pfm"))
    if not names:
        sys.exit(f"{a}: no images")
    different = 0
    for name in names:
        other = b / name
        if not other.exists():
            print(f"{name}: missing in {b}")
            different += 1
            continue
        x, y = read_pixels(a / name), read_pixels(other)
        if x != y:
            dtype = np.float32
            dx, dy = np.frombuffer(x, dtype), np.frombuffer(y, dtype)
            worst = float(np.max(np.abs(dx - dy))) if dx.shape == dy.shape else float("nan")
            print(f"{name}: differs (largest difference {worst:g})")
            different += 1
    print(f"{len(names) - different} of {len(names)} images identical")
    return 1 if different else 0


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "render":
        render(sys.argv[2], pathlib.Path(sys.argv[3]))
    elif len(sys.argv) == 4 and sys.argv[1] == "compare":
        sys.exit(compare(pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])))
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
