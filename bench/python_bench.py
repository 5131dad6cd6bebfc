#!/usr/bin/python3
"""Speed of the Python module against the same work through the C++ library, measured in one run.

Usage (after scripts/build): /usr/bin/python3 bench/python_bench.py [--repeats 5]
with PYTHONPATH=build/release/python. Alternates the C++ peer (build/release/bench/bench_python_peer) and
the Python calls `repeats` times and prints medians and ratios as Markdown for bench/RESULTS.md:
  sweep: restitution.eps(10^5 zeta log-spaced over [1e-3, 1e3], method="taylor") vs run_sweep, all cores;
  scalar: per-call time of restitution.eps(zeta, method="taylor") vs CollisionSolver::solve, same zetas.
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


def cxx_peer(case):
    """Seconds of one run of the C++ peer's case: the whole sweep, or one scalar solve."""
    out = subprocess.run([str(PEER), "--benchmark_format=json", f"--benchmark_filter={case}"], check=True,
                         capture_output=True, text=True)
    row = json.loads(out.stdout)["benchmarks"][0]
    return row["real_time"] * {"ms": 1e-3, "us": 1e-6}[row["time_unit"]]


def python_sweep(zetas):
    start = time.perf_counter()
    restitution.eps(zetas, method="taylor")
    return time.perf_counter() - start


def python_scalar(zetas):
    eps = restitution.eps
    calls = [float(zetas[i % zetas.size]) for i in range(SCALAR_CALLS)]
    start = time.perf_counter()
    for zeta in calls:
        eps(zeta, method="taylor")
    return (time.perf_counter() - start) / SCALAR_CALLS


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    repeats = parser.parse_args().repeats
    sweep_zetas = np.logspace(-3, 3, 100_000)
    scalar_zetas = np.logspace(-3, 3, 100)
    restitution.eps(scalar_zetas, method="taylor")  # warm up: load, first allocation
    samples = {"cxx_sweep": [], "py_sweep": [], "cxx_scalar": [], "py_scalar": []}
    for _ in range(repeats):
        samples["cxx_sweep"].append(cxx_peer("BM_SweepPeer"))
        samples["py_sweep"].append(python_sweep(sweep_zetas))
        for _ in range(SCALAR_ROUNDS):
            samples["cxx_scalar"].append(cxx_peer("BM_ScalarPeer"))
            samples["py_scalar"].append(python_scalar(scalar_zetas))
    m = {key: statistics.median(values) for key, values in samples.items()}
    load = os.getloadavg()
    print(f"## Python module vs the C++ library (bench/python_bench.py), "
          f"{datetime.datetime.utcnow():%Y-%m-%d %H:%M} UTC\n")
    print(f"{os.cpu_count()} cores, load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}; medians of {repeats} "
          f"alternating sweeps and {repeats * SCALAR_ROUNDS} alternating runs of {SCALAR_CALLS} scalar calls; "
          "delayed-recovery end, method taylor, tolerance 1e-10. Command: "
          "`PYTHONPATH=build/release/python /usr/bin/python3 bench/python_bench.py`.\n")
    print("| case | C++ library | Python module | ratio Python / C++ | difference |")
    print("|---|---|---|---|---|")
    print(f"| 10^5 zeta log-spaced in [1e-3, 1e3], all cores | {m['cxx_sweep'] * 1e3:.1f} ms | "
          f"{m['py_sweep'] * 1e3:.1f} ms | {m['py_sweep'] / m['cxx_sweep']:.3f} | "
          f"{(m['py_sweep'] - m['cxx_sweep']) * 1e3:+.1f} ms |")
    print(f"| scalar eps, per call (100 zeta log-spaced in [1e-3, 1e3], cycled) | {m['cxx_scalar'] * 1e6:.2f} µs | "
          f"{m['py_scalar'] * 1e6:.2f} µs | {m['py_scalar'] / m['cxx_scalar']:.3f} | "
          f"{(m['py_scalar'] - m['cxx_scalar']) * 1e6:+.2f} µs |")


if __name__ == "__main__":
    main()
