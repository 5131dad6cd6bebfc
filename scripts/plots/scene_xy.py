# SPDX-License-Identifier: BSD-3-Clause
"""Plot columns of a scene's CSV table against one column (restitution run).

usage: scene_xy.py CSV PNG --x COL --y COL[,COL...] [--dashed COL,...] [--xscale log] [--yscale log]
                   [--title T] [--xlabel L] [--ylabel L] [--error COL,...] [--error-label L]
--error adds a second, log-scaled panel with the absolute values of those columns.
"""
import argparse
import csv
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {name: [float(r[name]) for r in rows] for name in rows[0]} if rows else {}


def split(text):
    return [c for c in (text or "").split(",") if c]


def finite_pairs(xs, ys, positive_x, positive_y):
    return zip(*[(x, y) for x, y in zip(xs, ys)
                 if math.isfinite(x) and math.isfinite(y) and (x > 0 or not positive_x) and (y > 0 or not positive_y)]
               ) if any(math.isfinite(y) for y in ys) else ([], [])


def main():
    p = argparse.ArgumentParser()
    p.add_argument("csv")
    p.add_argument("png")
    p.add_argument("--x", required=True)
    p.add_argument("--y", required=True)
    p.add_argument("--dashed", default="")
    p.add_argument("--points", default="")
    p.add_argument("--error", default="")
    p.add_argument("--error-label", default="|relative difference from the numerics|")
    p.add_argument("--xscale", default="linear")
    p.add_argument("--yscale", default="linear")
    p.add_argument("--title", default="")
    p.add_argument("--xlabel", default=None)
    p.add_argument("--ylabel", default="")
    a = p.parse_args()
    data = read(a.csv)
    errors = split(a.error)
    fig, axes = plt.subplots(2 if errors else 1, 1, figsize=(7, 7 if errors else 4.5), sharex=True, squeeze=False)
    top = axes[0][0]
    logx, logy = a.xscale == "log", a.yscale == "log"
    for name in split(a.y) + split(a.dashed) + split(a.points):
        style = "--" if name in split(a.dashed) else ("o" if name in split(a.points) else "-")
        xs, ys = finite_pairs(data[a.x], data[name], logx, logy)
        top.plot(list(xs), list(ys), style, label=name, markersize=3)
    top.set_xscale(a.xscale)
    top.set_yscale(a.yscale)
    top.set_ylabel(a.ylabel)
    top.set_title(a.title)
    top.grid(True, which="both", alpha=0.3)
    top.legend(fontsize=8)
    if errors:
        bottom = axes[1][0]
        for name in errors:
            xs, ys = finite_pairs(data[a.x], [abs(v) for v in data[name]], logx, True)
            bottom.plot(list(xs), list(ys), "-", label=name)
        bottom.set_yscale("log")
        bottom.set_ylabel(a.error_label)
        bottom.grid(True, which="both", alpha=0.3)
        bottom.legend(fontsize=8)
    axes[-1][0].set_xlabel(a.xlabel or a.x)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)


if __name__ == "__main__":
    main()
