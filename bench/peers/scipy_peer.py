#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Peer benchmark: SciPy's solve_ivp (DOP853, LSODA, Radau, BDF) on x'' + zeta x' sqrt(x) + x^{3/2} = 0,
x(0) = 0, x'(0) = 1, with the delayed-recovery end zeta x' + x = 0 as a terminal event, as a physicist would
write it (time form, sqrt guarded at x <= 0). Errors against data/reference_solutions.csv; run times are
medians per solve. Compared at equal accuracy with this project's engines from a work-precision CSV measured
in the same run (scripts/bench).

Usage: scipy_peer.py REFERENCE_CSV OUR_POINTS_CSV OUT_CSV OUT_MD"""
import csv
import math
import statistics
import sys
import time

import numpy as np
import scipy
from scipy.integrate import solve_ivp

ZETAS = [1e-4, 1e-3, 1e-2, 1e-1, 1.0, 10.0, 100.0]  # the stiff 1e3, 1e4 take SciPy minutes per ladder
METHODS = ["DOP853", "LSODA", "Radau", "BDF"]
TOLERANCES = [10.0 ** -k for k in range(4, 14)]
ACCURACIES = [1e-6, 1e-8, 1e-10]
REPEATS = 3


def reference(path):
    ref = {}
    for row in csv.DictReader(line for line in open(path) if not line.startswith("#")):
        if row["delayed_recovery_eps"]:
            ref[float(row["zeta"])] = (float(row["delayed_recovery_eps"]), float(row["delayed_recovery_one_minus_eps"]))
    return ref


def solve(zeta, method, rtol):
    def rhs(t, s):
        x, v = s
        w = math.sqrt(x) if x > 0.0 else 0.0
        return [v, -w * (zeta * v + x)]

    def force(t, s):
        return zeta * s[1] + s[0] if t > 0.0 else 1.0

    force.terminal = True
    force.direction = -1
    scale = max(zeta, 1.0)
    atol = [rtol * 1e-2 * scale ** (-2.0 / 3.0), rtol * 1e-2 * scale ** (-5.0 / 3.0)]
    sol = solve_ivp(rhs, (0.0, 1e3 * (1 + zeta)), [0.0, 1.0], method=method, rtol=rtol, atol=atol,
                    events=force)
    if sol.status != 1 or len(sol.t_events[0]) == 0:
        return None
    return -sol.y_events[0][0][1]


def measure(ref):
    rows = []
    for method in METHODS:
        for rtol in TOLERANCES:
            if method in ("Radau", "BDF", "LSODA") and rtol < 1e-12:
                continue  # rtol below ~100 eps: SciPy warns and clips
            errors, times = [], []
            for zeta in ZETAS:
                eps_ref, ome_ref = ref[zeta]
                samples = []
                eps = None
                for _ in range(REPEATS):
                    start = time.perf_counter()
                    eps = solve(zeta, method, rtol)
                    samples.append(time.perf_counter() - start)
                if eps is None:
                    errors.append(math.inf)
                else:
                    errors.append(abs(eps - eps_ref) / min(eps_ref, ome_ref))
                times.append(statistics.median(samples))
            rows.append({"engine": "scipy-" + method, "tolerance": rtol, "max_error": max(errors),
                         "mean_median_us": 1e6 * statistics.mean(times)})
            print(f"{method:7s} rtol={rtol:.0e} max error {max(errors):.2e} mean {1e6 * statistics.mean(times):.0f} us",
                  file=sys.stderr)
    return rows


def ours(points_csv):
    groups = {}
    for r in csv.DictReader(open(points_csv)):
        if r["end"] != "delayed-recovery" or float(r["zeta"]) not in ZETAS:
            continue
        key = (r["engine"], float(r["tolerance"]))
        groups.setdefault(key, []).append(r)
    rows = []
    for (engine, tol), pts in groups.items():
        if len(pts) != len(ZETAS):
            continue
        rows.append({"engine": engine, "tolerance": tol, "max_error": max(float(p["error"]) for p in pts),
                     "mean_median_us": statistics.mean(float(p["median_us"]) for p in pts)})
    return rows


def cheapest(rows, engine, accuracy):
    ok = [r for r in rows if r["engine"] == engine and r["max_error"] <= accuracy]
    return min(ok, key=lambda r: r["mean_median_us"]) if ok else None


def main(ref_path, points_csv, out_csv, out_md):
    ref = reference(ref_path)
    peer_rows = measure(ref)
    our_rows = ours(points_csv)
    rows = peer_rows + our_rows
    with open(out_csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["engine", "tolerance", "max_error", "mean_median_us"])
        w.writeheader()
        w.writerows(rows)
    engines = sorted({r["engine"] for r in rows})
    lines = [f"Delayed-recovery end, zeta in {ZETAS}; error = worst |eps - eps*| / min(eps*, 1 - eps*) over the set, "
             f"time = mean over the set of the median run time per solve. SciPy {scipy.__version__}, "
             f"NumPy {np.__version__}.", "",
             "| engine | " + " | ".join(f"µs at ≤ {a:g} (tolerance)" for a in ACCURACIES) + " |",
             "|---|" + "---|" * len(ACCURACIES)]
    for engine in engines:
        cells = []
        for a in ACCURACIES:
            c = cheapest(rows, engine, a)
            cells.append(f"{c['mean_median_us']:.1f} ({c['tolerance']:.0e})" if c else "not reached")
        lines.append(f"| {engine} | " + " | ".join(cells) + " |")
    lines += ["", "Ratio of run times at equal accuracy (best SciPy method / ours):", ""]
    for a in ACCURACIES:
        peers = [cheapest(rows, "scipy-" + m, a) for m in METHODS]
        peers = [p for p in peers if p]
        best_peer = min(peers, key=lambda r: r["mean_median_us"]) if peers else None
        for engine in ("taylor", "bdf", "adams"):
            c = cheapest(rows, engine, a)
            if best_peer and c:
                lines.append(f"- accuracy {a:g}: {best_peer['engine']} {best_peer['mean_median_us']:.0f} µs vs "
                             f"{engine} {c['mean_median_us']:.1f} µs: {best_peer['mean_median_us'] / c['mean_median_us']:.0f}x")
            elif c:
                lines.append(f"- accuracy {a:g}: no SciPy method reaches it; {engine} {c['mean_median_us']:.1f} µs")
    open(out_md, "w").write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main(*sys.argv[1:5])
