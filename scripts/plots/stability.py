#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Stability report plot: cost (steps, right-hand sides) and the error checks against zeta, both ends.

Usage: stability.py STABILITY.csv OUT.png TOLERANCE [--format png,pdf,svg]   (`restitution stability --out DIR`)
zeta = 0 has no place on a log axis and is left out of the plot (it is in the CSV).
"""
import argparse
import csv

import style  # first: it selects the Agg backend and sets the style

END_WORDS = {"naive": "naive", "delayed-recovery": "delayed recovery"}


def number(text):
    try:
        return float(text)
    except ValueError:
        return None  # an engine that failed: its column holds the reason


def main():
    p = argparse.ArgumentParser()
    p.add_argument("csv")
    p.add_argument("png")
    p.add_argument("tolerance", type=float)
    style.add_format_argument(p)
    a = p.parse_args()
    tolerance = a.tolerance
    with open(a.csv, newline="") as f:
        rows = [r for r in csv.DictReader(f) if float(r["zeta"]) > 0]
    engines = [k[: -len("_difference")] for k in rows[0] if k.endswith("_difference")]
    fig, (cost, error) = style.figure(1, 2, width=style.DOUBLE_COLUMN_IN, height=5.0, sharex=True)
    for key, marker in (("naive", "o"), ("delayed-recovery", "s")):
        end = END_WORDS[key]
        part = [r for r in rows if r["end"] == key]
        z = [float(r["zeta"]) for r in part]
        cost.loglog(z, [float(r["steps"]) for r in part], marker=marker, label=f"{end}: steps")
        cost.loglog(z, [float(r["rhs_evaluations"]) for r in part], marker=marker, ls=":",
                    label=f"{end}: right-hand sides")
        floor = tolerance * 1e-4  # exact agreement (0) drawn at the floor
        error.loglog(z, [max(float(r["self_convergence"]), floor) for r in part], marker=marker,
                     label=f"{end}: self-convergence ($T$ against $T/100$)")
        for engine in engines:
            pairs = [(zz, number(r[f"{engine}_difference"])) for zz, r in zip(z, part)]
            ok = [(zz, max(d, floor)) for zz, d in pairs if d is not None and d > 0]
            failed = [zz for zz, d in pairs if d is None]
            if ok:
                error.loglog(*zip(*ok), marker=marker, ls="--",
                             label=f"{end}: {style.ENGINES.get(engine, engine)} against production")
            if failed:
                error.loglog(failed, [tolerance] * len(failed), marker="x", ls="none", ms=10,
                             label=f"{end}: {style.ENGINES.get(engine, engine)} too much work (stiff)")
    error.axhline(tolerance, color="k", lw=0.8, label="tolerance $T$")
    cost.set_ylabel("work per solve (count)")
    error.set_ylabel("relative difference\n" r"of $\min(\varepsilon, 1-\varepsilon)$")
    for ax in (cost, error):
        ax.set_xlabel(style.ZETA)
        ax.grid(True, which="major")
        # Below the panel: inside it would hide the points, beside it narrow the panels.
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16))
    style.save(fig, a.png, a.format)


if __name__ == "__main__":
    main()
