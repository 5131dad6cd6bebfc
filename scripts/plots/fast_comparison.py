#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Error and cost of the fast eps(zeta) table against the closed-form approximations, zeta in [1e-4, 1e4].

Errors: each approximation's eps and 1 - eps (from `restitution series validate`) against the fast table
(certified to 1e-13; evaluated through the exported C header, compiled here with gcc and loaded by ctypes);
the fast table's own error against data/reference_solutions.csv (__float128, 1e-25). Costs: median CPU ns per
call from the Google Benchmark CSV of bench/bench_fast.cpp (random zeta in [1e-4, 1e4]).

usage: fast_comparison.py RESTITUTION_EXE BENCH_FAST_CSV REFERENCE_CSV OUT.png OUT.md
"""
import csv
import ctypes
import json
import os
import subprocess
import sys
import tempfile

import style  # first: it selects the Agg backend and sets the style

ZETA_MIN, ZETA_MAX = 1e-4, 1e4
# name in `series validate`, end it approximates, benchmark name, label
APPROXIMATIONS = [
    ("pade-2011-1-4", "delayed", "pade_2011_1_4/dem", "Padé [1/4] 2011"),
    ("pade-2011-3-6", "delayed", "pade_2011_3_6/dem", "Padé [3/6] 2011"),
    ("pade-1999", "naive", "pade_1999/dem", "Padé 1999"),
    ("naive-series:computed-40", "naive", "naive_series_40/dem", "naive series, 40 terms"),
    ("delayed-recovery-series:computed-60", "delayed", "delayed_recovery_series_60/dem", "delayed series, 60 terms"),
]
END_WORDS = {"naive": "naive end", "delayed": "delayed recovery"}
FAST = {"naive": "fast_eps/dem/naive", "delayed": "fast_eps/dem/delayed-recovery"}


def load_header(exe, folder):
    header = os.path.join(folder, "restitution_fast.h")
    subprocess.run([exe, "export", "c-header", "--out", header], check=True, stdout=subprocess.DEVNULL)
    wrapper = os.path.join(folder, "wrapper.c")
    with open(wrapper, "w") as f:
        f.write('#include "restitution_fast.h"\n')
        for end in ("naive", "delayed_recovery"):
            for fn in ("eps", "one_minus_eps"):
                f.write(f"double w_{fn}_{end}(double z) {{ return restitution_{fn}_{end}(z); }}\n")
    lib = os.path.join(folder, "fast.so")
    subprocess.run(["gcc", "-std=c99", "-O2", "-shared", "-fPIC", wrapper, "-o", lib, "-lm"], check=True)
    so = ctypes.CDLL(lib)
    funcs = {}
    for end, c_end in (("naive", "naive"), ("delayed", "delayed_recovery")):
        for fn in ("eps", "one_minus_eps"):
            f = getattr(so, f"w_{fn}_{c_end}")
            f.restype, f.argtypes = ctypes.c_double, [ctypes.c_double]
            funcs[(fn, end)] = f
    return funcs


def rel(a, b):
    return abs(a - b) / b if b != 0 else abs(a)


def error(funcs, end, zeta, eps, one_minus_eps):
    return max(rel(eps, funcs[("eps", end)](zeta)), rel(one_minus_eps, funcs[("one_minus_eps", end)](zeta)))


def read_costs(path):
    lines = open(path).read().splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("name,"))
    return {r["name"][: -len("_median")]: float(r["cpu_time"]) for r in csv.DictReader(lines[start:])
            if r["name"].endswith("_median")}


def main(exe, bench_csv, reference_csv, png_path, md_path):
    with tempfile.TemporaryDirectory() as folder:
        funcs = load_header(exe, folder)
        subprocess.run([exe, "series", "validate", "--out", folder], check=True, stdout=subprocess.DEVNULL)
        with open(os.path.join(folder, "series_validation.csv"), newline="") as f:
            rows = [r for r in csv.DictReader(f) if ZETA_MIN <= float(r["zeta"]) <= ZETA_MAX]
        curves = {}
        for name, end, _, _ in APPROXIMATIONS:
            curves[name] = [(float(r["zeta"]), error(funcs, end, float(r["zeta"]), float(r[name + "_eps"]),
                                                     float(r[name + "_one_minus_eps"]))) for r in rows]
            # beyond the validation grid (it ends at zeta = 10): `series eval`, 4 points a decade
            last = max(float(r["zeta"]) for r in rows)
            for k in range(1, 13):
                zeta = last * 10 ** (k / 4)
                if zeta > ZETA_MAX * 1.0001:
                    break
                # every name `series validate` writes is a kind `series eval` takes
                run = subprocess.run([exe, "series", "eval", "--kind", name, "--zeta", repr(zeta), "--json"],
                                     capture_output=True, text=True)
                if run.returncode == 2 and "radius of convergence" in run.stderr:
                    break  # a series' curve ends at its radius: past it the partial sums diverge
                run.check_returncode()
                v = json.loads(run.stdout)
                curves[name].append((zeta, error(funcs, end, zeta, v["eps"], v["one_minus_eps"])))
        with open(reference_csv, newline="") as f:
            ref = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))
                   if ZETA_MIN <= float(r["zeta"]) <= ZETA_MAX]
        column = {"naive": "naive", "delayed": "delayed_recovery"}  # the reference file's column prefixes
        fast = {end: [(float(r["zeta"]), error(funcs, end, float(r["zeta"]), float(r[column[end] + "_eps"]),
                                               float(r[column[end] + "_one_minus_eps"])))
                      for r in ref if r[column[end] + "_eps"]]
                for end in ("naive", "delayed")}
    costs = read_costs(bench_csv)

    fig, (left, right) = style.figure(1, 2, width=style.DOUBLE_COLUMN_IN, height=5.2,
                                      gridspec_kw={"width_ratios": [3, 2]})
    for i, (name, end, _, label) in enumerate(APPROXIMATIONS):
        z, e = zip(*curves[name])
        left.plot(z, [max(v, 1e-17) for v in e], "-" if end == "naive" else "--", color=style.color(i), label=label)
    for end, marker in (("naive", "o"), ("delayed", "s")):
        z, e = zip(*fast[end])
        left.plot(z, [max(v, 1e-17) for v in e], marker, color="k", mfc="none",
                  label=f"fast table, {END_WORDS[end]} (against the __float128 reference)")
    left.axhline(1e-13, color="k", lw=0.8, ls=":")
    left.set_xscale("log")
    left.set_yscale("log")
    left.set_ylim(1e-17, 1e2)
    left.set_xlabel(r"$\zeta$ (solid: naive end, dashed: delayed)")
    left.set_ylabel(r"relative error of $\varepsilon$, $1-\varepsilon$ (the larger)")
    left.legend(loc="upper center", bbox_to_anchor=(0.5, -0.18))

    entries = [(label, costs.get(bench, float("nan")), max(e for _, e in curves[name]))
               for name, _, bench, label in APPROXIMATIONS]
    entries += [(f"fast table, {END_WORDS[end]}", costs.get(FAST[end], float("nan")), max(e for _, e in fast[end]))
                for end in ("naive", "delayed")]
    for i, (label, ns, worst) in enumerate(entries):
        shown = min(max(worst, 1e-17), 1e3)  # the series diverge beyond their radius: drawn at the top
        # Colours as in the left panel's legend, no labels at the points: several approximations cost about the
        # same and their labels overlapped.
        fast_marker = "s" if "delayed" in label else "o"
        right.scatter(ns, shown, color=style.color(i) if i < len(APPROXIMATIONS) else "k", s=20,
                      marker="^" if worst > 1e3 else (fast_marker if i >= len(APPROXIMATIONS) else "o"))
    right.set_yscale("log")
    right.set_xscale("log")
    right.set_xlabel(r"median CPU time per call (ns)")
    right.set_ylabel(r"worst error over $\zeta \in [10^{-4}, 10^4]$")
    right.text(0.03, 0.85, "colours as in the legend\n" r"$\blacktriangle$: error $> 10^3$, drawn at the top",
               transform=right.transAxes, fontsize="small")
    style.save(fig, png_path)

    with open(md_path, "w") as f:
        f.write("| approximation | median CPU ns | worst relative error of ε, 1 − ε on [1e-4, 1e4] |\n|---|---|---|\n")
        for label, ns, worst in entries:
            f.write(f"| {label} | {ns:.1f} | {worst:.2g} |\n")


if __name__ == "__main__":
    main(*sys.argv[1:6])
