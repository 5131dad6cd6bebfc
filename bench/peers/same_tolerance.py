#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""SciPy's DOP853 against this project's engines at the same requested tolerance, in one run: the basis on
which issue 27 stated its targets (DOP853 at rtol 1e-8 against the default engine at T = 1e-8). The fairer
basis, equal achieved accuracy, is scipy_peer.py's; this one is printed beside it because a user comparing
tools types the same tolerance into both. Delayed-recovery end, scipy_peer's ζ set; our engines through the
Python module (its per-call overhead counted against us). Times are means over ζ of the median per solve.

Usage: PYTHONPATH=build/release/python same_tolerance.py REFERENCE_CSV [TOLERANCE]"""
import statistics
import sys
import time

import restitution
import scipy_peer


def median_seconds(f, repeats):
    samples = []
    value = None
    for _ in range(repeats):
        start = time.perf_counter()
        value = f()
        samples.append(time.perf_counter() - start)
    return value, statistics.median(samples)


def main(argv):
    ref = scipy_peer.reference(argv[1])
    tolerance = float(argv[2]) if len(argv) > 2 else 1e-8
    engines = [
        (f"scipy-DOP853, rtol {tolerance:g}", lambda z: scipy_peer.solve(z, "DOP853", tolerance), 7),
        (f"restitution default (auto), T = {tolerance:g}", lambda z: restitution.eps(z, tolerance=tolerance), 201),
        (f"restitution taylor, T = {tolerance:g}",
         lambda z: restitution.eps(z, tolerance=tolerance, method="taylor"), 201),
    ]
    rows = []
    for name, solve, repeats in engines:
        errors, times = [], []
        for zeta in scipy_peer.ZETAS:
            eps, seconds = median_seconds(lambda: solve(zeta), repeats)
            eps_ref, ome_ref = ref[zeta]
            errors.append(abs(eps - eps_ref) / min(eps_ref, ome_ref))
            times.append(seconds)
        rows.append((name, 1e6 * statistics.mean(times), max(errors)))
    print("| engine | mean µs per solve | worst error / min(ε, 1 − ε) | DOP853 / this |")
    print("|---|---|---|---|")
    for name, us, error in rows:
        print(f"| {name} | {us:.1f} | {error:.2g} | {rows[0][1] / us:.0f}x |")


if __name__ == "__main__":
    main(sys.argv)
