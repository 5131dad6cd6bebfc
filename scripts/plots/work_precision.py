#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Work-precision plot: worst error over the zeta set against the mean run time per solve, one curve per
engine (points: tolerances), one panel per end. Usage: work_precision.py SUMMARY_CSV OUT_PNG"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(summary_path, png_path):
    rows = list(csv.DictReader(open(summary_path)))
    ends = ["delayed-recovery", "naive"]
    fig, axes = plt.subplots(1, 2, figsize=(12, 5), sharey=True)
    for ax, end in zip(axes, ends):
        engines = sorted({r["engine"] for r in rows if r["end"] == end})
        for engine in engines:
            pts = [r for r in rows if r["end"] == end and r["engine"] == engine]
            pts.sort(key=lambda r: -float(r["tolerance"]))
            t = [float(r["mean_median_us"]) for r in pts]
            e = [max(float(r["max_error"]), 1e-17) for r in pts]
            ax.loglog(t, e, "o-", label=engine)
        ax.set_title(f"{end} end")
        ax.set_xlabel("mean run time per solve over the zeta set [µs]")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    axes[0].set_ylabel("worst error of eps / min(eps, 1-eps) over zeta in {1e-4 ... 1e4}")
    fig.suptitle("restitution: error against run time (reference: data/reference_solutions.csv)")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
