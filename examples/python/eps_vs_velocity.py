#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""eps(v) of two colliding steel-like spheres at both ends of the collision, plotted to a PNG.

Usage: PYTHONPATH=build/release/python /usr/bin/python3 examples/python/eps_vs_velocity.py [OUT.png]
(default out/eps_vs_velocity.png). The material is illustrative: Y = 200 GPa, nu = 0.3, R = 1 cm,
density 7800 kg/m^3, dissipative constant A = 2e-5 s (strongly damped, so that the two ends part).
"""

import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import restitution  # noqa: E402


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/eps_vs_velocity.png")
    out.parent.mkdir(parents=True, exist_ok=True)
    steel = restitution.Material(young_modulus=2.0e11, poisson_ratio=0.3, radius=0.01, density=7800.0,
                                 dissipative_constant=2.0e-5)
    velocity = np.logspace(-3, 2, 200)  # m/s
    figure, axes = plt.subplots(figsize=(6.4, 4.2))
    for end, style in (("delayed-recovery", "-"), ("naive", "--")):
        eps = restitution.eps(material=steel, velocity=velocity, end=end)
        axes.semilogx(velocity, eps, style, label=f"{end} end")
    axes.set_xlabel("impact velocity v [m/s]")
    axes.set_ylabel("coefficient of restitution ε")
    axes.set_title(f"viscoelastic spheres, β = {steel.beta:.3g} s$^{{1/5}}$ m$^{{-1/5}}$")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
