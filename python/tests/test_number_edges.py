# SPDX-License-Identifier: BSD-3-Clause
"""Issue 33, items 8 and 9: a bool is no number (TypeError naming the argument), zeta below the smallest normal
double is refused as on the command line (1 - eps would be subnormal), zeta = 0 gives eps = 1 for every law."""

import sys

import numpy as np
import pytest

import restitution

TINY = 1e-320  # subnormal: 1 - eps ~ 1.15e-320 would carry a relative step of ~4e-4
NOT_SERVED = r"zeta = 1e-320 is below the smallest zeta served"


@pytest.mark.parametrize("flag", [True, False, np.bool_(True), [True, False], np.array([True])])
def test_bools_are_no_zeta(flag):
    with pytest.raises(TypeError, match=r"^zeta must (be|hold real numbers)"):
        restitution.eps(flag)
    with pytest.raises(TypeError, match=r"^zeta must (be|hold real numbers)"):
        restitution.solve(flag)
    with pytest.raises(TypeError, match=r"^zeta must (be|hold real numbers)"):
        restitution.zeta_of(flag)
    with pytest.raises(TypeError, match=r"^zeta must (be|hold real numbers)"):
        restitution.fast.eps(flag)
    with pytest.raises(TypeError, match=r"^zeta must (be|hold real numbers)"):
        restitution.series.eval("naive", flag)


def test_bools_are_no_speed_beta_or_eps():
    with pytest.raises(TypeError, match=r"^velocity must be"):
        restitution.eps(beta=0.1, velocity=True)
    with pytest.raises(TypeError, match=r"^beta must be"):
        restitution.eps(beta=True, velocity=1.0)
    with pytest.raises(TypeError, match=r"^eps must be"):
        restitution.fast.zeta_from_eps(True)
    with pytest.raises(TypeError, match=r"^velocity must be"):
        restitution.calibrate(0.8, True)


@pytest.mark.parametrize("field,value", [("young_modulus", True), ("radius", True), ("radii", (0.01, True)),
                                         ("density", np.bool_(True))])
def test_bools_are_no_material_data(field, value):
    fields = {"young_modulus": 2.1e11, "poisson_ratio": 0.3, "radius": 0.01, "density": 7850.0}
    if field == "radii":
        del fields["radius"]
    fields[field] = value
    with pytest.raises(TypeError, match=f"^Material: {field} must be"):
        restitution.Material(**fields)


def test_subnormal_zeta_is_refused_everywhere():
    with pytest.raises(ValueError, match=NOT_SERVED):
        restitution.eps(TINY)
    with pytest.raises(ValueError, match=NOT_SERVED + r".*\(zeta at index 1\)"):
        restitution.eps([0.1, TINY])
    with pytest.raises(ValueError, match=NOT_SERVED):
        restitution.solve(TINY)
    with pytest.raises(ValueError, match=NOT_SERVED):
        restitution.fast.eps(TINY)
    with pytest.raises(ValueError, match=NOT_SERVED):
        restitution.eps(TINY, law="tsuji-hertz")
    with pytest.raises(ValueError, match="below the smallest zeta served"):
        restitution.eps(beta=1e-320, velocity=1.0)
    smallest = sys.float_info.min
    for end in ("naive", "delayed-recovery"):
        assert restitution.eps(smallest, end=end) == 1.0
        one_minus = restitution.solve(smallest).naive.one_minus_eps
        assert one_minus / smallest == pytest.approx(1.15344885809, rel=1e-10)  # C1 in closed form (1999 paper, Eq. 30)


@pytest.mark.parametrize("law", ["viscoelastic-hertz", "linear-dashpot", "tsuji-hertz", "hertz-constant-damping"])
def test_zeta_zero_is_the_undamped_oscillator(law):
    result = restitution.solve(0.0, law=law)
    for end in (result.naive, result.delayed_recovery):
        assert end.eps == 1.0
        assert end.one_minus_eps == 0.0
