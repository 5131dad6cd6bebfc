#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""A gas deck's LAMMPS runs against the kinetic theory: T(t)/T0 (top) and the local exponent d ln T/d ln t
(bottom), points for the runs, lines for the theory, one colour per law, with Haff's -2 and, when a viscoelastic
run is shown, its -5/3. Usage: gas_compare.py CSV OUT_PNG [--format png,pdf,svg], the CSV of
`restitution gas --compare-output` (columns run, law, time_s, temperature_j, theory_temperature_j, local_exponent,
theory_local_exponent; the exponents empty at t = 0)."""
import style  # first: it selects the Agg backend and sets the style

LAW_WORDS = {"viscoelastic": "viscoelastic Hertz", "constant-eps": r"constant $\varepsilon$"}


def main():
    a = style.table_figure_parser().parse_args()
    rows = style.read_rows(a.csv)
    fig, (top, bottom) = style.figure(2, 1, width=style.DOUBLE_COLUMN_IN, height=4.8, sharex=True)
    laws = list(dict.fromkeys(r["law"] for r in rows))
    exponents = [-2.0]
    for run in dict.fromkeys(r["run"] for r in rows):
        pts = [r for r in rows if r["run"] == run and float(r["time_s"]) > 0]
        law = pts[0]["law"]
        colour = style.color(laws.index(law))
        words = LAW_WORDS.get(law, law)
        t0 = float(next(r for r in rows if r["run"] == run)["temperature_j"])
        t = [float(r["time_s"]) for r in pts]
        top.loglog(t, [float(r["temperature_j"]) / t0 for r in pts], "o", color=colour, label=f"LAMMPS, {words}")
        top.loglog(t, [float(r["theory_temperature_j"]) / t0 for r in pts], "-", color=colour,
                   label=f"kinetic theory, {words}")
        with_exponent = [r for r in pts if r["local_exponent"]]
        te = [float(r["time_s"]) for r in with_exponent]
        measured = [float(r["local_exponent"]) for r in with_exponent]
        theory = [float(r["theory_local_exponent"]) for r in with_exponent]
        exponents += measured + theory
        bottom.semilogx(te, measured, "o", color=colour)
        bottom.semilogx(te, theory, "-", color=colour)
    bottom.axhline(-2.0, color="k", ls=":", lw=1, label="Haff: $-2$")
    if "viscoelastic" in laws:
        bottom.axhline(-5.0 / 3.0, color="k", ls="--", lw=1, label="viscoelastic asymptote: $-5/3$")
    # Both guides inside the axes, never on their edge.
    bottom.set_ylim(min(exponents) - 0.15, max(exponents + [0.0]) + 0.1)
    top.set_ylabel(r"$T(t) / T_0$")
    bottom.set_xlabel(r"time $t$ (s)")
    bottom.set_ylabel(r"$d\ln T / d\ln t$")
    for ax in (top, bottom):
        ax.grid(True, which="major")
        ax.legend(loc="lower left")
    style.save(fig, a.png, a.format)


if __name__ == "__main__":
    main()
