#!/usr/bin/python3
"""Draws the speed/accuracy chart of `pbr accuracy`: one point per variant, its cost per evaluated light-pixel pair
(median, with the p10-p90 spread as error bars) against its relative RMSE in linear HDR against the CPU reference.
Left: the first scene of the CSV (sphere-grid by default); right: the mean over every scene. The 'geometry' row
(the tessellated meshes against the exact shapes, at the reference's own shading) is drawn as a dashed line: it is
no variant's error, but the error a comparison with exact shapes would have added to every variant. Shadow rows
(shadow settings on the shadow scene, the exact variant) have their own panel, since their cost is ms per frame
(the shadow and lighting passes) rather than ns per pair: relative RMSE of the shadowed frame (squares, left axis)
and the share of pixels whose lit/shadowed state differs from the reference's shadow rays (triangles, right
axis). Transparency rows (orderings of BLEND surfaces on the transparency scene, the exact variant, no shadows) have
a panel of their own too: the transparency pass's ms per frame against the relative RMSE of the frame (diamonds, left
axis) and the share of pixels more than 2 8-bit levels off (triangles, right axis), each labelled with its frame's
ms."""
import argparse
import csv
import os
import statistics
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("plot_accuracy.py: matplotlib is missing (Debian package python3-matplotlib)")


def read(path):
    """The provenance file beside the CSV (F.provenance.txt for F.csv) as a dict, and the CSV's rows."""
    meta = {}
    base = path[:-4] if path.endswith(".csv") else path
    if os.path.exists(base + ".provenance.txt"):
        with open(base + ".provenance.txt") as f:
            for line in f:
                key, _, value = line.partition(": ")
                if value:
                    meta[key] = value.strip()
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return meta, rows


def place_labels(ax, items):
    """Annotates each (x, y, name), moving a label up or down in 9-point steps until it overlaps no earlier one
    (approximate boxes in display points), so that a cluster of close variants stays legible."""
    ax.figure.canvas.draw()
    to_points = 72.0 / ax.figure.dpi
    placed = []
    for x, y, name in sorted(items, key=lambda item: (item[1], item[0])):
        px, py = ax.transData.transform((x, y)) * to_points
        width = 4.2 * len(name)
        for dy in [4, -11, 13, -20, 22, -29, 31, -38, 40, -47, 49]:
            box = (px + 4, py + dy, px + 4 + width, py + dy + 8)
            if not any(box[0] < b[2] and b[0] < box[2] and box[1] < b[3] and b[1] < box[3] for b in placed):
                break
        placed.append(box)
        ax.annotate(name, (x, y), textcoords="offset points", xytext=(4, dy), fontsize=7,
                    arrowprops=dict(arrowstyle="-", color="0.6", linewidth=0.5) if abs(dy) > 4 else None)


def panel(ax, points, geometry, title, xlabel):
    # A variant is on the front when no other is both cheaper and more accurate.
    front = sorted(p for p in points if not any(q[0] <= p[0] and q[3] < p[3] for q in points if q is not p))
    ax.set_yscale("log")
    ax.errorbar([p[0] for p in points], [p[3] for p in points],
                xerr=[[p[0] - p[1] for p in points], [p[2] - p[0] for p in points]],
                fmt="o", color="tab:blue", ecolor="tab:gray", capsize=3, zorder=3)
    ax.plot([p[0] for p in front], [p[3] for p in front], color="tab:orange", label="speed/accuracy front")
    place_labels(ax, [(p[0], p[3], p[4]) for p in points])
    if geometry is not None and geometry > 0:
        ax.axhline(geometry, color="tab:green", linestyle="--", linewidth=1,
                   label="geometry: tessellated vs exact shapes")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("relative RMSE vs CPU reference (same triangles)")
    ax.set_yscale("log")
    ax.set_title(title, fontsize=10)
    ax.grid(True, alpha=0.3, which="both")
    ax.legend(fontsize=8, loc="best")


def is_shadow_row(row):
    # CSVs written before the shadow rows have no shadow_filter column.
    return row.get("shadow_filter", "-") != "-"


def is_transparency_row(row):
    # CSVs written before the transparency rows have no transparency column.
    return row.get("transparency", "-") != "-"


# How a panel of setting rows (shadow or transparency) plots: the time it costs along x, the frame's relative RMSE
# on the left axis and a share of pixels on the right.
SHADOW_PANEL = {
    "time": "passes_ms", "marker": "s", "colour": "tab:purple",
    "rmse_label": "relative RMSE of the shadowed frame (left)",
    "rmse_axis": "relative RMSE vs CPU reference (shadow rays)",
    "share": "misclassified_share", "share_label": "lit/shadowed state misclassified (right)",
    "share_axis": "pixels misclassified, % (outside the penumbra band)",
    "point_label": lambda r: r["variant"],
}
TRANSPARENCY_PANEL = {
    "time": "transparency_ms", "marker": "D", "colour": "tab:cyan",
    "rmse_label": "relative RMSE of the frame (left)",
    "rmse_axis": "relative RMSE vs CPU reference (exact compositing)",
    "share": "share_over_2", "share_label": "pixels more than 2 8-bit levels off (right)",
    "share_axis": "pixels more than 2 levels off, %",
    "point_label": lambda r: "%s (frame %.1f ms)" % (r["variant"], float(r["frame_ms_median"])),
}


def setting_panel(ax, rows, title, xlabel, style):
    xs = [float(r[style["time"] + "_median"]) for r in rows]
    xerr = [[x - float(r[style["time"] + "_p10"]) for x, r in zip(xs, rows)],
            [float(r[style["time"] + "_p90"]) - x for x, r in zip(xs, rows)]]
    rmse = [float(r["relative_rmse"]) for r in rows]
    share = [100.0 * float(r[style["share"]]) for r in rows]
    ax.set_yscale("log")
    rmse_points = ax.errorbar(xs, rmse, xerr=xerr, fmt=style["marker"], color=style["colour"], ecolor="tab:gray",
                              capsize=3, zorder=3, label=style["rmse_label"])
    place_labels(ax, [(x, y, style["point_label"](r)) for x, y, r in zip(xs, rmse, rows)])
    ax.set_xlabel(xlabel)
    ax.set_ylabel(style["rmse_axis"])
    ax.grid(True, alpha=0.3, which="both")
    right = ax.twinx()
    share_points, = right.plot(xs, share, "^", color="tab:red", label=style["share_label"])
    right.set_ylabel(style["share_axis"])
    right.set_ylim(bottom=0.0)
    ax.legend(handles=[rmse_points, share_points], fontsize=8, loc="upper right")
    ax.set_title(title, fontsize=10)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("csv")
    parser.add_argument("png")
    args = parser.parse_args()

    meta, all_rows = read(args.csv)
    rows = [r for r in all_rows if not is_shadow_row(r) and not is_transparency_row(r)]
    shadow_rows = [r for r in all_rows if is_shadow_row(r) and r["passes_ms_median"] != "n/a"]
    transparency_rows = [r for r in all_rows if is_transparency_row(r) and r["transparency_ms_median"] != "n/a"]
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    variants = list(dict.fromkeys(r["variant"] for r in rows if r["variant"] != "geometry"))

    def points(scene_filter):
        out = []
        for name in variants:
            rs = [r for r in rows if r["variant"] == name and scene_filter(r["scene"])]
            out.append((float(rs[0]["ns_per_pair_median"]), float(rs[0]["ns_per_pair_p10"]),
                        float(rs[0]["ns_per_pair_p90"]), statistics.mean(float(r["relative_rmse"]) for r in rs),
                        name))
        return out

    def geometry(scene_filter):
        rs = [float(r["relative_rmse"]) for r in rows if r["variant"] == "geometry" and scene_filter(r["scene"])]
        return statistics.mean(rs) if rs else None

    cpu = "llvmpipe" in meta.get("gl_renderer", "")
    xlabel = "ns per evaluated light-pixel pair (p10-p90)" + (", CPU rasterizer (llvmpipe)" if cpu else "")
    panels = 2 + bool(shadow_rows) + bool(transparency_rows)
    fig, axes = plt.subplots(1, panels, figsize=(6.5 * panels + 0.5, 5), dpi=100)
    first = scenes[0]
    panel(axes[0], points(lambda s: s == first), geometry(lambda s: s == first), first, xlabel)
    panel(axes[1], points(lambda s: True), geometry(lambda s: True), "mean over %d scenes" % len(scenes), xlabel)
    if shadow_rows:
        title = "shadow settings, exact variant: %s" % meta.get("shadow_cost_frame", "?")
        shadow_xlabel = "ms per frame, shadow + lighting passes (p10-p90)" + (
            ", CPU rasterizer (llvmpipe)" if cpu else "")
        setting_panel(axes[2], shadow_rows, title, shadow_xlabel, SHADOW_PANEL)
    if transparency_rows:
        title = "orderings of BLEND surfaces, exact variant, no shadows:\n%s" % meta.get(
            "transparency_cost_frame", "?")
        transparency_xlabel = "ms per frame, transparency pass (p10-p90)" + (
            ", CPU rasterizer (llvmpipe)" if cpu else "")
        setting_panel(axes[-1], transparency_rows, title, transparency_xlabel, TRANSPARENCY_PANEL)
    fig.suptitle("pbr accuracy: cost from %s; %s" % (meta.get("pair_cost_frame", "?"), meta.get("gl_renderer", "?")),
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(args.png)


if __name__ == "__main__":
    main()
