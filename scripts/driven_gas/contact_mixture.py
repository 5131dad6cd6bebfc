#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""How the spheres caught in a contact shift the measured a2 = (3/5)<v^4>/<v^2>^2 - 1 of a soft-sphere gas
(docs/gas.md, "The measured a2"). The spheres out of contact are Maxwellian (T/m = 1, a2 = 0); a fraction kappa is
in a binary contact: Hertz with Tsuji damping and LAMMPS's limit_damping (x'' = -max(x^{3/2} + b x^{1/4} x', 0),
b set for eps = 0.8), whose normal closing speed u x'(s) is self-similar in u and lasts ~u^{-1/5}; contacts are
found in proportion to their rate (~u, the flux) times their duration, so pairs of Maxwellian spheres are weighted
by u^{4/5}, with a uniform time into the contact. Prints d a2/d kappa and d ln<v^2>/d kappa.

    scripts/driven_gas/contact_mixture.py
"""
import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq


def contact(b):
    """Duration, dense solution and restitution coefficient of the dimensionless contact."""
    def force(_, y):
        x = max(y[0], 0.0)
        return [y[1], -max(x**1.5 + b * x**0.25 * y[1], 0.0)]

    def separated(_, y):
        return y[0]

    separated.terminal, separated.direction = True, -1
    s = solve_ivp(force, [0, 50], [0, 1], events=separated, dense_output=True, rtol=1e-10, atol=1e-12,
                  max_step=0.01)
    return s.t_events[0][0], s.sol, -s.y_events[0][0][1]


def main():
    b = brentq(lambda x: contact(x)[2] - 0.8, 1e-3, 1.5)
    duration, solution, eps = contact(b)
    rng = np.random.default_rng(1)
    count = 2_000_000
    v1, v2 = rng.normal(size=(count, 3)), rng.normal(size=(count, 3))
    n = rng.normal(size=(count, 3))
    n /= np.linalg.norm(n, axis=1)[:, None]
    u = -((v1 - v2) * n).sum(1)  # closing speed along n
    weight = np.where(u > 0, np.abs(u) ** 0.8, 0.0)
    closing = u * solution(rng.uniform(size=count) * duration)[1]
    dv = (closing - u)[:, None] * n
    c1, c2 = v1 - dv / 2, v2 + dv / 2  # the centre of mass kept, the closing speed now `closing`
    s1, s2 = (c1**2).sum(1), (c2**2).sum(1)
    m2 = (weight * (s1 + s2)).sum() / (2 * weight.sum())
    m4 = (weight * (s1**2 + s2**2)).sum() / (2 * weight.sum())
    print(f"b = {b:.4f} (eps {eps:.4f}); in contact <v^2> = {m2:.4f}, <v^4> = {m4:.4f} (out of contact 3, 15)")
    print(f"d a2/d kappa = {m4 / 15 - 2 * m2 / 3 + 1:+.4f}, d ln<v^2>/d kappa = {m2 / 3 - 1:+.4f}")
    for kappa in (0.011, 0.038, 0.069):
        a2 = 0.6 * ((1 - kappa) * 15 + kappa * m4) / ((1 - kappa) * 3 + kappa * m2) ** 2 - 1
        print(f"kappa = {kappa}: a2 (all) - a2 (no contact) = {a2:+.5f}")


if __name__ == "__main__":
    main()
