#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Copies a driven deck of `restitution gas --deck ... --thermostat langevin` (docs/gas.md, "The measured a2") with
one more print at each of its scheduled times: `probe-free law=... time_s=... free=... sum_v2_free=...
sum_v4_free=... contacts=...`, the number of spheres in no contact (LAMMPS's `compute contact/atom`), the sums of
|v|^2 and |v|^4 over them and the number of contacts summed over the spheres; optionally with the time step dt0
scaled. The deck's own lines are unchanged, so `gas --compare` reads the log as before and
scripts/driven_gas/steady_moments.py reads the probe.

    scripts/driven_gas/probe_contacts.py driven_constant_eps.in probe.in [DT_FACTOR]
"""
import re
import sys

COMPUTES = [
    "compute ncontact all contact/atom\n",
    "variable free atom c_ncontact==0\n",
    "variable s2free atom v_speed2*v_free\n",
    "variable s4free atom v_speed4*v_free\n",
    "compute freemoments all reduce sum v_free v_s2free v_s4free c_ncontact\n",
]
# thermo 0 invokes the thermo computes at each run's end, which keeps them current for the prints between runs
THERMO_EXTRA = " c_freemoments[1] c_freemoments[2] c_freemoments[3] c_freemoments[4]"


def probed(lines, dt_factor):
    out = []
    for line in lines:
        if line.startswith("variable dt0 equal") and dt_factor != 1.0:
            line = f"variable dt0 equal {float(line.split()[-1]) * dt_factor!r}\n"
        if line.startswith("thermo_style custom"):
            line = line.rstrip("\n") + THERMO_EXTRA + "\n"
        out.append(line)
        if line.startswith("compute moments"):
            out += COMPUTES
        if line.startswith('print "restitution-driven law='):
            law = re.search(r"law=(\S+)", line).group(1)
            out.append(f'print "probe-free law={law} time_s=$(time:%.10g) free=$(c_freemoments[1]:%.10g) '
                       "sum_v2_free=$(c_freemoments[2]:%.10g) sum_v4_free=$(c_freemoments[3]:%.10g) "
                       'contacts=$(c_freemoments[4]:%.10g)"\n')
    return out


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        lines = f.readlines()
    with open(sys.argv[2], "w") as f:
        f.writelines(probed(lines, float(sys.argv[3]) if len(sys.argv) == 4 else 1.0))


if __name__ == "__main__":
    main()
