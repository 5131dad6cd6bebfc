# SPDX-License-Identifier: BSD-3-Clause
"""The one style of every report figure (scripts/plots/*.py import it): a journal's column widths with text of at
least 8 pt at that size, a colour-blind-safe palette, line widths, resolution, the words for the tables' columns,
log axes with enough labelled ticks, and save() writing each requested format.

Figures carry no title: the report's heading and caption (or the paper's) say what a figure shows. Text stays
text in PDF (TrueType, no Type 3 fonts) and SVG (editable, searchable), as journals ask.
"""
import argparse
import csv
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import ticker  # noqa: E402

FORMATS = ("png", "pdf", "svg")
DPI = 300  # PNG resolution; PDF and SVG are vector

# A journal's single and double column [inch]: every figure is drawn at one of them, so that its text is printed at
# the size set here (no figure is shrunk into a column).
SINGLE_COLUMN_IN = 3.5
DOUBLE_COLUMN_IN = 7.0
SMALLEST_FONT_PT = 8

# Okabe & Ito's palette (Color Universal Design, 2008), told apart with every common colour-vision deficiency; the
# order puts the most distinct first. Black and greys stay free for references (theory lines, limits).
OKABE_ITO = ("#0072B2", "#D55E00", "#009E73", "#E69F00", "#CC79A7", "#56B4E9", "#F0E442", "#000000")

matplotlib.rcParams.update({
    "font.size": SMALLEST_FONT_PT,
    "axes.labelsize": 9,
    "legend.fontsize": SMALLEST_FONT_PT,
    "xtick.labelsize": SMALLEST_FONT_PT,
    "ytick.labelsize": SMALLEST_FONT_PT,
    "axes.prop_cycle": matplotlib.cycler(color=OKABE_ITO),
    "image.cmap": "viridis",
    "lines.linewidth": 1.2,
    "lines.markersize": 3.5,
    "axes.linewidth": 0.8,
    "grid.alpha": 0.3,
    "grid.linewidth": 0.6,
    "legend.framealpha": 0.85,
    "legend.handlelength": 1.8,
    "mathtext.fontset": "dejavusans",
    "savefig.dpi": DPI,
    "pdf.fonttype": 42,
    "ps.fonttype": 42,
    "svg.fonttype": "none",
})

EPS = r"$\varepsilon$"
ZETA = r"$\zeta = \beta v^{1/5}$"

# What each end of the collision is, in the words of the 2008 paper.
ENDS = {
    "naive": r"naive end ($x = 0$)",
    "delayed_recovery": r"delayed recovery ($\ddot{x} = 0$)",
}

# The approximations a scene sets beside the numerics (src/scene/scene_approximations.hpp labels).
APPROXIMATIONS = {
    "naive_series": "naive series (2008, Table III, 10 terms)",
    "delayed_recovery_series": "delayed-recovery series (2008, Table V, 21 terms)",
    "pade_1999": "Padé [1/4] (1999)",
    "pade_1999_corrected": r"Padé [1/4] (1999, recomputed $a_3$, $a_4$)",
    "simple_theory_1999": r"simple theory $\varepsilon + w\varepsilon^{3/5} = 1$ (1999)",
    "pade_2011_1_4": r"Padé [1/4] in $\sqrt{\zeta}$ (2011)",
    "pade_2011_3_6": r"Padé [3/6] in $\sqrt{\zeta}$ (2011)",
    "naive_asymptotic": r"naive end, large-$\zeta$ law $\kappa\,\zeta^{-5}$",
    "delayed_recovery_asymptotic": r"delayed recovery, large-$\zeta$ law $(3/2)^{2/3}\zeta^{-5/3}$, corrected",
}

# Axis labels for the columns a table is plotted against.
AXES = {
    "zeta": ZETA,
    "velocity_m_s": r"impact speed $v$ (m/s)",
    "v": r"impact speed $v$ (m/s)",
    "damping_ratio": r"damping ratio $r$",
    "requested_eps": r"requested $\varepsilon$",
    "tau": r"scaled time $\tau$",
}

# The integration engines by their names on the command line.
ENGINES = {"taylor": "Taylor series", "adams": "CVODE Adams", "bdf": "CVODE BDF", "adams-plain": "CVODE Adams, plain",
           "bdf-plain": "CVODE BDF, plain", "auto": "automatic choice"}

DEM_CODES = {"lammps": "LAMMPS", "liggghts": "LIGGGHTS", "yade": "YADE"}

LAWS = {
    "viscoelastic-hertz": "viscoelastic Hertz",
    "tsuji-hertz": "Tsuji (Hertz)",
    "linear-dashpot": "linear dash-pot",
}


def law_label(name):
    """A fitted law's name as `fit-data` writes it (LAW_END, e.g. viscoelastic-hertz_delayed-recovery)."""
    law, _, end = name.partition("_")
    words = LAWS.get(law, law.replace("-", " "))
    return words + (", " + {"naive": "naive end"}.get(end, end.replace("-", " ")) if end else "")


def approximation_label(name):
    """An approximation by its catalogue name (`series validate`: pade-2011-1-4, naive-series:computed-40, ...)
    or its scene column label (pade_2011_1_4, naive_series, ...)."""
    base, _, variant = name.partition(":")
    words = APPROXIMATIONS.get(base.replace("-", "_"), name)
    computed = re.fullmatch(r"computed-(\d+)", variant)
    if computed:  # the series' coefficients recomputed here, to a chosen order
        return re.sub(r" \(2008.*\)", f", {computed.group(1)} terms (recomputed)", words)
    return words


def curve_label(column):
    """What a table column's curve is, in words and symbols (never the column's name)."""
    for end, words in ENDS.items():
        if column == end + "_eps":
            return words
        if column == end + "_eps_exact":
            return words.replace(" (", ", closed form (")
        if column == end + "_relative_error":
            return words
    for name, words in APPROXIMATIONS.items():
        if column in (name + "_eps", name + "_rel_diff"):
            return words
    if column == "empirical_eps":
        return "empirical law (scene)"
    if column == "eps_restitution":
        return "restitution (this code)"
    if column == "requested_eps":
        return r"actual = requested $\varepsilon$"
    match = re.fullmatch(r"eps_(\w+)", column)
    if match and match.group(1) in DEM_CODES:
        return DEM_CODES[match.group(1)] + " (extrapolated to zero time step)"
    if column == "rel_diff":
        return "DEM code against restitution"
    match = re.fullmatch(r"(.+)_clamp_(on|off)", column)
    if match:
        return f"{match.group(1)}, clamp {match.group(2)}"
    return column.replace("_", " ")


def curve_family(column):
    """Curves of one family share a colour: a damping recipe with the clamp on and off; an end's numerics, its
    closed form and its error; an approximation and its difference from the numerics."""
    return re.sub(r"_(clamp_on|clamp_off)$", "", re.sub(r"_(rel_diff|eps_exact|relative_error)$", "_eps", column))


def color(index):
    """The palette's colour number index (cycling), for curves coloured by their place in a list."""
    return OKABE_ITO[index % len(OKABE_ITO)]


def figure(rows=1, columns=1, width=SINGLE_COLUMN_IN, height=None, **options):
    """plt.subplots at a journal's column width (SINGLE_COLUMN_IN or DOUBLE_COLUMN_IN), height by default 3/4 of
    the single column per row of panels."""
    if width not in (SINGLE_COLUMN_IN, DOUBLE_COLUMN_IN):
        raise ValueError(f"a figure is {SINGLE_COLUMN_IN} or {DOUBLE_COLUMN_IN} in wide, not {width}")
    return plt.subplots(rows, columns, figsize=(width, height or 0.75 * SINGLE_COLUMN_IN * rows), **options)


def legend(ax, **options):
    """A legend inside the axes, or below them when it has too many entries to leave the curves visible (beside
    them it would widen the figure beyond its column)."""
    if len(ax.get_legend_handles_labels()[1]) > 5:
        options = {"loc": "upper center", "bbox_to_anchor": (0.5, -0.2), "ncol": 1, **options}
    return ax.legend(**options)


def number(value, digits=4):
    """A number for a legend or a note: at most `digits` significant digits (a figure shows, the tables carry all)."""
    return f"{value:.{digits}g}"


def axis_label(column):
    """The axis label of a column plotted along an axis (its symbol and unit)."""
    return AXES.get(column, column.replace("_", " "))


def _labelled_ticks(axis):
    """The major tick labels of an axis that are drawn: inside the view and with text."""
    low, high = sorted(axis.get_view_interval())
    return [t for t in axis.get_major_ticks()
            if t.label1.get_visible() and t.label1.get_text() and low <= t.get_loc() <= high]


def _plain_number(value, _position=None):
    return f"{value:g}"


def shows_tick_labels(axis):
    """False for an axis whose labels are hidden (the inner panel of a shared axis): another panel shows them."""
    return any(t.label1.get_visible() for t in axis.get_major_ticks())


def enough_log_ticks(fig):
    """Every log axis spanning less than a few decades gets ticks at 1, 2, 5 (then every digit) of each decade, so
    that at least two of them carry a number: matplotlib's default labels only powers of ten."""
    fig.canvas.draw()
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            if axis.get_scale() != "log" or not shows_tick_labels(axis) or len(_labelled_ticks(axis)) >= 2:
                continue
            for subs in ((1.0, 2.0, 5.0), tuple(float(d) for d in range(1, 10))):
                axis.set_major_locator(ticker.LogLocator(subs=subs))
                axis.set_major_formatter(ticker.FuncFormatter(_plain_number))
                axis.set_minor_formatter(ticker.NullFormatter())
                fig.canvas.draw()
                if len(_labelled_ticks(axis)) >= 2:
                    break


def parse_formats(text):
    """Parses "png,pdf,svg" (argparse type): a list without repeats, or an error naming the unknown format."""
    chosen = []
    for name in text.split(","):
        name = name.strip().lower()
        if name not in FORMATS:
            raise argparse.ArgumentTypeError(f"unknown figure format '{name}' (known: {', '.join(FORMATS)})")
        if name not in chosen:
            chosen.append(name)
    return chosen


def add_format_argument(parser):
    parser.add_argument("--format", type=parse_formats, default=["png"],
                        help="figure formats, comma-separated: png (%d dpi), pdf, svg" % DPI)


def table_figure_parser():
    """The arguments every script that draws one table takes: the CSV, the figure's path, --format."""
    parser = argparse.ArgumentParser()
    parser.add_argument("csv")
    parser.add_argument("png")
    add_format_argument(parser)
    return parser


def read_rows(path):
    """A CSV table's rows as dicts of text."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def save(fig, path, formats=("png",)):
    """Writes the figure once per format: PATH with its extension replaced by each format's. Returns the paths.

    No date is stamped into PDF or SVG, so that the same data give the same file."""
    stem = os.path.splitext(path)[0]
    fig.tight_layout()
    enough_log_ticks(fig)
    written = []
    for name in formats:
        out = f"{stem}.{name}"
        metadata = {"Date": None} if name == "svg" else ({"CreationDate": None} if name == "pdf" else None)
        fig.savefig(out, format=name, dpi=DPI, bbox_inches="tight", metadata=metadata)
        written.append(out)
    plt.close(fig)
    return written
