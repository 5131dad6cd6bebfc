# SPDX-License-Identifier: BSD-3-Clause
"""The 2008 paper's Fig. 3 for one collision: x, x'' and x' against tau with the ends marked (restitution run).

usage: scene_trajectory.py CSV PNG --ends NAME:TAU,... [--title T]
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    p = argparse.ArgumentParser()
    p.add_argument("csv")
    p.add_argument("png")
    p.add_argument("--ends", default="")
    p.add_argument("--title", default="")
    a = p.parse_args()
    with open(a.csv, newline="") as f:
        rows = list(csv.DictReader(f))
    tau = [float(r["tau"]) for r in rows]
    ends = [(e.split(":")[0], float(e.split(":")[1])) for e in a.ends.split(",") if e]
    fig, axes = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
    panels = [("x", "x (natural units)"), ("acceleration", "x''"), ("velocity", "x'")]
    for ax, (column, label) in zip(axes, panels):
        ax.plot(tau, [float(r[column]) for r in rows], "-")
        ax.axhline(0.0, color="grey", linewidth=0.5)
        for name, t in ends:
            ax.axvline(t, linestyle="--" if name == "delayed-recovery" else ":", color="k",
                       label=f"{name} end" if column == "x" else None)
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=8)
    axes[0].set_title(a.title)
    axes[-1].set_xlabel("tau (natural units)")
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)


if __name__ == "__main__":
    main()
