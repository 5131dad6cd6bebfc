#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The freely cooling gas from kinetic theory: T(t)/T0 and the local exponent d ln T / d ln t against t/tau0.

Usage: gas_cooling.py GAS.csv OUT.png T0_J TAU0_S HAFF_EPS (--constant-eps EPS | --law LAW --end END --zeta ZETA
       --reference-speed V_M_S) [--format png,pdf,svg]   (written by `restitution gas --plot` and [[gas]])
Top: T(t)/T0 of the law's eps(v) and Haff's law T0/(1 + t/tau0)^2 of the constant eps with the same initial
cooling rate; for viscoelastic Hertz also a t^(-5/3) line through the last point. Bottom: the local exponent with
-2 (Haff's asymptote) and, for viscoelastic Hertz, -5/3 (its asymptote as the dissipation vanishes). The time axis
is t/tau0 (Haff's time): it starts at the decade in which T/T0 has fallen by 1 %, where the cooling shows.
"""
import math

import style  # first: it selects the Agg backend and sets the style

VISCOELASTIC = "viscoelastic-hertz"


def law_words(a):
    """The law in the legend: its name and numbers to 4 significant digits (the CSV and JSON carry all)."""
    if a.constant_eps is not None:
        return rf"constant $\varepsilon$ = {style.number(a.constant_eps)}"
    end = "naive end" if a.end == "naive" else "delayed recovery"
    return (rf"{style.LAWS.get(a.law, a.law.replace('-', ' '))}, $\zeta$ = {style.number(a.zeta)} at "
            rf"{style.number(a.reference_speed)} m/s, {end}")


def first_shown(x, ratio):
    """Where the time axis starts: the decade in which T/T0 first falls below 0.99, not before the data."""
    cooled = next((xi for xi, r in zip(x, ratio) if r < 0.99), x[-1])
    return max(x[0], 10.0 ** math.floor(math.log10(cooled)))


def main():
    p = style.table_figure_parser()
    p.add_argument("t0", type=float)
    p.add_argument("tau0", type=float)
    p.add_argument("haff_eps", type=float)
    p.add_argument("--constant-eps", type=float)
    p.add_argument("--law")
    p.add_argument("--end")
    p.add_argument("--zeta", type=float)
    p.add_argument("--reference-speed", type=float)
    a = p.parse_args()
    if a.constant_eps is None and None in (a.law, a.end, a.zeta, a.reference_speed):
        p.error("give --constant-eps, or --law, --end, --zeta and --reference-speed")
    rows = [r for r in style.read_rows(a.csv) if float(r["time_s"]) > 0]  # t = 0 has no place on a log axis
    t0, tau0 = a.t0, a.tau0
    x = [float(r["time_s"]) / tau0 for r in rows]
    ratio = [float(r["temperature_j"]) / t0 for r in rows]
    haff = [float(r["haff_temperature_j"]) / t0 for r in rows]
    exponent = [float(r["local_exponent"]) for r in rows]
    viscoelastic = a.constant_eps is None and a.law == VISCOELASTIC
    fig, (top, bottom) = style.figure(2, 1, width=style.DOUBLE_COLUMN_IN, height=4.8, sharex=True)
    top.loglog(x, ratio, lw=2, label=f"kinetic theory, {law_words(a)}")
    top.loglog(x, haff, ls="--", color=style.color(1),
               label=rf"Haff's law, constant $\varepsilon$ = {style.number(a.haff_eps)}")
    if viscoelastic:
        top.loglog(x, [ratio[-1] * (xi / x[-1]) ** (-5.0 / 3.0) for xi in x], ls=":", color="gray",
                   label=r"$t^{-5/3}$ through the last point")
    top.set_ylim(min(ratio + haff) / 2.0, 2.0)
    top.set_ylabel(r"$T(t) / T_0$")
    bottom.semilogx(x, exponent, lw=2, label="local exponent of the kinetic theory")
    bottom.semilogx(x, [-2.0 * xi / (1.0 + xi) for xi in x], ls="--", color=style.color(1),
                    label=r"Haff's law: $-2t/(\tau_0 + t)$")
    if viscoelastic:
        bottom.axhline(-5.0 / 3.0, color="gray", ls=":", label=r"$-5/3$ (viscoelastic, vanishing dissipation)")
    bottom.axhline(-2.0, color="k", lw=0.8, label=r"$-2$ (Haff, $t \gg \tau_0$)")
    bottom.set_ylim(min(exponent + [-2.0]) - 0.15, max(exponent + [0.0]) + 0.1)
    bottom.set_ylabel(r"$d\ln T / d\ln t$")
    bottom.set_xlabel(rf"$t / \tau_0$ (scaled; $\tau_0$ = {style.number(tau0)} s, $T_0$ = {style.number(t0)} J)")
    bottom.set_xlim(first_shown(x, ratio), x[-1])
    for ax in (top, bottom):
        ax.grid(True, which="major")
        ax.legend(loc="lower left")
    style.save(fig, a.png, a.format)


if __name__ == "__main__":
    main()
