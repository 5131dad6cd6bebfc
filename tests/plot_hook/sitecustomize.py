# SPDX-License-Identifier: BSD-3-Clause
"""Loaded by every Python the program starts while tests/plot_labels.py puts this folder on PYTHONPATH: each
figure saved is described (its texts, whether its titles fit, its format and resolution, its size, smallest font,
line colours and the labelled ticks of its log axes) as one JSON line appended to $PLOT_TEXTS_LOG, for the test to
judge. Does nothing without that variable."""
import os

if os.environ.get("PLOT_TEXTS_LOG"):
    import json

    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.colors import to_hex
    from matplotlib.figure import Figure
    from matplotlib.text import Text

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
        fonts = [t.get_fontsize() for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip()]
        # The curves' colours (a legend's sample lines are no curves of their own).
        colours = sorted({to_hex(line.get_color()) for ax in fig.axes for line in ax.get_lines()
                          if line.get_visible() and len(line.get_xdata()) > 0})
        log_axes = []
        for index, ax in enumerate(fig.axes):
            for name, axis in (("x", ax.xaxis), ("y", ax.yaxis)):
                # A shared axis's inner panel hides its labels: the outer panel is judged.
                if axis.get_scale() == "log" and any(t.label1.get_visible() for t in axis.get_major_ticks()):
                    low, high = sorted(axis.get_view_interval())
                    labelled = [t.label1.get_text() for t in axis.get_major_ticks()
                                if t.label1.get_visible() and t.label1.get_text() and low <= t.get_loc() <= high]
                    log_axes.append({"axes": index, "axis": name, "labelled_ticks": labelled})
        tight = fig.get_tightbbox(renderer)  # inches: the figure as saved with bbox_inches="tight"
        return {"titles": [t.get_text() for t in titles], "labels": labels, "legends": legends, "others": others,
                "titles_outside": overflow, "width_in": float(fig.get_size_inches()[0]),
                "saved_width_in": float(tight.width), "smallest_font_pt": min(fonts) if fonts else None,
                "colours": colours, "log_axes": log_axes}

    def recording_savefig(self, fname, *args, **kwargs):
        entry = describe(self)
        entry.update({"path": str(fname), "format": kwargs.get("format") or str(fname).rsplit(".", 1)[-1],
                      "dpi": kwargs.get("dpi") or matplotlib.rcParams["savefig.dpi"]})
        with open(os.environ["PLOT_TEXTS_LOG"], "a") as log:
            log.write(json.dumps(entry) + "\n")
        return original_savefig(self, fname, *args, **kwargs)

    Figure.savefig = recording_savefig
