#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Direct simulation Monte Carlo (DSMC) of the homogeneous Enskog-Boltzmann equation of a gas of constant eps in a
Langevin bath (docs/gas.md, "The measured a2"). Collisions: random disjoint pairs, each a candidate with probability
0.2 per step and accepted with probability |g.n|/g_max (n uniform on the sphere), the Enskog rate K = n g2 sigma^2 c
with the collision-rate factor c; the bath: the exact Ornstein-Uhlenbeck step towards T_b with drag 1/tau_b. Molecular
chaos holds by construction, so the stationary a2 measured here is the kinetic equation's, without the first-Sonine
truncation of `restitution gas`: their difference is that truncation; the difference to LAMMPS is what the kinetic
equation leaves out. a2 = (3/5)<v^4>/<v^2>^2 - 1 per sample (bias -2/(3N)), block means of 4 relaxation times after
10 relaxation times, the error bar their standard deviation over sqrt(K).

    scripts/driven_gas/dsmc.py --particles 40000 --relaxation-times 150 --seed 2     # the hottest bath of the runs
"""
import argparse
import math

import numpy as np


def arguments():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--particles", type=int, default=40000)
    p.add_argument("--relaxation-times", type=float, default=150.0, help="simulated span, in relaxation times")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--dt-scale", type=float, default=1.0, help="time step factor (<= 1)")
    p.add_argument("--eps", type=float, default=0.8)
    p.add_argument("--mass-kg", type=float, default=0.0004817108735504349)
    p.add_argument("--diameter-m", type=float, default=0.01)
    p.add_argument("--packing-fraction", type=float, default=0.1)
    p.add_argument("--collision-rate-factor", type=float, default=0.924769)
    p.add_argument("--bath-temperature-j", type=float, default=0.07)
    p.add_argument("--bath-time-s", type=float, default=2.0)
    p.add_argument("--steady-temperature-j", type=float, default=1.8030538e-3, help="the theory's T_s (sets g_max)")
    p.add_argument("--relaxation-time-s", type=float, default=0.01448792756655155, help="the theory's")
    return p.parse_args()


def collide(v, rng, p_candidate, g_max, eps):
    """One step of collisions between disjoint random pairs; returns the number of |g.n| above g_max (clipped)."""
    perm = rng.permutation(len(v))
    i, j = perm[0::2], perm[1::2]
    candidate = rng.uniform(size=i.size) < p_candidate
    i, j = i[candidate], j[candidate]
    n = rng.normal(size=(i.size, 3))
    n /= np.linalg.norm(n, axis=1)[:, None]
    gn = ((v[i] - v[j]) * n).sum(1)
    accepted = rng.uniform(size=i.size) * g_max < gn
    dv = (0.5 * (1.0 + eps) * gn[accepted])[:, None] * n[accepted]
    v[i[accepted]] -= dv
    v[j[accepted]] += dv
    return int((gn > g_max).sum())


def main():
    a = arguments()
    phi, sigma, m = a.packing_fraction, a.diameter_m, a.mass_kg
    n = 6.0 * phi / (math.pi * sigma**3)
    g2 = (1.0 - phi / 2.0) / (1.0 - phi) ** 3
    rate = n * g2 * sigma**2 * a.collision_rate_factor  # 1/m: collisions per sphere = rate * pi <|g|>
    g_max = 7.0 * math.sqrt(2.0 * a.steady_temperature_j / m)
    p_candidate = 0.2 * a.dt_scale
    dt = p_candidate / (rate * 4.0 * math.pi * g_max)
    rng = np.random.default_rng(a.seed)
    v = rng.normal(scale=math.sqrt(a.steady_temperature_j / m), size=(a.particles, 3))
    v -= v.mean(0)
    decay = math.exp(-dt / a.bath_time_s)
    kick = math.sqrt(a.bath_temperature_j / m * (1.0 - decay**2))
    tau = a.relaxation_time_s
    steps, burn, every = int(a.relaxation_times * tau / dt), int(10 * tau / dt), max(1, int(tau / 4 / dt))
    a2, temperature, clipped = [], [], 0
    for step in range(steps):
        v = v * decay + kick * rng.normal(size=v.shape)
        clipped += collide(v, rng, p_candidate, g_max, a.eps)
        if step >= burn and step % every == 0:
            v2 = (v * v).sum(1)
            temperature.append(m * v2.mean() / 3.0)
            a2.append(0.6 * (v2 * v2).mean() / v2.mean() ** 2 - 1.0)
    per_block = 16  # samples in 4 relaxation times
    k = len(a2) // per_block
    blocks_a2 = np.array(a2[: k * per_block]).reshape(k, per_block).mean(1)
    blocks_t = np.array(temperature[: k * per_block]).reshape(k, per_block).mean(1)
    omega_dt = 4.0 * math.sqrt(math.pi) * rate * math.sqrt(a.steady_temperature_j / m) * dt
    print(f"N = {a.particles}, dt = {dt:.3e} s (collisions per sphere and step {omega_dt:.4f}), {k} blocks, "
          f"{clipped} clipped")
    print(f"T_s = {blocks_t.mean():.6e} J +- {blocks_t.std(ddof=1) / math.sqrt(k) / blocks_t.mean() * 100:.2f} %")
    print(f"a2 = {blocks_a2.mean():+.5f} +- {blocks_a2.std(ddof=1) / math.sqrt(k):.5f}")


if __name__ == "__main__":
    main()
