# SPDX-License-Identifier: BSD-3-Clause
"""Plot a scene's [[fit]] (restitution run): the measured eps with error bars, each law's eps(v) with its 95 %
band, and below the residuals of each law against the speed.

usage: fit_data.py DATA_CSV PNG --curves CURVES_CSV [--data-label L] [--format png,pdf,svg]
(written by `restitution fit-data --plot` and a scene's [[fit]])
DATA_CSV: v, eps, sigma (nan without), model_<law>, residual_<law>; CURVES_CSV: v, eps_<law>, low_<law>,
high_<law> (the band's edges; nan where a bound lies beyond the checked range).
"""
import argparse
import csv
import math

import style  # first: it selects the Agg backend and sets the style


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {name: [float(r[name]) for r in rows] for name in rows[0]} if rows else {}


def main():
    p = argparse.ArgumentParser()
    p.add_argument("data")
    p.add_argument("png")
    p.add_argument("--curves", required=True)
    p.add_argument("--data-label", default="measured", help="what the data points are")
    style.add_format_argument(p)
    a = p.parse_args()
    data = read(a.data)
    curves = read(a.curves)
    laws = [c[len("eps_"):] for c in curves if c.startswith("eps_")]
    fig, (top, bottom) = style.figure(2, 1, width=style.DOUBLE_COLUMN_IN, height=4.6, sharex=True,
                                      gridspec_kw={"height_ratios": [3, 2]})
    sigma = data["sigma"]
    has_sigma = all(math.isfinite(s) for s in sigma)
    top.errorbar(data["v"], data["eps"], yerr=sigma if has_sigma else None, fmt="o", color="black", ms=4,
                 capsize=2, label=a.data_label + (r" $\pm\,\sigma$" if has_sigma else r" (no $\sigma$ given)"), zorder=3)
    for i, law in enumerate(laws):
        color = style.color(i)
        # Line styles differ so that tied laws (Tsuji and the dash-pot fit the same constant) stay visible.
        top.plot(curves["v"], curves["eps_" + law], color=color, linestyle=["-", "--", "-.", ":"][i % 4],
                 label=style.law_label(law) + ", 95 % band")
        low, high = curves["low_" + law], curves["high_" + law]
        pairs = [(v, lo, hi) for v, lo, hi in zip(curves["v"], low, high) if math.isfinite(lo) and math.isfinite(hi)]
        if pairs:
            vs, los, his = zip(*pairs)
            top.fill_between(vs, los, his, color=color, alpha=0.2, linewidth=0)
        if "residual_" + law in data:
            bottom.plot(data["v"], data["residual_" + law], "o", color=color, ms=3)
    bottom.axhline(0.0, color="gray", linewidth=0.8)
    top.set_xscale("log")
    top.set_ylabel(style.EPS)
    top.legend()
    bottom.set_xlabel(style.axis_label("v"))
    bottom.set_ylabel(r"residual $\varepsilon - \varepsilon_\mathrm{law}$")
    bottom.grid(True)
    top.grid(True, which="both")
    style.save(fig, a.png, a.format)


if __name__ == "__main__":
    main()
