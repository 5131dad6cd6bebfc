# SPDX-License-Identifier: BSD-3-Clause
"""Loaded by every Python the program starts while tests/plot_labels.py puts this folder on PYTHONPATH: each
figure saved is described (its texts, whether its titles fit, its format and resolution) as one JSON line
appended to $PLOT_TEXTS_LOG, for the test to judge. Does nothing without that variable."""
import os

if os.environ.get("PLOT_TEXTS_LOG"):
    import json

    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    original_savefig = Figure.savefig

    def describe(fig):
        fig.canvas.draw()
        renderer = fig.canvas.get_renderer()
        width = fig.bbox.width
        titles, labels, legends, others = [], [], [], []
        for ax in fig.axes:
            for loc in ("left", "center", "right"):
                if ax.get_title(loc):
                    titles.append(ax.title if loc == "center" else getattr(ax, f"_{loc}_title"))
            for axis in (ax.xaxis, ax.yaxis):
                if axis.label.get_text() and axis.label.get_visible():
                    labels.append(axis.label.get_text())
            if ax.get_legend() is not None:
                legends += [t.get_text() for t in ax.get_legend().get_texts()]
            others += [t.get_text() for t in ax.texts]
        if fig._suptitle is not None and fig._suptitle.get_text():
            titles.append(fig._suptitle)
        overflow = [t.get_text() for t in titles
                    if t.get_window_extent(renderer).x0 < -1 or t.get_window_extent(renderer).x1 > width + 1]
        return {"titles": [t.get_text() for t in titles], "labels": labels, "legends": legends, "others": others,
                "titles_outside": overflow}

    def recording_savefig(self, fname, *args, **kwargs):
        entry = describe(self)
        entry.update({"path": str(fname), "format": kwargs.get("format") or str(fname).rsplit(".", 1)[-1],
                      "dpi": kwargs.get("dpi") or matplotlib.rcParams["savefig.dpi"]})
        with open(os.environ["PLOT_TEXTS_LOG"], "a") as log:
            log.write(json.dumps(entry) + "\n")
        return original_savefig(self, fname, *args, **kwargs)

    Figure.savefig = recording_savefig
