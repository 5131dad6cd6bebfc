"""Heat map of a damping recipe's relative error over requested eps x impact speed (restitution run, [[damping_check]]).

usage: damping_heatmap.py CSV PNG [--title T]
The CSV has requested_eps, velocity_m_s, relative_error_clamp_on, relative_error_clamp_off (one row per point).
"""
import argparse
import csv
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import TwoSlopeNorm  # noqa: E402


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
    p.add_argument("--title", default="")
    a = p.parse_args()
    with open(a.csv, newline="") as f:
        rows = list(csv.DictReader(f))
    eps = sorted({float(r["requested_eps"]) for r in rows})
    speeds = sorted({float(r["velocity_m_s"]) for r in rows})
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), sharey=True)
    for ax, clamp in zip(axes, ("on", "off")):
        grid = [[math.nan] * len(eps) for _ in speeds]
        for r in rows:
            grid[speeds.index(float(r["velocity_m_s"]))][eps.index(float(r["requested_eps"]))] = float(
                r["relative_error_clamp_" + clamp])
        finite = [abs(v) for line in grid for v in line if math.isfinite(v)] or [1.0]
        bound = max(max(finite), 1e-12)
        mesh = ax.pcolormesh(edges(eps, False), edges(speeds, True), grid, shading="flat", cmap="RdBu_r",
                             norm=TwoSlopeNorm(vcenter=0.0, vmin=-bound, vmax=bound))
        ax.set_yscale("log")
        ax.set_xlabel("requested eps")
        ax.set_title("clamp " + clamp)
        fig.colorbar(mesh, ax=ax, label="(actual - requested) / requested")
    axes[0].set_ylabel("impact speed v [m/s]")
    fig.suptitle(a.title)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)


if __name__ == "__main__":
    main()
