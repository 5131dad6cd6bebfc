#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Two threads against one, measured as a user runs them: the whole `restitution sweep` command and the Python
array call, each over 10^5 Taylor points.

Usage (after scripts/build): /usr/bin/python3 bench/thread_scaling.py [--repeats 7] [--program PATH]
It alternates 1 and 2 threads REPEATS times each and prints a Markdown section for bench/RESULTS.md: median
wall time, median user and system CPU, the speed-up of the medians, and the serial part wall(2) - wall(1)/2 (the
time that two threads did not split; on an idle machine the speed-up is 2 when it is 0). The load average is
recorded before and after: on a machine shared with other jobs two threads cannot get two cores, and only an
idle machine's wall-time speed-up means something. The CLI's two CSV files are compared byte for byte.
"""

import argparse
import datetime
import filecmp
import os
import pathlib
import resource
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
POINTS = 100_000
THREADS = (1, 2)
SWEEP = ["sweep", "--method", "taylor", "--end", "delayed-recovery", "--log", "--zeta-range", f"1e-3:1e3:{POINTS}"]


def load():
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def cli_run(program, threads, out):
    """(wall, user, sys) seconds of one whole sweep command, start-up and the CSV file included."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run([program] + SWEEP + ["--threads", str(threads), "--out", str(out)], check=True,
                   stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, after.ru_utime - before.ru_utime, after.ru_stime - before.ru_stime


def python_runs(repeats):
    """{threads: [(wall, CPU of every thread of this process, None)]} of restitution.eps over 10^5 points."""
    import numpy as np
    import restitution
    zetas = np.logspace(-3, 3, POINTS)
    restitution.eps(zetas[:100], method="taylor")  # warm up: the module loaded, first allocations made
    runs = {t: [] for t in THREADS}
    values = {}
    for _ in range(repeats):
        for threads in THREADS:
            wall, cpu = time.perf_counter(), time.process_time()
            values[threads] = restitution.eps(zetas, method="taylor", threads=threads)
            runs[threads].append((time.perf_counter() - wall, time.process_time() - cpu, None))
    assert (values[1] == values[2]).all(), "1 and 2 threads gave different values"
    return runs


def table(runs, cpu_columns):
    med = {t: [statistics.median(r[i] for r in runs[t]) for i in range(len(cpu_columns) + 1)] for t in THREADS}
    print("| threads | wall s | " + " | ".join(f"{c} s" for c in cpu_columns) + " | walls of the repeats, s |")
    print("|---|---|" + "---|" * len(cpu_columns) + "---|")
    for t in THREADS:
        walls = " ".join(f"{r[0]:.3f}" for r in runs[t])
        print(f"| {t} | {med[t][0]:.3f} | " + " | ".join(f"{v:.3f}" for v in med[t][1:]) + f" | {walls} |")
    print(f"\nSpeed-up of 2 threads over 1: **{med[1][0] / med[2][0]:.2f}x** wall; serial part "
          f"wall(2) - wall(1)/2 = {1e3 * (med[2][0] - med[1][0] / 2):.0f} ms; CPU of 2 threads / CPU of 1: "
          f"{sum(med[2][1:]) / sum(med[1][1:]):.3f}.")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--program", default=str(ROOT / "build" / "release" / "restitution"))
    args = parser.parse_args()
    print(f"## Two threads against one, as a user runs them (bench/thread_scaling.py), "
          f"{datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC\n")
    print(f"{os.cpu_count()} cores. 10^5 ζ log-spaced in [1e-3, 1e3], delayed-recovery end, method taylor, "
          f"default tolerance; 1 and 2 threads alternating, {args.repeats} runs each; medians.\n")

    print("### The command line\n")
    print(f"`restitution {' '.join(SWEEP)} --threads T --out FILE`, the whole command timed (start-up, checks, "
          "the 15 MB CSV and its partial file included).\n")
    before = load()
    with tempfile.TemporaryDirectory() as folder:
        runs = {t: [] for t in THREADS}
        for _ in range(args.repeats):
            for t in THREADS:
                runs[t].append(cli_run(args.program, t, pathlib.Path(folder) / f"threads{t}.csv"))
        identical = filecmp.cmp(pathlib.Path(folder) / "threads1.csv", pathlib.Path(folder) / "threads2.csv",
                                shallow=False)
    print(f"Load average before {before}, after {load()}. The two CSV files are "
          f"{'byte-identical' if identical else 'DIFFERENT (a bug)'}.\n")
    table(runs, ["user", "sys"])

    print("\n### The Python array call\n")
    print("`restitution.eps(zetas, method=\"taylor\", threads=T)` in one process "
          "(`PYTHONPATH=build/release/python /usr/bin/python3`); CPU is that of every thread of the process.\n")
    try:
        before = load()
        runs = python_runs(args.repeats)
    except ImportError as error:
        print(f"Not measured: the Python module is not importable ({error}).")
        return
    print(f"Load average before {before}, after {load()}. The two arrays are equal.\n")
    table(runs, ["CPU"])


if __name__ == "__main__":
    sys.exit(main())
