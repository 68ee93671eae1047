#!/usr/bin/python3
"""Draws one line per data column of a CSV (first column: x) into a PNG chart."""
import argparse
import csv
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("plot_csv.py: matplotlib is missing (Debian package python3-matplotlib)")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--title", default="")
    parser.add_argument("--ylabel", default="")
    parser.add_argument("--logx", action="store_true")
    parser.add_argument("--logy", action="store_true")
    args = parser.parse_args()

    with open(args.csv, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    header, data = rows[0], rows[1:]
    x = [float(r[0]) for r in data]
    fig, ax = plt.subplots(figsize=(7, 4.2), dpi=100)
    for j, name in enumerate(header[1:], start=1):
        ax.plot(x, [float(r[j]) for r in data], marker="o", label=name.replace("_", " "))
    ax.set_xlabel(header[0].replace("_", " "))
    ax.set_ylabel(args.ylabel)
    ax.set_title(args.title, fontsize=10)
    if args.logx:
        ax.set_xscale("log")
    if args.logy:
        ax.set_yscale("log")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.png)


if __name__ == "__main__":
    main()
