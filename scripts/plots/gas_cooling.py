#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The freely cooling gas from kinetic theory: T(t)/T0 and the local exponent d ln T / d ln t.

Usage: gas_cooling.py GAS.csv OUT.png T0_J TAU0_S HAFF_EPS LAW   (written by `restitution gas --plot`)
Top: T(t)/T0 of the law's eps(v), Haff's law T0/(1 + t/tau0)^2 of the constant eps with the same initial
cooling rate, and a t^(-5/3) line through the last point. Bottom: the local exponent with -2 (Haff's
asymptote) and -5/3 (viscoelastic Hertz as the dissipation vanishes).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main(csv_path, png_path, t0, tau0, haff_eps, law):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    t = [float(r["time_s"]) for r in rows]
    ratio = [float(r["temperature_j"]) / t0 for r in rows]
    haff = [float(r["haff_temperature_j"]) / t0 for r in rows]
    exponent = [float(r["local_exponent"]) for r in rows]
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 8), sharex=True)
    top.loglog(t, ratio, lw=2, label=f"kinetic theory, {law}")
    top.loglog(t, haff, ls="--", label=f"Haff's law, constant eps = {haff_eps:.6g} (tau0 = {tau0:.4g} s)")
    top.loglog(t, [ratio[-1] * (x / t[-1]) ** (-5.0 / 3.0) for x in t], ls=":", color="gray",
               label="t^(-5/3) through the last point")
    top.set_ylim(min(ratio + haff) / 2.0, 2.0)
    top.set_ylabel("T(t) / T0  [1]")
    top.set_title(f"freely cooling gas, T0 = {t0:.4g} J")
    bottom.semilogx(t, exponent, lw=2, label="local exponent of the kinetic theory")
    bottom.semilogx(t, [-2.0 * x / (tau0 + x) for x in t], ls="--", label="Haff's law: -2 t/(tau0 + t)")
    bottom.axhline(-5.0 / 3.0, color="gray", ls=":", label="-5/3 (viscoelastic, vanishing dissipation)")
    bottom.axhline(-2.0, color="k", lw=0.8, label="-2 (Haff, t >> tau0)")
    bottom.set_ylabel("d ln T / d ln t  [1]")
    bottom.set_xlabel("time t  [s]")
    for ax in (top, bottom):
        ax.grid(True, which="major", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5]), sys.argv[6])
