#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""A gas deck's LAMMPS runs against the kinetic theory: T(t)/T0 (left) and the local exponent d ln T/d ln t
(right), points for the runs, lines for the theory, one colour per law, with Haff's -2 and the viscoelastic
-5/3. Usage: gas_compare.py CSV OUT_PNG, the CSV of `restitution gas --compare --output` (columns run, law,
time_s, temperature_j, theory_temperature_j, local_exponent, theory_local_exponent; the exponents empty at t = 0)."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def number(text):
    return float(text) if text else None


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 5))
    colours = {"viscoelastic": "tab:blue", "constant-eps": "tab:red"}
    for run in dict.fromkeys(r["run"] for r in rows):
        pts = [r for r in rows if r["run"] == run]
        law = pts[0]["law"]
        colour = colours.get(law, "tab:gray")
        t0 = float(pts[0]["temperature_j"])
        t = [float(r["time_s"]) for r in pts]
        left.loglog(t, [float(r["temperature_j"]) / t0 for r in pts], "o", ms=3, color=colour, label=f"{run} (LAMMPS)")
        left.loglog(t, [float(r["theory_temperature_j"]) / t0 for r in pts], "-", color=colour,
                    label=f"{law}: kinetic theory")
        with_exponent = [r for r in pts if r["local_exponent"]]
        te = [float(r["time_s"]) for r in with_exponent]
        right.semilogx(te, [number(r["local_exponent"]) for r in with_exponent], "o", ms=3, color=colour,
                       label=f"{run} (LAMMPS)")
        right.semilogx(te, [number(r["theory_local_exponent"]) for r in with_exponent], "-", color=colour,
                       label=f"{law}: kinetic theory")
    right.axhline(-2.0, color="k", ls=":", lw=1, label="Haff: -2")
    right.axhline(-5.0 / 3.0, color="k", ls="--", lw=1, label="viscoelastic asymptote: -5/3")
    left.set_xlabel("t [s]")
    left.set_ylabel("T(t) / T0")
    right.set_xlabel("t [s]")
    right.set_ylabel("local exponent d ln T / d ln t")
    for ax in (left, right):
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("freely cooling gas: LAMMPS against the kinetic theory with the exact eps(v)")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
