# SPDX-License-Identifier: BSD-3-Clause
"""The one style of every report figure (scripts/plots/*.py import it): font sizes, line widths, resolution, the
words for the tables' columns, titles that fit, and save() writing each requested format.

Text stays text in PDF (TrueType, no Type 3 fonts) and SVG (editable, searchable), as journals ask.
"""
import argparse
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FORMATS = ("png", "pdf", "svg")
DPI = 200  # PNG resolution; PDF and SVG are vector

matplotlib.rcParams.update({
    "font.size": 9,
    "axes.titlesize": 10,
    "axes.labelsize": 10,
    "legend.fontsize": 8,
    "xtick.labelsize": 9,
    "ytick.labelsize": 9,
    "lines.linewidth": 1.5,
    "lines.markersize": 4,
    "axes.linewidth": 0.8,
    "grid.alpha": 0.3,
    "grid.linewidth": 0.6,
    "legend.framealpha": 0.85,
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


def legend(ax, **options):
    """A legend inside the axes, or beside them when it has too many entries to leave the curves visible."""
    if len(ax.get_legend_handles_labels()[1]) > 6:
        options = {"loc": "center left", "bbox_to_anchor": (1.02, 0.5), **options}
    return ax.legend(**options)


def axis_label(column):
    """The axis label of a column plotted along an axis (its symbol and unit)."""
    return AXES.get(column, column.replace("_", " "))


def _fitted(text_artist, width_pixels):
    """Breaks a title's text into lines no wider than width_pixels, measured as drawn; a $...$ formula is never
    split."""
    words = re.findall(r"(?:\$[^$]*\$|[^\s$])+", text_artist.get_text())
    renderer = text_artist.figure.canvas.get_renderer()
    lines = []
    for word in words:
        candidate = (lines[-1] + " " + word) if lines else word
        text_artist.set_text(candidate)
        if lines and text_artist.get_window_extent(renderer).width > width_pixels:
            lines.append(word)
        elif lines:
            lines[-1] = candidate
        else:
            lines.append(word)
    text_artist.set_text("\n".join(lines))


def set_title(ax, text):
    """A title broken into lines that fit the width of its axes, so that it never runs off the figure."""
    if text:
        _fitted(ax.set_title(text), ax.get_position().width * ax.figure.bbox.width)


def suptitle(fig, text):
    """A figure title broken into lines that fit the figure's width."""
    if text:
        _fitted(fig.suptitle(text, fontsize=matplotlib.rcParams["axes.titlesize"] + 1), 0.95 * fig.bbox.width)


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


def save(fig, path, formats=("png",)):
    """Writes the figure once per format: PATH with its extension replaced by each format's. Returns the paths.

    No date is stamped into PDF or SVG, so that the same data give the same file."""
    stem = os.path.splitext(path)[0]
    fig.tight_layout()
    written = []
    for name in formats:
        out = f"{stem}.{name}"
        metadata = {"Date": None} if name == "svg" else ({"CreationDate": None} if name == "pdf" else None)
        fig.savefig(out, format=name, dpi=DPI, bbox_inches="tight", metadata=metadata)
        written.append(out)
    plt.close(fig)
    return written
