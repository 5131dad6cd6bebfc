#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The report figures are fit for a paper (issue 36): every figure of every shipped scene and of the commands
that draw one (`series validate`, `stability`, `gas --plot`) is drawn by the program itself, and each figure's texts are
judged as matplotlib holds them (tests/plot_hook/sitecustomize.py records them):

* axis labels carry a mathtext symbol or a unit, and a physical quantity always its unit (or "scaled");
* no text is a table's column name (snake_case) or an ASCII spelling of a symbol (eps, zeta, tau, beta)
  outside mathtext;
* titles fit inside the figure; PNG at >= 200 dpi;
* --format png,pdf,svg and a scene's `format` key write each format; an unknown format is refused (exit 2).

Usage: plot_labels.py RESTITUTION_EXE SOURCE_DIR
"""
import json
import os
import re
import subprocess
import sys
import tempfile

MATH = re.compile(r"\$[^$]*\$")
COLUMN_NAME = re.compile(r"\b[a-z][a-z0-9]*(?:_[a-z0-9]+)+\b")
ASCII_SYMBOL = re.compile(r"\b(?:eps|zeta|tau|beta)\b")
# A unit in parentheses, or a quantity's value with its unit ("at 1 m/s"), or a scaled (dimensionless) quantity.
UNIT = re.compile(r"\((?:m/s|s|ms|µs|ns|m|kg|Pa|J|count|scaled)\)|\d\s*(?:m/s|s|µs|ns)\b|\bscaled\b")
PHYSICAL = re.compile(r"\b(?:speed|velocity|time|duration|compression|run time)\b")


def plain(text):
    """The text outside its $...$ formulas."""
    return MATH.sub(" ", text)


def problems_of(figure):
    found = []
    where = os.path.basename(figure["path"])
    for label in figure["labels"]:
        if "$" not in label and not UNIT.search(label):
            found.append(f"{where}: axis label {label!r} has neither a symbol ($...$) nor a unit")
        if PHYSICAL.search(plain(label)) and not UNIT.search(label):
            found.append(f"{where}: axis label {label!r} names a physical quantity without its unit")
    for kind in ("labels", "legends", "titles", "others"):
        for text in figure[kind]:
            rest = plain(text)
            for pattern, what in ((COLUMN_NAME, "a column name"), (ASCII_SYMBOL, "a symbol spelled in ASCII")):
                match = pattern.search(rest)
                if match:
                    found.append(f"{where}: {kind[:-1]} {text!r} has {what}: {match.group(0)!r}")
    for text in figure["titles_outside"]:
        found.append(f"{where}: title {text!r} runs off the figure")
    if figure["format"] == "png" and float(figure["dpi"]) < 200:
        found.append(f"{where}: PNG at {figure['dpi']} dpi, fewer than 200")
    return found


def run(exe, args, env, cwd, expect=0):
    result = subprocess.run([exe] + args, env=env, cwd=cwd, capture_output=True, text=True)
    if result.returncode != expect:
        raise SystemExit(f"`restitution {' '.join(args)}` exited {result.returncode}, expected {expect}:\n"
                         f"{result.stderr}")
    return result


def main(exe, source):
    failures = []
    with tempfile.TemporaryDirectory() as folder:
        log = os.path.join(folder, "figures.jsonl")
        env = dict(os.environ, PLOT_TEXTS_LOG=log,
                   PYTHONPATH=os.path.join(source, "tests", "plot_hook"))
        env.pop("RESTITUTION_PYTHON", None)
        scenes = sorted(f for f in os.listdir(os.path.join(source, "scenes")) if f.endswith(".toml"))
        pngs = 0
        for scene in scenes:
            out = os.path.join(folder, scene[:-5])
            run(exe, ["run", os.path.join("scenes", scene), "--quick", "--threads", "2", "--output", out], env,
                source)
            pngs += sum(1 for f in os.listdir(out) if f.endswith(".png"))
        run(exe, ["series", "validate", "--out", os.path.join(folder, "series")], env, source)
        run(exe, ["stability", "--tolerance", "1e-6", "--out", os.path.join(folder, "stability")], env, source)
        run(exe, ["gas", "--radius", "0.005", "--density", "920", "--eps", "0.8", "--velocity", "2",
                  "--packing-fraction", "0.1", "--rms-speed", "1", "--haff-times", "100", "--points-per-decade", "4",
                  "--plot", os.path.join(folder, "gas.png")], env, source)
        pngs += 3
        with open(log) as f:
            figures = [json.loads(line) for line in f]
        # Each PNG written was recorded (the hook ran in every plot script), and none of them has a problem.
        recorded = sum(1 for fig in figures if fig["format"] == "png")
        if recorded != pngs or pngs < 16:
            failures.append(f"{recorded} figures recorded, {pngs} PNG files written (expected >= 16)")
        for figure in figures:
            failures += problems_of(figure)

        # Formats: the command line's list, a scene's key, and what is refused.
        series = os.path.join(folder, "formats")
        run(exe, ["series", "validate", "--out", series, "--format", "pdf,svg,png"], {**os.environ}, source)
        for name in ("series_validation.png", "series_validation.pdf", "series_validation.svg"):
            if not os.path.isfile(os.path.join(series, name)):
                failures.append(f"--format pdf,svg,png wrote no {name}")
        with open(os.path.join(series, "series_validation.pdf"), "rb") as f:
            if not f.read(5) == b"%PDF-":
                failures.append("series_validation.pdf is no PDF")
        leftovers = [f for f in os.listdir(series) if ".tmp" in f]
        if leftovers:
            failures.append(f"temporary figures left behind: {leftovers}")
        refused = run(exe, ["series", "validate", "--out", os.path.join(folder, "refused"), "--format", "png,jpg"],
                      {**os.environ}, source, expect=2)
        if "unknown figure format 'jpg'" not in refused.stderr:
            failures.append(f"--format png,jpg: the error does not name 'jpg': {refused.stderr!r}")
        scene = os.path.join(folder, "formats.toml")
        with open(scene, "w") as f:
            f.write('output = "x"\nformat = ["svg", "pdf"]\n[[trajectory]]\nname = "t"\nzeta = 0.5\n')
        out = os.path.join(folder, "scene_formats")
        run(exe, ["run", scene, "--output", out], {**os.environ}, source)
        written = sorted(f for f in os.listdir(out) if f.startswith("t."))
        if written != ["t.csv", "t.pdf", "t.svg"]:
            failures.append(f'format = ["svg", "pdf"] wrote {written}')
        with open(os.path.join(out, "report.md")) as f:
            if "](t.svg)" not in f.read():
                failures.append("report.md does not link the SVG figure of a scene without PNG")
        with open(scene, "w") as f:
            f.write('output = "x"\nformat = ["png", "gif"]\n[[trajectory]]\nname = "t"\nzeta = 0.5\n')
        refused = run(exe, ["run", scene, "--output", os.path.join(folder, "bad")], {**os.environ}, source, 2)
        if "format" not in refused.stderr or "'gif'" not in refused.stderr:
            failures.append(f"format = [..., \"gif\"]: the error does not name the key and 'gif': {refused.stderr!r}")
    for failure in failures:
        print(failure)
    print(f"{len(figures)} figures checked, {len(failures)} problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
