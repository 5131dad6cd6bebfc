#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The 2008 paper's Fig. 2 with the derived large-zeta laws, local slopes against zeta, and the numbers quoted
in docs/asymptotics.md (fitted exponents per range, the measured first correction of the delayed end).

Usage: asymptotics.py RESTITUTION_EXE OUT_DIR [--format png,pdf,svg]
Writes OUT_DIR/asymptotics_fig2.png, OUT_DIR/asymptotics_slopes.png (and each other format), OUT_DIR/asymptotics.json.
"""
import argparse
import json
import math
import os
import subprocess

import style  # first: it selects the Agg backend and sets the style
import numpy as np  # noqa: E402

XM = 1.5 ** (2 / 3)  # (3/2)^{2/3}
Q = 1.5 ** (1 / 3)  # sqrt(X_m)
END_WORDS = {"naive": style.ENDS["naive"], "delayed-recovery": style.ENDS["delayed_recovery"]}
LN_A = math.log(XM) + math.log(2) + 0.5 * math.log(3) - math.pi / (2 * math.sqrt(3))


def fit(exe, end, zmin, zmax, points):
    out = subprocess.run([exe, "fit", "--end", end, "--zeta-range", f"{zmin}:{zmax}:{points}", "--json"],
                         check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def delayed_law(z, terms):
    d = z ** (-5 / 3)
    lead = XM * d
    return lead if terms == 1 else lead * (1 - d * (LN_A - 2 * np.log(d) - 2.5) / Q)


def delayed_slope(z):
    d = z ** (-5 / 3)
    return -5 / 3 + (5 / 3) * d * (LN_A - 2 * np.log(d) - 2.5) / Q - (10 / 3) * d / Q


def main(exe, out_dir, formats):
    os.makedirs(out_dir, exist_ok=True)
    naive = fit(exe, "naive", 0.1, 1e5, 37)
    delayed = fit(exe, "delayed-recovery", 0.1, 1e6, 43)
    kappa = naive["derived"]["prefactor"]
    summary = {"kappa": kappa, "delayed_prefactor": XM, "fits": []}
    # Fitted exponents over ranges (what a fit by eye over a finite window returns).
    for end, ranges in (("naive", [(1, 10), (10, 1e5)]),
                        ("delayed-recovery", [(1, 10), (1, 100), (10, 100), (10, 1e3), (10, 1e6), (1e2, 1e4),
                                              (1e4, 1e6)])):
        for a, b in ranges:
            f = fit(exe, end, a, b, 9)
            summary["fits"].append({"end": end, "zeta_min": a, "zeta_max": b, "exponent_zeta": f["exponent_zeta"],
                                    "stderr": f["stderr"], "exponent_velocity": f["exponent_velocity"],
                                    "prefactor": f["prefactor"]})
    # The first correction of the delayed end, measured: (eps/(X_m z^{-5/3}) - 1) z^{5/3} = a ln z + b.
    pts = [p for p in delayed["local_slopes"] if p["zeta"] >= 1e3]
    z = np.array([p["zeta"] for p in pts])
    r = (np.array([p["eps"] for p in pts]) / (XM * z ** (-5 / 3)) - 1) * z ** (5 / 3)
    a, b = np.polyfit(np.log(z), r, 1)
    summary["delayed_correction_measured"] = {"log_coefficient": a, "constant": b, "zeta_min": 1e3}
    summary["delayed_correction_derived"] = {"log_coefficient": -10 / (3 * Q), "constant": (2.5 - LN_A) / Q}
    # Where the local slope crosses the paper's -0.331 * 5.
    zs = np.array([p["zeta"] for p in delayed["local_slopes"]])
    ss = np.array([p["slope"] for p in delayed["local_slopes"]])
    i = int(np.argmax(ss < -1.655))
    summary["paper_slope_crossing"] = float(np.exp(np.interp(-1.655, [ss[i], ss[i - 1]],
                                                             [np.log(zs[i]), np.log(zs[i - 1])])))
    with open(os.path.join(out_dir, "asymptotics.json"), "w") as f:
        json.dump(summary, f, indent=1)

    fig, axes = style.figure(1, 2, width=style.DOUBLE_COLUMN_IN, height=4.4)
    for ax, data, law, label in ((axes[0], naive, lambda zz: kappa * zz ** -5.0,
                                  rf"derived ${style.number(kappa)}\,\zeta^{{-5}}$"),
                                 (axes[1], delayed, lambda zz: delayed_law(zz, 1),
                                  r"derived $(3/2)^{2/3}\zeta^{-5/3}$")):
        zz = np.array([p["zeta"] for p in data["local_slopes"]])
        ee = np.array([p["eps"] for p in data["local_slopes"]])
        ax.loglog(zz, ee, "o", ms=4, label="numerics, " + END_WORDS[data["end"]])
        ax.loglog(zz, law(zz), "-", label=label)
        big = zz >= 10
        fz = fit(exe, data["end"], 10, zz[-1], 9)
        ax.loglog(zz[big], fz["prefactor"] * zz[big] ** fz["exponent_zeta"], "--",
                  label=rf"least squares over $\zeta \in [10, 10^{{{np.log10(zz[-1]):.0f}}}]$: "
                        rf"exponent {style.number(fz['exponent_zeta'])}")
        ax.set_ylabel(style.EPS)
        ax.grid(True)
    axes[1].loglog(zs[zs >= 10], delayed_law(zs[zs >= 10], 2), ":", label="derived, with first correction")
    anchor = 100.0
    axes[1].loglog(zs[zs >= 1], delayed_law(anchor, 2) * (zs[zs >= 1] / anchor) ** -1.655, "-.", lw=0.8,
                   label=r"paper: $\varepsilon \propto v^{-0.331}$ ($\zeta^{-1.655}$), through $\zeta = 100$")
    for ax in axes:
        ax.set_xlabel(style.ZETA)
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16))  # below: inside it would hide the points
    style.save(fig, os.path.join(out_dir, "asymptotics_fig2.png"), formats)

    fig, ax = style.figure(width=style.DOUBLE_COLUMN_IN, height=3.2)
    nz = np.array([p["zeta"] for p in naive["local_slopes"]])
    ax.loglog(nz, [max(abs(p["slope"] + 5), 1e-13) for p in naive["local_slopes"]], "o-", ms=3,
              label=r"naive end: $|s + 5|$")
    ax.loglog(zs, np.abs(ss + 5 / 3), "s-", ms=3, label=r"delayed recovery: $|s + 5/3|$")
    big = zs >= 3
    ax.loglog(zs[big], np.abs(delayed_slope(zs[big]) + 5 / 3), "--", label="delayed recovery: derived first correction")
    ax.loglog(zs, [p["error"] for p in delayed["local_slopes"]], ":", color="gray", label="error estimate")
    ax.axhline(abs(-1.655 + 5 / 3), color="k", lw=0.8, label=r"paper's $-0.331 \times 5$ against $-5/3$")
    ax.set_xlabel(style.ZETA)
    ax.set_ylabel(r"$|s - s_\infty|$, $s = d\ln\varepsilon / d\ln\zeta$")
    ax.grid(True)
    ax.legend(loc="center left", bbox_to_anchor=(1.02, 0.5))
    style.save(fig, os.path.join(out_dir, "asymptotics_slopes.png"), formats)
    print(json.dumps(summary, indent=1))


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("exe")
    parser.add_argument("out_dir")
    style.add_format_argument(parser)
    args = parser.parse_args()
    main(args.exe, args.out_dir, args.format)
