#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The report figures are fit for a paper (issues 36 and 47): every figure of every shipped scene and of the
commands that draw one (`series validate`, `stability`, `gas --plot`, `oblique --plot`, `fit-data --plot`) is drawn
by the program itself, and each figure is judged as matplotlib holds it (tests/plot_hook/sitecustomize.py records
it):

* axis labels carry a mathtext symbol or a unit, and a physical quantity always its unit (or "scaled");
* no text is a table's column name (snake_case) or an ASCII spelling of a symbol (eps, zeta, tau, beta)
  outside mathtext;
* no title inside the figure (the report's heading and caption carry it);
* a journal's column: 3.5 in or 7 in wide, no wider as saved, every text >= 8 pt at that size;
* colour-blind-safe curves: Okabe & Ito's palette, black or grey;
* every log axis has at least 2 labelled ticks; legend numbers have at most 4 significant digits;
* PNG at >= 300 dpi;
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
# Okabe & Ito, Color Universal Design (2008): told apart with every common colour-vision deficiency.
OKABE_ITO = {"#0072b2", "#d55e00", "#009e73", "#e69f00", "#cc79a7", "#56b4e9", "#f0e442", "#000000"}
COLUMN_WIDTHS_IN = (3.5, 7.0)
SMALLEST_FONT_PT = 8
NUMBER = re.compile(r"\d+(?:\.\d+)?")


def significant_digits(number):
    """How many significant digits a number as written shows (trailing zeros of an integer do not count)."""
    digits = number.replace(".", "").lstrip("0")
    return len(digits if "." in number else digits.rstrip("0"))


def achromatic(colour):
    return colour[1:3] == colour[3:5] == colour[5:7]


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
    for text in figure["titles"]:
        found.append(f"{where}: title {text!r} inside the figure (the caption carries it)")
    if figure["width_in"] not in COLUMN_WIDTHS_IN:
        found.append(f"{where}: {figure['width_in']} in wide, not a column's {COLUMN_WIDTHS_IN}")
    if figure["saved_width_in"] > max(COLUMN_WIDTHS_IN) + 0.05:
        found.append(f"{where}: {figure['saved_width_in']:.2f} in wide as saved: shrunk into a page, its text "
                     f"falls below {SMALLEST_FONT_PT} pt")
    if figure["smallest_font_pt"] is not None and figure["smallest_font_pt"] < SMALLEST_FONT_PT:
        found.append(f"{where}: text at {figure['smallest_font_pt']} pt, below {SMALLEST_FONT_PT}")
    for colour in figure["colours"]:
        if colour not in OKABE_ITO and not achromatic(colour):
            found.append(f"{where}: a curve in {colour}, neither Okabe & Ito's palette nor grey")
    for axis in figure["log_axes"]:
        if len(axis["labelled_ticks"]) < 2:
            found.append(f"{where}: log {axis['axis']} axis of panel {axis['axes']} has "
                         f"{len(axis['labelled_ticks'])} labelled tick(s) {axis['labelled_ticks']}, fewer than 2")
    for text in figure["legends"]:
        for number in NUMBER.findall(text):
            if significant_digits(number) > 4:
                found.append(f"{where}: legend {text!r} shows {number} (more than 4 significant digits)")
    if figure["format"] == "png" and float(figure["dpi"]) < 300:
        found.append(f"{where}: PNG at {figure['dpi']} dpi, fewer than 300")
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
            run(exe, ["run", os.path.join("scenes", scene), "--quick", "--threads", "2", "--out", out], env,
                source)
            pngs += sum(1 for f in os.listdir(out) if f.endswith(".png"))
        run(exe, ["series", "validate", "--out", os.path.join(folder, "series")], env, source)
        run(exe, ["stability", "--tolerance", "1e-6", "--out", os.path.join(folder, "stability")], env, source)
        run(exe, ["gas", "--radius", "0.005", "--density", "920", "--eps", "0.8", "--velocity", "2",
                  "--packing-fraction", "0.1", "--rms-speed", "1", "--haff-times", "100", "--points-per-decade", "4",
                  "--plot", os.path.join(folder, "gas.png")], env, source)
        run(exe, ["oblique", "--young-modulus", "2e11", "--poisson-ratio", "0.3", "--radius", "1e-3", "--density",
                  "7800", "--dissipative-constant", "1e-7", "--wall", "--tangential", "mindlin", "--friction", "0.3",
                  "--angle-range", "1:80:6",
                  "--spin", "0,300", "--plot", os.path.join(folder, "oblique_maw.png")], env, source)
        run(exe, ["gas", "--radius", "0.005", "--density", "920", "--eps", "0.8", "--velocity", "2", "--law",
                  "linear-dashpot", "--packing-fraction", "0.1", "--rms-speed", "1", "--haff-times", "100",
                  "--plot", os.path.join(folder, "gas_constant.png")], env, source)
        run(exe, ["fit-data", os.path.join(source, "examples", "fit", "rubber_drop.csv"), "--plot",
                  os.path.join(folder, "fit.png")], env, source)
        pngs += 6
        with open(log) as f:
            figures = [json.loads(line) for line in f]
        # Each PNG written was recorded (the hook ran in every plot script), and none of them has a problem.
        recorded = sum(1 for fig in figures if fig["format"] == "png")
        if recorded != pngs or pngs < 18:
            failures.append(f"{recorded} figures recorded, {pngs} PNG files written (expected >= 18)")
        for figure in figures:
            failures += problems_of(figure)
        # A constant eps cools by Haff's law: no viscoelastic guide (-5/3, t^-5/3) in its figure.
        constant = [f for f in figures if os.path.basename(f["path"]).startswith(("gas_constant", "constant_eps_gas"))]
        for figure in constant:
            guides = [t for t in figure["legends"] if "5/3" in t]
            if guides:
                failures.append(f"gas --law linear-dashpot --plot draws viscoelastic guides: {guides}")

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
        run(exe, ["run", scene, "--out", out], {**os.environ}, source)
        written = sorted(f for f in os.listdir(out) if f.startswith("t."))
        if written != ["t.csv", "t.pdf", "t.svg"]:
            failures.append(f'format = ["svg", "pdf"] wrote {written}')
        with open(os.path.join(out, "report.md")) as f:
            if "](t.svg)" not in f.read():
                failures.append("report.md does not link the SVG figure of a scene without PNG")
        with open(scene, "w") as f:
            f.write('output = "x"\nformat = ["png", "gif"]\n[[trajectory]]\nname = "t"\nzeta = 0.5\n')
        refused = run(exe, ["run", scene, "--out", os.path.join(folder, "bad")], {**os.environ}, source, 2)
        if "format" not in refused.stderr or "'gif'" not in refused.stderr:
            failures.append(f"format = [..., \"gif\"]: the error does not name the key and 'gif': {refused.stderr!r}")
    for failure in failures:
        print(failure)
    print(f"{len(figures)} figures checked, {len(failures)} problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
