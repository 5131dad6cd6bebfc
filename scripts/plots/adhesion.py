#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The figures of docs/adhesion.md, from the restitution module's numbers for µm water ice (the document's §7):

* adhesion_eps.png: ε against the impact speed v for textbook JKR, JKR as LAMMPS 20220106 breaks it and a damped
  textbook JKR, each curve's sticking region (v < v_s, ε = 0) shaded in its colour;
* adhesion_loop.png: the force-overlap loop of an elastic JKR collision, F/F_c against δ/δ_c (F_c = 3πγR the
  pull-off force, δ_c = (3/4)A²/R the textbook break overlap's magnitude, A³ = 2πγR²/E*), with the snap-in at first
  touch and both break points marked.

Usage: PYTHONPATH=build/release/python /usr/bin/python3 scripts/plots/adhesion.py OUT_DIR [--format png,pdf,svg]
"""
import argparse
import math
import os

import numpy as np

import style  # first: it selects the Agg backend and sets the style

import restitution

ICE = dict(young_modulus=7e9, poisson_ratio=0.25, radius=1.5e-6, density=920.0)
GAMMA_J_M2 = 0.19
DAMPED_A_S = 5e-10  # the dissipative constant of the damped curve [s]
# (model, A [s], legend words, line style)
CURVES = (
    ("jkr", 0.0, "JKR, textbook break, elastic", "-"),
    ("jkr-lammps", 0.0, "JKR, LAMMPS 20220106 break, elastic", "--"),
    ("jkr", DAMPED_A_S, f"JKR, textbook break, $A$ = {DAMPED_A_S * 1e9:g} ns", "-."),
)


def eps_figure(material, out, formats):
    fig, ax = style.figure(width=style.DOUBLE_COLUMN_IN, height=3.6)
    speeds = np.logspace(-1, 2, 181)  # m/s
    for index, (model, a_s, words, line) in enumerate(CURVES):
        color = style.color(index)
        v_s = restitution.sticking_speed(material=material, adhesion=model, surface_energy=GAMMA_J_M2,
                                         dissipative_constant=a_s)
        grid = np.unique(np.concatenate([speeds, v_s * (1 + np.logspace(-6, -1, 25))]))
        eps = [restitution.adhesive_collision(v, material=material, adhesion=model, surface_energy=GAMMA_J_M2,
                                              dissipative_constant=a_s).eps for v in grid]
        ax.axvspan(speeds[0], v_s, color=color, alpha=0.12, lw=0)
        ax.axvline(v_s, color=color, lw=0.8, ls=":")
        ax.plot(grid, eps, line, color=color, label=rf"{words}: $v_s$ = {style.number(v_s)} m/s")
    ax.text(0.115, 0.5, "shaded: stuck ($v < v_s$, $\\varepsilon = 0$)", rotation=90,
            va="center", ha="left")
    ax.set_xscale("log")
    ax.set_xlim(speeds[0], speeds[-1])
    ax.set_ylim(-0.02, 1.02)
    ax.set_xlabel("impact speed $v$ (m/s)")
    ax.set_ylabel(r"coefficient of restitution $\varepsilon$")
    ax.grid(True, which="major")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=1)
    return style.save(fig, os.path.join(out, "adhesion_eps.png"), formats)


def branch(s):
    """The scaled JKR equilibrium branch (docs/adhesion.md §2): overlap [A²/R] and force [πwR] at s = a/A."""
    return s * s - math.sqrt(2.0) * np.sqrt(s), 4.0 / 3.0 * s ** 3 - 2.0 * math.sqrt(2.0) * s ** 1.5


def loop_figure(material, out, formats):
    forms = {model: restitution.adhesive_closed_forms(material=material, adhesion=model, surface_energy=GAMMA_J_M2)
             for model in ("jkr", "jkr-lammps")}
    r_m = material.effective_radius
    e_star = forms["jkr"]["effective_modulus_pa"]
    a_m = (2.0 * math.pi * GAMMA_J_M2 * r_m * r_m / e_star) ** (1.0 / 3.0)
    overlap_unit_m = a_m * a_m / r_m  # A²/R
    delta_c_m = 0.75 * overlap_unit_m
    f_c_n = forms["jkr"]["pull_off_force_n"]
    # The turning point of an elastic textbook collision at 2 v_s, from the solve: the branch's largest overlap.
    v_s = restitution.sticking_speed(material=material, surface_energy=GAMMA_J_M2, dissipative_constant=0.0)
    hit = restitution.adhesive_collision(2.0 * v_s, material=material, surface_energy=GAMMA_J_M2,
                                         dissipative_constant=0.0)
    s = np.linspace(0.5, 2.0, 4001)
    delta, force = branch(s)
    s = s[delta <= hit.max_compression_m / overlap_unit_m]
    delta, force = branch(s)
    force_scaled = force * math.pi * 2.0 * GAMMA_J_M2 * r_m / f_c_n  # πwR → F_c
    delta_scaled = delta * overlap_unit_m / delta_c_m

    fig, ax = style.figure(width=style.SINGLE_COLUMN_IN, height=4.0)
    ax.axhline(0.0, color="gray", lw=0.6)
    ax.axvline(0.0, color="gray", lw=0.6)
    ax.plot(delta_scaled, force_scaled, "-", color="k", label="JKR equilibrium branch (in and out)")
    ax.plot([-1.3, 0.0], [0.0, 0.0], "-", color=style.color(2), lw=2, label="approach, no contact")
    snap = -8.0 / 9.0
    ax.annotate("", xy=(0.0, snap), xytext=(0.0, 0.0),
                arrowprops=dict(arrowstyle="->", color=style.color(2), lw=1.2))
    ax.plot([0.0], [snap], "o", color=style.color(2), label=r"snap-in: $F = -\frac{8}{9}F_c$ at $\delta = 0$")
    for index, (model, words, marker) in enumerate((("jkr", "textbook break", "D"),
                                                    ("jkr-lammps", "LAMMPS break", "s"))):
        d_b = forms[model]["break_overlap_m"] / delta_c_m
        f_b = np.interp(d_b, delta_scaled, force_scaled)  # the overlap rises along the branch for s >= 1/2
        color = style.color(index)
        ax.plot([d_b], [f_b], marker, color=color, ms=5,
                label=rf"{words}: $\delta/\delta_c$ = {style.number(d_b, 3)}, $F/F_c$ = {style.number(f_b, 3)}")
        ax.annotate("", xy=(d_b, 0.0), xytext=(d_b, f_b), arrowprops=dict(arrowstyle="->", color=color, lw=1.0))
    ax.set_xlim(-1.3, max(delta_scaled) * 1.05)
    ax.text(0.03, 0.97, "$F_c = 3\\pi\\gamma R$\n$\\delta_c = \\frac{3}{4}A^2/R$\n$A^3 = 2\\pi\\gamma R^2/E^*$",
            transform=ax.transAxes, va="top", ha="left")
    ax.set_xlabel(r"overlap $\delta/\delta_c$ (scaled)")
    ax.set_ylabel(r"force $F/F_c$ (scaled)")
    ax.grid(True)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=1)
    return style.save(fig, os.path.join(out, "adhesion_loop.png"), formats)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("out_dir")
    style.add_format_argument(p)
    a = p.parse_args()
    material = restitution.Material(**ICE)
    for path in eps_figure(material, a.out_dir, a.format) + loop_figure(material, a.out_dir, a.format):
        print(path)


if __name__ == "__main__":
    main()
