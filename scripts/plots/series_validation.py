#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Plot of `restitution series validate`: the 2008 paper's Fig. 1 (eps against zeta, both ends, solver with
the series) and the relative error of eps and of 1 - eps of every approximation (log scales).

usage: series_validation.py series_validation.csv out.png [--format png,pdf,svg]
"""
import argparse
import csv

import style  # first: it selects the Agg backend and sets the style


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    columns = {name: [float(r[name]) for r in rows] for name in rows[0]}
    names = [c[: -len("_rel_err_eps")] for c in rows[0] if c.endswith("_rel_err_eps")]
    return columns, names


def clipped(values, floor=1e-17):
    return [max(v, floor) if v == v else float("nan") for v in values]


def main():
    p = argparse.ArgumentParser()
    p.add_argument("csv")
    p.add_argument("png")
    style.add_format_argument(p)
    a = p.parse_args()
    col, names = read(a.csv)
    zeta = col["zeta"]
    fig, (top, mid, bottom) = style.figure(3, 1, width=style.DOUBLE_COLUMN_IN, height=8.0, sharex=True)

    top.plot(zeta, col["naive_eps"], "-", color="k", lw=2, label="numerics, " + style.ENDS["naive"])
    top.plot(zeta, col["delayed_recovery_eps"], "-", color=style.color(0), lw=2,
             label="numerics, " + style.ENDS["delayed_recovery"])
    series_styles = {"naive-series:published": ("k", "o"), "delayed-recovery-series:published": (style.color(0), "s")}
    for name, (color, marker) in series_styles.items():
        if name + "_eps" in col:
            top.plot(zeta[::3], col[name + "_eps"][::3], color=color, marker=marker, ls="none", mfc="none",
                     label=style.approximation_label(name))
    top.set_xscale("log")
    top.set_ylim(0.0, 1.05)
    top.set_ylabel(style.EPS)
    top.legend(loc="lower left")

    for i, name in enumerate(names):
        line = "-" if name.startswith(("naive", "pade-1999", "simple")) else "--"
        label = style.approximation_label(name)
        mid.plot(zeta, clipped(col[name + "_rel_err_eps"]), line, color=style.color(i), label=label)
        bottom.plot(zeta, clipped(col[name + "_rel_err_one_minus_eps"]), line, color=style.color(i), label=label)
    for ax, what in ((mid, r"$\varepsilon$"), (bottom, r"$1-\varepsilon$")):
        ax.set_yscale("log")
        ax.set_ylim(1e-17, 1e2)
        for level in (1e-3, 1e-6, 1e-10):
            ax.axhline(level, color="grey", lw=0.5, ls=":")
        ax.set_ylabel("relative error of " + what)
    # One legend for both error panels, below them: inside it would hide the curves.
    bottom.legend(*mid.get_legend_handles_labels(), ncol=2, loc="upper center", bbox_to_anchor=(0.5, -0.25))
    bottom.set_xlabel(style.ZETA + " (solid: naive end, dashed: delayed recovery)")
    style.save(fig, a.png, a.format)


if __name__ == "__main__":
    main()
