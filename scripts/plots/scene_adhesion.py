# SPDX-License-Identifier: BSD-3-Clause
"""ε against the impact speed of a scene's [[adhesion]] section (restitution run, docs/scenes.md), the sticking
region v < v_s shaded.

usage: scene_adhesion.py CSV PNG --sticking-speed V_S --model WORDS [--xscale log] [--format png,pdf,svg]
The CSV has the columns of `restitution sweep --adhesion` (velocity_m_per_s, outcome, eps, ...).
"""
import style  # first: it selects the Agg backend and sets the style


def main():
    p = style.table_figure_parser()
    p.add_argument("--sticking-speed", type=float, required=True)  # m/s; 0: the spheres never stick
    p.add_argument("--model", required=True)  # the model in words, for the legend
    p.add_argument("--xscale", default="linear")
    a = p.parse_args()
    rows = style.read_rows(a.csv)
    speeds = [float(r["velocity_m_per_s"]) for r in rows]
    # Stuck and bounced apart: a line from the last stuck point to the first bounce would hide the jump at v_s.
    bounced = [(float(r["velocity_m_per_s"]), float(r["eps"])) for r in rows if r["outcome"] == "bounced"]
    stuck = [float(r["velocity_m_per_s"]) for r in rows if r["outcome"] == "stuck"]
    fig, ax = style.figure(width=style.SINGLE_COLUMN_IN, height=2.8)
    low, high = min(speeds), max(speeds)
    v_s = a.sticking_speed
    if v_s > low:
        ax.axvspan(low, min(v_s, high), color=style.color(0), alpha=0.15, lw=0, label=r"sticking region $v < v_s$")
    if low < v_s < high:
        ax.axvline(v_s, color=style.color(0), lw=0.8, ls=":", label=rf"$v_s$ = {style.number(v_s)} m/s")
    if stuck:
        ax.plot(stuck, [0.0] * len(stuck), "x", markersize=4, color=style.color(0), label=r"stuck ($\varepsilon = 0$)")
    if bounced:
        ax.plot(*zip(*bounced), "o-", markersize=3, color=style.color(1), label=f"bounced: {a.model}")
    ax.set_xscale(a.xscale)
    ax.set_xlim(low, high)
    ax.set_ylim(-0.02, 1.02)
    ax.set_xlabel(style.axis_label("velocity_m_s"))
    ax.set_ylabel(r"coefficient of restitution $\varepsilon$")
    ax.grid(True, which="both", alpha=0.3)
    style.legend(ax)
    style.save(fig, a.png, a.format)


if __name__ == "__main__":
    main()
