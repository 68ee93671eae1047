#!/usr/bin/python3
"""Draws the speed/accuracy front of `pbr accuracy`: one point per variant, lighting time (median over the
scenes) against relative RMSE in linear HDR (mean over the scenes), the Pareto-optimal variants joined."""
import argparse
import csv
import statistics
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("plot_accuracy.py: matplotlib is missing (Debian package python3-matplotlib)")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("csv")
    parser.add_argument("png")
    args = parser.parse_args()

    rows = {}
    with open(args.csv, newline="") as f:
        for r in csv.DictReader(f):
            rows.setdefault(r["variant"], []).append(r)
    points = []
    for name, rs in rows.items():
        time = statistics.median(float(r["lighting_ms"]) for r in rs)
        error = statistics.mean(float(r["relative_rmse"]) for r in rs)
        points.append((time, error, name))

    # A variant is on the front when no other is both faster and more accurate.
    front = sorted(p for p in points if not any(q[0] <= p[0] and q[1] < p[1] for q in points if q is not p))
    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=100)
    ax.scatter([p[0] for p in points], [p[1] for p in points], color="tab:blue", zorder=3)
    ax.plot([p[0] for p in front], [p[1] for p in front], color="tab:orange", label="speed/accuracy front")
    for time, error, name in points:
        ax.annotate(name, (time, error), textcoords="offset points", xytext=(4, 4), fontsize=8)
    ax.set_xlabel("lighting pass, ms (median over scenes)")
    ax.set_ylabel("relative RMSE vs CPU reference (mean over scenes)")
    ax.set_yscale("log")
    ax.set_title("pbr accuracy: %d scenes" % len(next(iter(rows.values()))), fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.png)


if __name__ == "__main__":
    main()
