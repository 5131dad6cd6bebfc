#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Maw, Barber & Fawcett's diagram of oblique impacts (Wear 38, 101 (1976)): the normalized outgoing
contact-point velocity psi_2 against the incoming psi_1, psi = 2(1 - nu)/(mu (2 - nu)) s/v_n (docs/oblique.md).

Usage: oblique_maw.py OBLIQUE.csv OUT.png CHI EPS MODEL E_STICK [--series CSV MODEL E_STICK]... [--format png,pdf,svg]
(written by `restitution oblique --plot` and a scene's [[oblique]] section)
One curve per tangential model (the CSV's psi_in, psi_out columns, one curve per initial spin), the gross-slip
line psi_2 = psi_1 - 2(1 + eps) chi of a contact that slides throughout, and each model's sticking limit
psi_2 = -e_t(mu -> inf) psi_1.
"""
import argparse
import csv

import style  # first: it selects the Agg backend and sets the style
import matplotlib.pyplot as plt  # noqa: E402

MODELS = {
    "linear_nohistory": "LAMMPS linear (no history)",
    "linear_history": "LAMMPS linear history",
    "mindlin": "LAMMPS Mindlin",
}


def read(path):
    """The rows of one CSV as (spin, psi_in, psi_out) per initial spin."""
    curves = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            curves.setdefault(float(row["initial_spin_rad_s"]), []).append(
                (float(row["psi_in"]), float(row["psi_out"])))
    return curves


def main():
    p = argparse.ArgumentParser()
    p.add_argument("csv")
    p.add_argument("png")
    p.add_argument("chi", type=float)
    p.add_argument("eps", type=float)
    p.add_argument("model")
    p.add_argument("e_stick", type=float)
    p.add_argument("--series", nargs=3, action="append", default=[], metavar=("CSV", "MODEL", "E_STICK"))
    style.add_format_argument(p)
    a = p.parse_args()
    series = [(a.csv, a.model, a.e_stick)] + [(c, m, float(e)) for c, m, e in a.series]
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    lo, hi = 0.0, 0.0
    for index, (path, model, e_stick) in enumerate(series):
        color = f"C{index}"
        name = MODELS.get(model, model.replace("_", " "))
        curves = read(path)
        for number, (spin, points) in enumerate(sorted(curves.items())):
            points.sort()
            x = [q[0] for q in points]
            y = [q[1] for q in points]
            lo, hi = min([lo] + x), max([hi] + x)
            label = name + (f", initial spin {spin:g} rad/s" if len(curves) > 1 else "")
            ax.plot(x, y, "o-", color=color, alpha=1.0 - 0.5 * number / max(1, len(curves)), label=label)
        if e_stick == e_stick:  # not NaN
            reach = [0.0, min(hi, 1.5)]  # the limit's slope at psi_1 -> 0
            ax.plot(reach, [-e_stick * v for v in reach], ls=":", color=color,
                    label=rf"{name}: sticking limit $\psi_2 = -e_t(\mu\to\infty)\,\psi_1$, $e_t$ = {e_stick:.4g}")
    line = [lo, hi]
    ax.plot(line, [v - 2.0 * (1.0 + a.eps) * a.chi for v in line], ls="--", color="k", lw=1,
            label=rf"gross slip $\psi_2 = \psi_1 - 2(1+\varepsilon)\chi$ ($\chi$ = {a.chi:.4g}, "
                  rf"$\varepsilon$ = {a.eps:.4g})")
    ax.axhline(0.0, color="gray", lw=0.6)
    ax.set_xlabel(r"incoming $\psi_1 = \kappa\, s_1 / (\mu v_n)$, $\kappa = 2(1-\nu)/(2-\nu)$")
    ax.set_ylabel(r"outgoing $\psi_2 = \kappa\, s_2 / (\mu v_n)$")
    style.set_title(ax, "Maw, Barber & Fawcett's diagram of oblique impacts (Wear 38, 101, 1976)")
    ax.grid(True)
    style.legend(ax)
    style.save(fig, a.png, a.format)


if __name__ == "__main__":
    main()
