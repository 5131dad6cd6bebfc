#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""eps(v) of two colliding ice spheres at both ends of the collision, with the measurements' power law, to a PNG.

Usage: PYTHONPATH=build/release/python /usr/bin/python3 examples/python/eps_vs_velocity.py [OUT.png]
(default out/eps_vs_velocity.png).

The material is ice as the 1999 paper has it (Ramirez, Poschel, Brilliantov & Schwager, Phys. Rev. E 60, 4465):
its characteristic velocity g* = 0.32 cm/s (Eq. 31, (g*)^(-1/5) = C1 beta), chosen to match the fit
eps = 0.32 (v / 1 cm/s)^(-0.234) that Bridges, Hatzes & Lin (Nature 309, 333, 1984) made to their measurements on
frost-covered ice spheres, over the speeds they measured (0.01 ... 10 cm/s). eps depends on the material only
through beta, which g* fixes.
"""

import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import restitution  # noqa: E402

ICE_CHARACTERISTIC_VELOCITY = 0.0032  # m/s: g* = 0.32 cm/s (Ramirez et al. 1999)
# Okabe & Ito's colour-blind-safe palette; a journal's single column, 3.5 in, with 8 pt text.
BLUE, VERMILLION = "#0072B2", "#D55E00"


def beta_of(characteristic_velocity):
    """beta [s^(1/5) m^(-1/5)] of a characteristic velocity g* [m/s]: g* = (C1 beta)^-5 (1999 paper, Eq. 31); C1
    read from any calibration, which reports both its beta and its g*."""
    any_law = restitution.calibrate(0.5, 1.0)
    return any_law.beta * (any_law.characteristic_velocity_m_s / characteristic_velocity) ** 0.2


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/eps_vs_velocity.png")
    out.parent.mkdir(parents=True, exist_ok=True)
    plt.rcParams.update({"font.size": 8, "axes.labelsize": 9})
    beta = beta_of(ICE_CHARACTERISTIC_VELOCITY)
    velocity = np.logspace(-4, -1, 200)  # m/s: 0.01 ... 10 cm/s
    figure, axes = plt.subplots(figsize=(3.5, 3.2))
    for end, colour, line, words in (("delayed-recovery", BLUE, "-", "delayed recovery (force vanishes)"),
                                     ("naive", VERMILLION, "--", "naive end (overlap vanishes)")):
        axes.semilogx(velocity, restitution.eps(beta=beta, velocity=velocity, end=end), line, color=colour,
                      label=words)
    axes.semilogx(velocity, 0.32 * (velocity / 0.01) ** -0.234, ":", color="k",
                  label=r"Bridges et al. (1984): $0.32\,(v / 1\,\mathrm{cm/s})^{-0.234}$")
    axes.set_xlabel(r"impact speed $v$ (m/s)")
    axes.set_ylabel(r"coefficient of restitution $\varepsilon$")
    axes.set_ylim(0.0, 1.0)
    axes.grid(True, which="both", alpha=0.3)
    # Below the axes: inside, it would hide a curve at any place.
    axes.legend(loc="upper center", bbox_to_anchor=(0.5, -0.22), frameon=False)
    figure.tight_layout()
    figure.savefig(out, dpi=300, bbox_inches="tight")
    print(out)


if __name__ == "__main__":
    main()
