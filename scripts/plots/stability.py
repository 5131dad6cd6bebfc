#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Stability report plot: cost (steps, right-hand sides) and the error checks against zeta, both ends.

Usage: stability.py STABILITY.csv OUT.png TOLERANCE   (written by `restitution stability --out DIR`)
zeta = 0 has no place on a log axis and is left out of the plot (it is in the CSV).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def number(text):
    try:
        return float(text)
    except ValueError:
        return None  # an engine that failed: its column holds the reason


def main(csv_path, png_path, tolerance):
    with open(csv_path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if float(r["zeta"]) > 0]
    engines = [k[: -len("_difference")] for k in rows[0] if k.endswith("_difference")]
    fig, (cost, error) = plt.subplots(2, 1, figsize=(8, 8), sharex=True)
    for end, marker in (("naive", "o"), ("delayed-recovery", "s")):
        part = [r for r in rows if r["end"] == end]
        z = [float(r["zeta"]) for r in part]
        cost.loglog(z, [float(r["steps"]) for r in part], marker=marker, label=f"{end}: steps")
        cost.loglog(z, [float(r["rhs_evaluations"]) for r in part], marker=marker, ls=":",
                    label=f"{end}: right-hand sides")
        floor = tolerance * 1e-4  # exact agreement (0) drawn at the floor
        error.loglog(z, [max(float(r["self_convergence"]), floor) for r in part], marker=marker,
                     label=f"{end}: self-convergence (T vs T/100)")
        for engine in engines:
            pairs = [(zz, number(r[f"{engine}_difference"])) for zz, r in zip(z, part)]
            ok = [(zz, max(d, floor)) for zz, d in pairs if d is not None and d > 0]
            failed = [zz for zz, d in pairs if d is None]
            if ok:
                error.loglog(*zip(*ok), marker=marker, ls="--", label=f"{end}: {engine} vs production")
            if failed:
                error.loglog(failed, [tolerance] * len(failed), marker="x", ls="none", ms=10,
                             label=f"{end}: {engine} too much work (stiff)")
    error.axhline(tolerance, color="k", lw=0.8, label="tolerance T")
    cost.set_ylabel("work per solve")
    cost.set_title(f"restitution stability report (tolerance {tolerance:g}, method auto)")
    error.set_ylabel("relative difference of min(eps, 1-eps)")
    error.set_xlabel("zeta")
    for ax in (cost, error):
        ax.grid(True, which="major", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], float(sys.argv[3]))
