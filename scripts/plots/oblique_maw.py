#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Maw, Barber & Fawcett's diagram of oblique impacts (Wear 38, 101 (1976)): the normalized outgoing
contact-point velocity psi_2 against the incoming psi_1, psi = 2(1 - nu)/(mu (2 - nu)) s/v_n (docs/oblique.md).

Usage: oblique_maw.py OBLIQUE.csv OUT.png CHI EPS --model MODEL E_STICK [--model ...] [--format png,pdf,svg]
(written by `restitution oblique --plot` and a scene's [[oblique]] section)
One curve per tangential model and initial spin (the CSV's psi_in, psi_out columns; a tangential_model column
says which model a row is of, without it every row is of the first --model), the gross-slip line
psi_2 = psi_1 - 2(1 + eps) chi of a contact that slides throughout, and each model's sticking limit
psi_2 = -e_t(mu -> inf) psi_1.
"""
import argparse
import csv

import style  # first: it selects the Agg backend and sets the style

MODELS = {
    "linear_nohistory": "LAMMPS linear (no history)",
    "linear_history": "LAMMPS linear history",
    "mindlin": "LAMMPS Mindlin",
}


def read(path, first_model):
    """The rows of the CSV as {model: {spin: [(psi_in, psi_out), ...]}}."""
    curves = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            model = curves.setdefault(row.get("tangential_model", first_model), {})
            model.setdefault(float(row["initial_spin_rad_s"]), []).append(
                (float(row["psi_in"]), float(row["psi_out"])))
    return curves


def main():
    p = argparse.ArgumentParser()
    p.add_argument("csv")
    p.add_argument("png")
    p.add_argument("chi", type=float)
    p.add_argument("eps", type=float)
    p.add_argument("--model", nargs=2, action="append", required=True, metavar=("MODEL", "E_STICK"))
    style.add_format_argument(p)
    a = p.parse_args()
    data = read(a.csv, a.model[0][0])
    fig, ax = style.figure(width=style.DOUBLE_COLUMN_IN, height=3.8)
    markers = "osd^v<>"
    spins = sorted({spin for curves in data.values() for spin in curves})
    psi = [p[0] for curves in data.values() for points in curves.values() for p in points]
    hi = max([4.0 * a.chi] + psi)
    # The diagram's shape lies within |psi_1| of a few 4 chi; grazing impacts beyond continue on the gross-slip
    # line. A spin against the slip gives psi_1 < 0, where the diagram is the mirror image.
    right = min(hi, 12.0 * a.chi)
    left = max(min([0.0] + psi), -12.0 * a.chi)
    for index, (model, e_stick) in enumerate(a.model):
        e_stick = float(e_stick)
        color = style.color(index)
        name = MODELS.get(model, model.replace("_", " "))
        for spin, points in sorted(data.get(model, {}).items()):
            points.sort()
            ax.plot([q[0] for q in points], [q[1] for q in points], "-", color=color,
                    marker=markers[spins.index(spin) % len(markers)],
                    label=name if spin == spins[0] else None)
        if e_stick == e_stick:  # not NaN
            reach = [0.0, min(right, 1.5)]  # the limit's slope at psi_1 -> 0
            ax.plot(reach, [-e_stick * v for v in reach], ls=":", color=color, lw=2,
                    label=rf"sticking limit, $e_t(\mu\to\infty)$ = {style.number(e_stick)}")
    if len(spins) > 1:
        for spin in spins:
            ax.plot([], [], ls="none", color="gray", marker=markers[spins.index(spin) % len(markers)],
                    label=rf"initial spin $\omega_0$ = {spin:g} rad/s")
    shift = 2.0 * (1.0 + a.eps) * a.chi
    ax.plot([0.0, right], [-shift, right - shift], ls="--", color="k", lw=1,
            label=rf"gross slip $\psi_2 = \psi_1 - 2(1+\varepsilon)\chi$, $\chi$ = {style.number(a.chi)}")
    mirrored = left < -shift  # the data reach the mirrored gross-slip line
    if mirrored:
        ax.plot([left, 0.0], [left + shift, shift], ls="--", color="k", lw=1)
    ax.set_xlim(left * 1.02, right * 1.02)
    top = max(2.0, right - shift, shift if mirrored else 0.0)
    bottom = min(-shift, left + shift)
    ax.set_ylim(bottom - 0.5, top + 0.5)
    if hi > right or min([0.0] + psi) < left:
        ax.text(0.98, 0.02, rf"$|\psi_1|$ up to {max(hi, -min(psi)):.3g} continue on the gross-slip line",
                transform=ax.transAxes, ha="right", va="bottom")
    ax.axhline(0.0, color="gray", lw=0.6)
    ax.set_xlabel(r"incoming $\psi_1 = \kappa\, s_1 / (\mu v_n)$, $\kappa = 2(1-\nu)/(2-\nu)$")
    ax.set_ylabel(r"outgoing $\psi_2 = \kappa\, s_2 / (\mu v_n)$")
    ax.grid(True)
    ax.legend(loc="center left", bbox_to_anchor=(1.02, 0.5))
    style.save(fig, a.png, a.format)


if __name__ == "__main__":
    main()
