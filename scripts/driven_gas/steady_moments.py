#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The steady part of one driven run's log, block-averaged as `gas --compare` does (blocks of 4 relaxation times
from steady_from_s, a last block of less than 3/4 of the first left out; docs/gas.md, "The driven deck"): a2 of all
spheres, T_s, var(T)/T^2 of the single samples against 2/(3N), and, from a log of scripts/driven_gas/probe_contacts.py,
a2 of the spheres in no contact, the difference, <v^2> of those over all, the fraction in contact and contacts per
sphere. (docs/gas.md, "The measured a2".)

    scripts/driven_gas/steady_moments.py LOG RELAXATION_TIME_S [PARTICLES]
"""
import math
import re
import sys


def fields(line):
    return dict(token.split("=", 1) for token in line.split()[1:])


def read(path):
    steady, rows, free, temperature = None, {}, {}, {}
    with open(path) as f:
        for line in f:
            if line.startswith("restitution-driven-setup"):
                steady = float(re.search(r"steady_from_s=(\S+)", line).group(1))
            elif line.startswith("restitution-driven "):
                d = fields(line)
                rows[float(d["time_s"])] = d
            elif line.startswith("probe-free "):
                d = fields(line)
                free[float(d["time_s"])] = d
            elif line.startswith("restitution-gas "):
                d = fields(line)
                temperature[float(d["time_s"])] = float(d["temperature_j"])
    return steady, rows, free, temperature


def blocks(times, values, steady, block_s):
    sums, counts = {}, {}
    for t, v in zip(times, values):
        if t > steady:
            b = int((t - steady) / block_s)
            sums[b] = sums.get(b, 0.0) + v
            counts[b] = counts.get(b, 0) + 1
    keys = sorted(sums)
    while keys and counts[keys[-1]] < 0.75 * counts[keys[0]]:
        keys.pop()
    means = [sums[k] / counts[k] for k in keys]
    mean = sum(means) / len(means)
    error = math.sqrt(sum((x - mean) ** 2 for x in means) / (len(means) - 1) / len(means))
    return mean, error, len(means)


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    steady, rows, free, temperature = read(sys.argv[1])
    block_s, particles = 4.0 * float(sys.argv[2]), int(sys.argv[3]) if len(sys.argv) == 4 else 2000
    times = sorted(rows)
    v2 = [float(rows[t]["mean_v2_m2_s2"]) for t in times]
    v4 = [float(rows[t]["mean_v4_m4_s4"]) for t in times]
    a2 = [0.6 * b / (a * a) - 1.0 for a, b in zip(v2, v4)]
    m, e, k = blocks(times, a2, steady, block_s)
    print(f"a2 (all spheres)        {m:+.5f} +- {e:.5f}  ({k} blocks)")
    m, e, _ = blocks(times, [temperature[t] for t in times], steady, block_s)
    print(f"T_s                     {m:.6g} J +- {e / m * 100:.2f} %")
    samples = [temperature[t] for t in times if t > steady]
    mean = sum(samples) / len(samples)
    var = sum((x - mean) ** 2 for x in samples) / (len(samples) - 1)
    print(f"var(T)/T^2              {var / mean**2:.3e}  (2/(3N) = {2.0 / (3.0 * particles):.3e})")
    if not free:
        return
    ft = [t for t in times if t in free]
    nfree = [float(free[t]["free"]) for t in ft]
    s2 = [float(free[t]["sum_v2_free"]) / n for t, n in zip(ft, nfree)]
    s4 = [float(free[t]["sum_v4_free"]) / n for t, n in zip(ft, nfree)]
    a2f = [0.6 * b / (a * a) - 1.0 for a, b in zip(s2, s4)]
    all_of = dict(zip(times, a2))
    v2_of = dict(zip(times, v2))
    for label, values in (("a2 (no contact)", a2f),
                          ("a2 (all) - a2 (no contact)", [all_of[t] - x for t, x in zip(ft, a2f)]),
                          ("<v2> no contact / all", [x / v2_of[t] for t, x in zip(ft, s2)]),
                          ("fraction in contact", [1.0 - n / particles for n in nfree]),
                          ("contacts per sphere", [float(free[t]["contacts"]) / particles for t in ft])):
        m, e, _ = blocks(ft, values, steady, block_s)
        print(f"{label:<23} {m:+.5f} +- {e:.5f}")


if __name__ == "__main__":
    main()
