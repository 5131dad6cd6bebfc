#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The freely cooling gas from kinetic theory: T(t)/T0 and the local exponent d ln T / d ln t.

Usage: gas_cooling.py GAS.csv OUT.png T0_J TAU0_S HAFF_EPS LAW [--format png,pdf,svg]
(written by `restitution gas --plot`)
Top: T(t)/T0 of the law's eps(v), Haff's law T0/(1 + t/tau0)^2 of the constant eps with the same initial
cooling rate, and a t^(-5/3) line through the last point. Bottom: the local exponent with -2 (Haff's
asymptote) and -5/3 (viscoelastic Hertz as the dissipation vanishes).
"""
import argparse
import csv

import style  # first: it selects the Agg backend and sets the style
import matplotlib.pyplot as plt  # noqa: E402


def main():
    p = argparse.ArgumentParser()
    p.add_argument("csv")
    p.add_argument("png")
    p.add_argument("t0", type=float)
    p.add_argument("tau0", type=float)
    p.add_argument("haff_eps", type=float)
    p.add_argument("law")
    style.add_format_argument(p)
    a = p.parse_args()
    with open(a.csv, newline="") as f:
        rows = list(csv.DictReader(f))
    t0, tau0 = a.t0, a.tau0
    t = [float(r["time_s"]) for r in rows]
    ratio = [float(r["temperature_j"]) / t0 for r in rows]
    haff = [float(r["haff_temperature_j"]) / t0 for r in rows]
    exponent = [float(r["local_exponent"]) for r in rows]
    law = a.law.replace("zeta", "ζ").replace("constant eps", "constant ε")
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(6.4, 6.4), sharex=True)
    top.loglog(t, ratio, lw=2, label=f"kinetic theory, {law}")
    top.loglog(t, haff, ls="--",
               label=rf"Haff's law, constant $\varepsilon$ = {a.haff_eps:.6g} ($\tau_0$ = {tau0:.4g} s)")
    top.loglog(t, [ratio[-1] * (x / t[-1]) ** (-5.0 / 3.0) for x in t], ls=":", color="gray",
               label=r"$t^{-5/3}$ through the last point")
    top.set_ylim(min(ratio + haff) / 2.0, 2.0)
    top.set_ylabel(r"$T(t) / T_0$")
    style.set_title(top, rf"freely cooling gas, $T_0$ = {t0:.4g} J")
    bottom.semilogx(t, exponent, lw=2, label="local exponent of the kinetic theory")
    bottom.semilogx(t, [-2.0 * x / (tau0 + x) for x in t], ls="--", label=r"Haff's law: $-2t/(\tau_0 + t)$")
    bottom.axhline(-5.0 / 3.0, color="gray", ls=":", label=r"$-5/3$ (viscoelastic, vanishing dissipation)")
    bottom.axhline(-2.0, color="k", lw=0.8, label=r"$-2$ (Haff, $t \gg \tau_0$)")
    bottom.set_ylabel(r"$d\ln T / d\ln t$")
    bottom.set_xlabel(r"time $t$ (s)")
    for ax in (top, bottom):
        ax.grid(True, which="major")
        ax.legend()
    style.save(fig, a.png, a.format)


if __name__ == "__main__":
    main()
