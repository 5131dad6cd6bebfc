# SPDX-License-Identifier: BSD-3-Clause
"""The 2008 paper's Fig. 3 for one collision: x, x'' and x' against tau with the ends marked (restitution run).

usage: scene_trajectory.py CSV PNG --ends NAME:TAU,... [--format png,pdf,svg]
"""
import argparse
import csv

import style  # first: it selects the Agg backend and sets the style

# The end names `--ends` carries (the CLI's end_name) and what each is.
END_WORDS = {"naive": style.ENDS["naive"], "delayed-recovery": style.ENDS["delayed_recovery"]}


def main():
    p = argparse.ArgumentParser()
    p.add_argument("csv")
    p.add_argument("png")
    p.add_argument("--ends", default="")
    style.add_format_argument(p)
    a = p.parse_args()
    with open(a.csv, newline="") as f:
        rows = list(csv.DictReader(f))
    tau = [float(r["tau"]) for r in rows]
    ends = [(e.split(":")[0], float(e.split(":")[1])) for e in a.ends.split(",") if e]
    fig, axes = style.figure(3, 1, height=5.2, sharex=True)
    panels = [("x", r"compression $x$ (scaled)"), ("acceleration", r"$\ddot{x}$ (scaled)"),
              ("velocity", r"$\dot{x}$ (scaled)")]
    for ax, (column, label) in zip(axes, panels):
        ax.plot(tau, [float(r[column]) for r in rows], "-")
        ax.axhline(0.0, color="grey", linewidth=0.5)
        for name, t in ends:
            ax.axvline(t, linestyle="--" if name == "delayed-recovery" else ":", color="k",
                       label=END_WORDS.get(name, name) if column == "x" else None)
        ax.set_ylabel(label)
        ax.grid(True)
    if ends:
        axes[0].legend()
    axes[-1].set_xlabel(style.axis_label("tau"))
    style.save(fig, a.png, a.format)


if __name__ == "__main__":
    main()
