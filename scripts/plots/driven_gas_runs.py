# SPDX-License-Identifier: BSD-3-Clause
"""The driven gas's runs against the theory (docs/gas.md, "The driven gas"): the relaxation T(t) of the viscoelastic
gas in LAMMPS (points) and the kinetic theory (lines), and the steady temperature against the bath temperature for
the viscoelastic law and its constant-eps companion, measured (error bars from block averages) and predicted.

Usage: driven_gas_runs.py OUT.png RUN_FOLDER... (each holding compare.json, the output of
`restitution gas ... --thermostat langevin ... --compare driven.log driven_constant_eps.log --json`)."""
import json
import sys

import matplotlib
import matplotlib.ticker

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import restitution  # noqa: E402

GAS = dict(radius=0.005, density=920.0, eps=0.8, velocity=2.0, packing_fraction=0.1, rms_speed=1.0, duration=1.0,
           thermostat="langevin", bath_time=2.0, a2="evolving")


def main(out, folders):
    runs = [json.load(open(f"{folder}/compare.json"))["driven_comparison"] for folder in folders]
    factor = float(np.mean([r["collision_rate_factor"] for r in runs]))
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
    for r, colour in zip(runs, ["C0", "C1", "C2"]):
        visco = next(x for x in r["runs"] if x["law"] == "viscoelastic")
        t = np.array(visco["time_s"])
        ts = visco["theory_steady_temperature_j"]
        left.plot(t, np.array(visco["temperature_j"]) / ts, "o", ms=3, color=colour,
                  label=f"LAMMPS, $T_b$ = {r['bath_temperature_j']:g} J")
        left.plot(t, np.array(visco["theory_temperature_j"]) / ts, "-", color=colour)
    left.set_xscale("log")
    left.set_yscale("log")
    left.yaxis.set_major_formatter(matplotlib.ticker.ScalarFormatter())
    left.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    left.set_yticks([0.6, 0.8, 1, 1.5, 2, 3])
    left.set_xlabel("t [s]")
    left.set_ylabel("$T / T_s$ ($T_s$ from the kinetic theory)")
    left.set_title("relaxation from $T_0$ (lines: kinetic theory, exact ε(v))")
    left.legend(fontsize=8)
    baths = np.geomspace(8e-4, 1e-1, 30)
    for law, style, label in [("viscoelastic", "-", "ε(v), theory"), ("constant-eps", "--", "constant ε, theory")]:
        extra = {} if law == "viscoelastic" else {"law": "linear-dashpot"}
        theory = [restitution.gas(**GAS, **extra, bath_temperature=b, collision_rate_factor=factor)[
            "steady_temperature_j"] for b in baths]
        right.plot(baths, np.array(theory) / baths ** (2 / 3), style, color="k", label=label)
        measured = [next(x for x in r["runs"] if x["law"] == law) for r in runs]
        tb = np.array([r["bath_temperature_j"] for r in runs])
        right.errorbar(tb, np.array([m["steady_temperature_j"] for m in measured]) / tb ** (2 / 3),
                       yerr=np.array([m["steady_temperature_error_j"] for m in measured]) / tb ** (2 / 3),
                       fmt="o" if law == "viscoelastic" else "s", mfc="none" if law != "viscoelastic" else None,
                       color="C3" if law == "viscoelastic" else "C4", label=f"LAMMPS, {label.split(',')[0]}")
    right.set_xscale("log")
    right.set_xlabel("bath temperature $T_b$ [J] ($\\tau_b$ = 2 s)")
    right.set_ylabel("$T_s / T_b^{2/3}$ [J$^{1/3}$]")
    right.set_title(f"steady state, compensated (factor {factor:.3f})")
    right.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=130)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2:])
