#!/usr/bin/python3
"""Charts of a `pbr bench` CSV: frame time against light count (log-log, one line per culling mode x shading
model), per-pass stacked bars per configuration, and the speedup of clustered culling over brute force.

Titles carry the GL renderer from the provenance file beside the CSV (F.provenance.txt), and say so when the
times are CPU-rasterizer times (llvmpipe). Skipped configurations are left out of the lines and bars and named in the legends."""
import argparse
import csv
import os
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import NullFormatter, ScalarFormatter
except ImportError:
    sys.exit("plot_bench.py: matplotlib is missing: install the Debian package python3-matplotlib "
             "(scripts/install-deps.sh does)")

FRAME_COLUMNS = ("frame", "cpu_frame")
SHORT_MODEL = {"pbr": "PBR", "blinn-phong": "B-P"}


def read_provenance(csv_path):
    """The "key: value" lines of the provenance file `pbr` writes beside a CSV (F.provenance.txt for F.csv)."""
    base = csv_path[:-4] if csv_path.endswith(".csv") else csv_path
    provenance = {}
    if os.path.exists(base + ".provenance.txt"):
        with open(base + ".provenance.txt") as f:
            for line in f:
                key, _, value = line.partition(":")
                if value:
                    provenance[key.strip()] = value.strip()
    return provenance


def read_bench_csv(path):
    """Returns (provenance dict, header, rows as dicts) of a CSV written by `pbr bench --csv`."""
    provenance = read_provenance(path)
    with open(path, newline="") as f:
        lines = [line for line in f if line.strip()]
    reader = csv.DictReader(lines)
    rows = list(reader)
    if not rows:
        sys.exit(f"plot_bench.py: {path} has no configurations")
    return provenance, reader.fieldnames, rows


def number(text):
    """The value of a cell, or None for "n/a" and "skipped"."""
    try:
        return float(text)
    except ValueError:
        return None


def ok(row):
    return row["status"] == "ok"


def series_keys(rows):
    keys = []
    for r in rows:
        if (r["culling"], r["model"]) not in keys:
            keys.append((r["culling"], r["model"]))
    return keys


def pass_names(header):
    names = [c[: -len("_median_ms")] for c in header if c.endswith("_median_ms")]
    return [n for n in names if n not in FRAME_COLUMNS]


def subtitle(provenance):
    renderer = provenance.get("gl_renderer", "unknown renderer")
    note = "llvmpipe: CPU times" if "llvmpipe" in renderer else provenance.get("timing_mode", "")
    return f"{renderer} - {note}"


def title(provenance, what):
    scene, size = provenance.get("scene", "?"), provenance.get("size", "?")
    return f"{scene} {size}: {what}\n{subtitle(provenance)}"


def skipped_note(rows, culling, model):
    lights = [r["lights"] for r in rows if r["culling"] == culling and r["model"] == model and not ok(r)]
    return f" ({', '.join(lights)} skipped)" if lights else ""


def light_count_axis(ax, rows):
    """Log-scale x axis ticked at the measured light counts, written out in full."""
    ax.set_xscale("log")
    ax.set_xticks(sorted({int(r["lights"]) for r in rows if int(r["lights"]) > 0}))
    ax.xaxis.set_major_formatter(ScalarFormatter())
    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.set_xlabel("point lights")


def plain_log_y(ax):
    ax.set_yscale("log")
    ax.yaxis.set_major_formatter(ScalarFormatter())


def plot_frame_time(provenance, rows, path, dpi):
    fig, ax = plt.subplots(figsize=(7, 4.4), dpi=dpi)
    for culling, model in series_keys(rows):
        points = [r for r in rows if r["culling"] == culling and r["model"] == model and ok(r)
                  and int(r["lights"]) > 0]
        x = [int(r["lights"]) for r in points]
        y = [float(r["frame_median_ms"]) for r in points]
        err = [[v - float(r["frame_p10_ms"]) for v, r in zip(y, points)],
               [float(r["frame_p90_ms"]) - v for v, r in zip(y, points)]]
        ax.errorbar(x, y, yerr=err, marker="o", capsize=3,
                    linestyle="--" if culling == "none" else "-",
                    label=f"{culling} / {model}{skipped_note(rows, culling, model)}")
    light_count_axis(ax, rows)
    plain_log_y(ax)
    ax.set_ylabel("frame time, median ms (bars: p10-p90)")
    ax.set_title(title(provenance, "frame time vs light count"), fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def plot_passes(provenance, header, rows, path, dpi):
    passes = pass_names(header)
    modes = list(dict.fromkeys(r["culling"] for r in rows))
    fig, axes = plt.subplots(1, len(modes), figsize=(4.2 * len(modes) + 1.0, 4.6), dpi=dpi, squeeze=False)
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for ax, culling in zip(axes[0], modes):
        configs = [r for r in rows if r["culling"] == culling]
        labels = [f"{r['lights']}\n{SHORT_MODEL.get(r['model'], r['model'])}" for r in configs]
        bottoms = [0.0] * len(configs)
        for i, name in enumerate(passes):
            heights = [number(r[f"{name}_median_ms"]) or 0.0 for r in configs]
            if not any(heights):
                continue
            ax.bar(range(len(configs)), heights, bottom=bottoms, color=colors[i % len(colors)], label=name)
            bottoms = [b + h for b, h in zip(bottoms, heights)]
        for j, r in enumerate(configs):
            if not ok(r):
                ax.text(j, 0, "skipped", rotation=90, ha="center", va="bottom", fontsize=7, color="gray")
        ax.set_xticks(range(len(configs)))
        ax.set_xticklabels(labels, fontsize=7)
        ax.set_title(f"culling {culling}", fontsize=9)
        ax.set_ylabel("median ms per pass")
        ax.grid(True, axis="y", alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle(title(provenance, "where the frame goes (per-pass medians; "
                       + ", ".join(f"{v} = {k}" for k, v in SHORT_MODEL.items()) + ")"), fontsize=9)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def plot_speedup(provenance, rows, path, dpi):
    """Returns False when no light count has both a clustered and a brute-force measurement."""
    fig, ax = plt.subplots(figsize=(7, 4.2), dpi=dpi)
    drawn = False
    for index, model in enumerate(dict.fromkeys(r["model"] for r in rows)):
        frame = {(r["culling"], int(r["lights"])): float(r["frame_median_ms"])
                 for r in rows if r["model"] == model and ok(r)}
        x = sorted(n for (c, n) in frame if c == "clustered" and ("none", n) in frame and n > 0)
        if not x:
            continue
        y = [frame[("none", n)] / frame[("clustered", n)] for n in x]
        ax.plot(x, y, marker="o", label=model)
        for n, s in zip(x, y):
            # Alternate sides so that the labels of nearby lines do not overlap.
            ax.annotate(f"{s:.1f}x", (n, s), textcoords="offset points", xytext=(-6, 6 if index % 2 else -12),
                        ha="right", fontsize=7)
        drawn = True
    if drawn:
        light_count_axis(ax, rows)
        plain_log_y(ax)
        ax.axhline(1.0, color="gray", linewidth=0.8)
        ax.set_ylabel("brute-force frame / clustered frame")
        ax.set_title(title(provenance, "speedup of clustered culling over brute force"), fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(path)
    plt.close(fig)
    return drawn


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("csv", help="CSV written by pbr bench --csv")
    parser.add_argument("--out", default=".", help="folder for the PNG files (default: current folder)")
    parser.add_argument("--prefix", default="perf-", help="file name prefix (default perf-)")
    parser.add_argument("--dpi", type=int, default=100)
    args = parser.parse_args()

    provenance, header, rows = read_bench_csv(args.csv)
    os.makedirs(args.out, exist_ok=True)
    path = lambda name: os.path.join(args.out, f"{args.prefix}{name}.png")
    plot_frame_time(provenance, rows, path("frame-time"), args.dpi)
    plot_passes(provenance, header, rows, path("passes"), args.dpi)
    written = [path("frame-time"), path("passes")]
    if plot_speedup(provenance, rows, path("speedup"), args.dpi):
        written.append(path("speedup"))
    else:
        print("plot_bench.py: no light count has both culling modes measured: no speedup chart", file=sys.stderr)
    for p in written:
        print(f"wrote {p}")


if __name__ == "__main__":
    main()
