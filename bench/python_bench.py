#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Speed of the Python module against the same work through the C++ library, measured in one run.

Usage (after scripts/build): PYTHONPATH=build/release/python /usr/bin/python3 bench/python_bench.py [--repeats 7]
Alternates the C++ peer (build/release/bench/bench_python_peer) and the Python calls and prints medians
and ratios as Markdown for bench/RESULTS.md:
  sweep: restitution.eps(10^5 zeta log-spaced over [1e-3, 1e3], method="taylor") vs run_sweep, all cores;
  scalar: per-call time of restitution.eps(zeta, method="taylor") vs CollisionSolver::solve, same zetas.
Wall time and CPU time (all threads of the process) are both reported: on a shared, loaded machine the
wall time of a two-thread sweep follows the load, the CPU time much less so.
"""

import argparse
import datetime
import json
import os
import pathlib
import statistics
import subprocess
import time

import numpy as np

import restitution

ROOT = pathlib.Path(__file__).resolve().parents[1]
PEER = ROOT / "build" / "release" / "bench" / "bench_python_peer"
SCALAR_CALLS = 2_000  # as BM_ScalarPeer's iterations
SCALAR_ROUNDS = 5  # short scalar runs per repeat, alternating with the C++ peer, against drifting load
UNIT = {"ms": 1e-3, "us": 1e-6}


def cxx_peer(case):
    """(wall, CPU) seconds of one run of the C++ peer's case: the whole sweep, or one scalar solve."""
    out = subprocess.run([str(PEER), "--benchmark_format=json", f"--benchmark_filter={case}"], check=True,
                         capture_output=True, text=True)
    row = json.loads(out.stdout)["benchmarks"][0]
    return row["real_time"] * UNIT[row["time_unit"]], row["cpu_time"] * UNIT[row["time_unit"]]


def timed(function, count=1):
    """(wall, CPU of the whole process) seconds per call."""
    wall, cpu = time.perf_counter(), time.process_time()
    function()
    return (time.perf_counter() - wall) / count, (time.process_time() - cpu) / count


def python_scalar(zetas):
    eps = restitution.eps
    calls = [float(zetas[i % zetas.size]) for i in range(SCALAR_CALLS)]

    def loop():
        for zeta in calls:
            eps(zeta, method="taylor")

    return timed(loop, SCALAR_CALLS)


def _spread(ratios):
    ratios = sorted(ratios)
    return f"{statistics.median(ratios):.3f} ({ratios[0]:.3f}–{ratios[-1]:.3f})"


def _row(name, cxx, py, scale, unit):
    """Markdown row: medians, ratio of medians, difference, and the paired ratios (each Python run against
    the C++ run just before it, robust to load that drifts between repeats)."""
    cxx_median, py_median = statistics.median(cxx), statistics.median(py)
    return (f"| {name} | {cxx_median * scale:.2f} {unit} | {py_median * scale:.2f} {unit} | "
            f"{py_median / cxx_median:.3f} | {(py_median - cxx_median) * scale:+.2f} {unit} | "
            f"{_spread([p / c for p, c in zip(py, cxx)])} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=7)
    repeats = parser.parse_args().repeats
    sweep_zetas = np.logspace(-3, 3, 100_000)
    scalar_zetas = np.logspace(-3, 3, 100)
    restitution.eps(scalar_zetas, method="taylor")  # warm up: load, first allocation
    runs = {key: [] for key in ("cxx_sweep", "py_sweep", "cxx_scalar", "py_scalar")}
    for _ in range(repeats):
        runs["cxx_sweep"].append(cxx_peer("BM_SweepPeer"))
        runs["py_sweep"].append(timed(lambda: restitution.eps(sweep_zetas, method="taylor")))
        for _ in range(SCALAR_ROUNDS):
            runs["cxx_scalar"].append(cxx_peer("BM_ScalarPeer"))
            runs["py_scalar"].append(python_scalar(scalar_zetas))
    wall = {key: [w for w, _ in values] for key, values in runs.items()}
    cpu = {key: [c for _, c in values] for key, values in runs.items()}
    load = os.getloadavg()
    print(f"## Python module vs the C++ library (bench/python_bench.py), "
          f"{datetime.datetime.utcnow():%Y-%m-%d %H:%M} UTC\n")
    print(f"{os.cpu_count()} cores, load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}; {repeats} alternating "
          f"sweeps and {repeats * SCALAR_ROUNDS} alternating runs of {SCALAR_CALLS} scalar calls; delayed-recovery "
          "end, method taylor, tolerance 1e-10. Command: "
          "`PYTHONPATH=build/release/python /usr/bin/python3 bench/python_bench.py`.\n")
    print("| case | C++ library | Python module | ratio of medians | difference | paired ratios: median (min–max) |")
    print("|---|---|---|---|---|---|")
    sweep = "10^5 zeta log-spaced in [1e-3, 1e3], all cores"
    scalar = "scalar eps per call, 100 zeta log-spaced in [1e-3, 1e3] cycled"
    print(_row(f"{sweep}, wall", wall["cxx_sweep"], wall["py_sweep"], 1e3, "ms"))
    print(_row(f"{sweep}, CPU", cpu["cxx_sweep"], cpu["py_sweep"], 1e3, "ms"))
    print(_row(f"{scalar}, wall", wall["cxx_scalar"], wall["py_scalar"], 1e6, "µs"))
    print(_row(f"{scalar}, CPU", cpu["cxx_scalar"], cpu["py_scalar"], 1e6, "µs"))


if __name__ == "__main__":
    main()
