#!/usr/bin/python3
"""Chart of `pbr bench` sweeps over the light count (make bench's many-lights sweeps): against the number of
lights, the light-assignment time per light, the frame time, the culling efficiency, the clusters holding a
surface and the GPU memory, one line per CSV (e.g. radii shrinking with the count, and fixed radii).

Usage: plot_light_count.py SWEEP.csv[=LABEL] ... --out FILE.png"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_bench import read_bench_csv, plt  # noqa: E402


def series(path):
    provenance, _, rows = read_bench_csv(path)
    rows = [r for r in rows if r["status"] == "ok" and r["culling"] == "clustered"]
    rows.sort(key=lambda r: int(r["lights"]))
    lights = [int(r["lights"]) for r in rows]
    return provenance, {
        "lights": lights,
        "assignment µs per light": [1000.0 * float(r["cluster_median_ms"]) / n for r, n in zip(rows, lights)],
        "frame ms": [float(r["frame_median_ms"]) for r in rows],
        "culling efficiency": [float(r["culling_efficiency"]) for r in rows],
        "clusters holding a surface": [int(r["active_clusters"]) for r in rows],
        "GPU MiB": [int(r["gpu_bytes"]) / 2**20 for r in rows],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", nargs="+", help="a pbr bench CSV, optionally followed by =LABEL")
    parser.add_argument("--out", required=True)
    parser.add_argument("--dpi", type=int, default=100)
    args = parser.parse_args()
    curves, renderer = [], ""
    for spec in args.csv:
        path, _, label = spec.partition("=")
        provenance, data = series(path)
        renderer = provenance.get("gl_renderer", renderer)
        curves.append((label or os.path.basename(path), data))
    quantities = [q for q in curves[0][1] if q != "lights"]
    fig, axes = plt.subplots(1, len(quantities), figsize=(4.2 * len(quantities), 3.6))
    for ax, quantity in zip(axes, quantities):
        for label, data in curves:
            ax.plot(data["lights"], data[quantity], marker="o", label=label)
        ax.set_xscale("log", base=2)
        ax.set_xlabel("lights")
        ax.set_title(quantity)
        if quantity in ("frame ms", "GPU MiB"):
            ax.set_yscale("log")
        ax.set_ylim(bottom=0 if ax.get_yscale() == "linear" else None)
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=8)
    note = " (CPU-rasterizer times)" if "llvmpipe" in renderer else ""
    fig.suptitle(f"many-lights, clustered PBR, 1280x720: {renderer}{note}", fontsize=10)
    fig.tight_layout()
    fig.savefig(args.out, dpi=args.dpi)


if __name__ == "__main__":
    main()
