# SPDX-License-Identifier: BSD-3-Clause
"""A speed-dependent damping recipe's two errors (restitution run, [[damping_check]]): top, its own error at the
set-up speed over requested eps (a line per clamp); bottom, heat maps of the physical speed dependence
eps(v)/eps(v_ref) - 1 over requested eps x impact speed, one per clamp.

usage: damping_heatmap.py CSV PNG [--format png,pdf,svg]
The CSV has requested_eps, velocity_m_s, recipe_error_at_calibration_speed_clamp_on|off,
speed_dependence_clamp_on|off (one row per point; the recipe error repeats along the speeds).
"""
import argparse
import csv
import math

import style  # first: it selects the Agg backend and sets the style
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import TwoSlopeNorm  # noqa: E402

# The clamp keeps the contact force >= 0: with it a collision ends at delayed recovery, without it at x = 0.
CLAMP = {"on": "clamp on (force ≥ 0)", "off": "clamp off"}
REQUESTED = r"requested $\varepsilon_\mathrm{req}$"


def edges(values, log):
    """Cell edges around sorted centres: midpoints (geometric on a log axis), the ends mirrored."""
    if len(values) == 1:
        return [values[0] / 2, values[0] * 2] if log else [values[0] - 0.5, values[0] + 0.5]
    if log:
        mids = [math.sqrt(a * b) for a, b in zip(values, values[1:])]
        return [values[0] ** 2 / mids[0]] + mids + [values[-1] ** 2 / mids[-1]]
    mids = [(a + b) / 2 for a, b in zip(values, values[1:])]
    return [2 * values[0] - mids[0]] + mids + [2 * values[-1] - mids[-1]]


def main():
    p = argparse.ArgumentParser()
    p.add_argument("csv")
    p.add_argument("png")
    style.add_format_argument(p)
    a = p.parse_args()
    with open(a.csv, newline="") as f:
        rows = list(csv.DictReader(f))
    eps = sorted({float(r["requested_eps"]) for r in rows})
    speeds = sorted({float(r["velocity_m_s"]) for r in rows})
    fig = plt.figure(figsize=(style.DOUBLE_COLUMN_IN, 5.6))
    top = fig.add_subplot(2, 1, 1)
    for clamp, line in (("on", "-o"), ("off", "--s")):
        by_eps = {float(r["requested_eps"]): float(r["recipe_error_at_calibration_speed_clamp_" + clamp])
                  for r in rows}
        top.plot(eps, [by_eps[e] for e in eps], line, label=CLAMP[clamp])
    top.axhline(0.0, color="grey", linewidth=0.8)
    top.set_xlabel(REQUESTED)
    top.set_ylabel(r"$\varepsilon(v_\mathrm{ref}) / \varepsilon_\mathrm{req} - 1$")
    top.legend()
    for index, clamp in enumerate(("on", "off")):
        ax = fig.add_subplot(2, 2, 3 + index)
        grid = [[math.nan] * len(eps) for _ in speeds]
        for r in rows:
            grid[speeds.index(float(r["velocity_m_s"]))][eps.index(float(r["requested_eps"]))] = float(
                r["speed_dependence_clamp_" + clamp])
        finite = [abs(v) for line in grid for v in line if math.isfinite(v)] or [1.0]
        bound = max(max(finite), 1e-12)
        mesh = ax.pcolormesh(edges(eps, False), edges(speeds, True), grid, shading="flat", cmap="RdBu_r",
                             norm=TwoSlopeNorm(vcenter=0.0, vmin=-bound, vmax=bound))
        ax.set_yscale("log")
        ax.set_xlabel(REQUESTED)
        if index == 0:
            ax.set_ylabel(style.axis_label("velocity_m_s"))
        # Which clamp a map is, inside its axes (no titles: the caption says what the figure is).
        ax.text(0.03, 0.97, CLAMP[clamp], transform=ax.transAxes, ha="left", va="top",
                bbox={"facecolor": "white", "alpha": 0.8, "linewidth": 0})
        fig.colorbar(mesh, ax=ax, label=r"$\varepsilon(v) / \varepsilon(v_\mathrm{ref}) - 1$")
    style.save(fig, a.png, a.format)


if __name__ == "__main__":
    main()
