#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Work-precision plot: worst error over the zeta set against the mean run time per solve, one curve per
engine (points: tolerances), one panel per end. Usage: work_precision.py SUMMARY_CSV OUT_PNG [--format png,pdf,svg]"""
import argparse
import csv

import style  # first: it selects the Agg backend and sets the style

END_WORDS = {"naive": style.ENDS["naive"], "delayed-recovery": style.ENDS["delayed_recovery"]}


def main():
    p = argparse.ArgumentParser()
    p.add_argument("summary")
    p.add_argument("png")
    style.add_format_argument(p)
    a = p.parse_args()
    with open(a.summary, newline="") as f:
        rows = list(csv.DictReader(f))
    ends = ["delayed-recovery", "naive"]
    fig, axes = style.figure(1, 2, width=style.DOUBLE_COLUMN_IN, height=3.2, sharey=True)
    for ax, end in zip(axes, ends):
        engines = sorted({r["engine"] for r in rows if r["end"] == end})
        for engine in engines:
            pts = [r for r in rows if r["end"] == end and r["engine"] == engine]
            pts.sort(key=lambda r: -float(r["tolerance"]))
            t = [float(r["mean_median_us"]) for r in pts]
            e = [max(float(r["max_error"]), 1e-17) for r in pts]
            ax.loglog(t, e, "o-", label=style.ENGINES.get(engine, engine))
        ax.set_xlabel(r"mean time per solve (µs)")
        ax.grid(True, which="both")
        ax.legend(title=END_WORDS.get(end, end))  # which end the panel is (no titles: the caption says the rest)
    axes[0].set_ylabel(r"worst error $|\Delta\varepsilon| / \min(\varepsilon, 1-\varepsilon)$")
    style.save(fig, a.png, a.format)


if __name__ == "__main__":
    main()
