# SPDX-License-Identifier: BSD-3-Clause
"""Plot columns of a scene's CSV table against one column (restitution run).

usage: scene_xy.py CSV PNG --x COL --y COL[,COL...] [--dashed COL,...] [--xscale log] [--yscale log]
                   [--xlabel L] [--ylabel L] [--error COL,...] [--error-label L] [--format png,pdf,svg]
--error adds a second, log-scaled panel with the absolute values of those columns. Legends say what each column
is (style.curve_label); the x axis is labelled from its column unless --xlabel is given.
"""
import argparse
import csv
import math

import style  # first: it selects the Agg backend and sets the style


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
    p.add_argument("--error-label", default=r"$|\varepsilon_\mathrm{approx} / \varepsilon - 1|$ against the numerics")
    p.add_argument("--xscale", default="linear")
    p.add_argument("--yscale", default="linear")
    p.add_argument("--xlabel", default=None)
    p.add_argument("--ylabel", default="")
    style.add_format_argument(p)
    a = p.parse_args()
    data = read(a.csv)
    errors = split(a.error)
    logx, logy = a.xscale == "log", a.yscale == "log"
    curves = split(a.y) + split(a.dashed) + split(a.points)
    # A few curves with short names fit a single column; more, or long names, take the double column (a legend
    # wider than its panel would hide the curves).
    wide = len(curves) + len(errors) > 4 or max(len(style.curve_label(c)) for c in curves) > 30
    fig, axes = style.figure(2 if errors else 1, 1, width=style.DOUBLE_COLUMN_IN if wide else style.SINGLE_COLUMN_IN,
                             height=(5.0 if errors else 2.8) if wide else (4.6 if errors else 2.6), sharex=True,
                             squeeze=False)
    top = axes[0][0]
    families = list(dict.fromkeys(style.curve_family(name) for name in curves))
    for name in curves:
        line = "--" if name in split(a.dashed) else ("o" if name in split(a.points) else "-")
        xs, ys = finite_pairs(data[a.x], data[name], logx, logy)
        # Each family has its colour; points of their own (measurements, actual = requested) are black.
        family = style.curve_family(name)
        alone = line == "o" and all(style.curve_family(c) != family for c in curves if c != name)
        color = "k" if alone else style.color(families.index(family))
        top.plot(list(xs), list(ys), line, label=style.curve_label(name), markersize=3, color=color)
    top.set_xscale(a.xscale)
    top.set_yscale(a.yscale)
    top.set_ylabel(a.ylabel)
    top.grid(True, which="both", alpha=0.3)
    style.legend(top)
    if errors:
        bottom = axes[1][0]
        for name in errors:
            xs, ys = finite_pairs(data[a.x], [abs(v) for v in data[name]], logx, True)
            family = style.curve_family(name)
            if family not in families:
                families.append(family)
            bottom.plot(list(xs), list(ys), "-", label=style.curve_label(name),
                        color=style.color(families.index(family)))
        bottom.set_yscale("log")
        bottom.set_ylabel(a.error_label)
        bottom.grid(True, which="both", alpha=0.3)
        style.legend(bottom)
    axes[-1][0].set_xlabel(a.xlabel or style.axis_label(a.x))
    style.save(fig, a.png, a.format)


if __name__ == "__main__":
    main()
