# SPDX-License-Identifier: BSD-3-Clause
"""The contact-law family from Python: law="NAME" in eps, solve and calibrate, against the closed forms of
the naive end (Tsuji: eps = exp(-pi zeta / sqrt(5 - zeta^2)); the linear dash-pot, zeta = 2 r:
eps = exp(-pi r / sqrt(1 - r^2)))."""

import math

import numpy as np
import pytest

import restitution

TOLERANCE = 1e-10


def tsuji_naive(zeta):
    return math.exp(-math.pi * zeta / math.sqrt(5.0 - zeta * zeta))


def dashpot_naive(r):
    return math.exp(-math.pi * r / math.sqrt(1.0 - r * r))


def close(computed, exact):
    return abs(computed - exact) <= 1.5 * TOLERANCE * min(exact, 1.0 - exact)


def test_eps_scalar_and_array_take_the_law():
    assert close(restitution.eps(1.5, end="naive", law="tsuji-hertz"), tsuji_naive(1.5))
    zetas = np.array([0.2, 1.0, 1.8])
    values = restitution.eps(zetas, end="naive", law="linear-dashpot")
    for zeta, value in zip(zetas, values):
        assert close(value, dashpot_naive(zeta / 2.0))


def test_solve_reports_the_law_and_the_dashpot_ratio():
    result = restitution.solve(0.8, law="linear-dashpot")
    assert result.law == "linear-dashpot"
    assert result.zeta == 0.4  # the damping ratio r = zeta / 2
    assert close(result.naive.eps, dashpot_naive(0.4))


def test_calibrate_inverts_the_closed_forms():
    c = restitution.calibrate(0.3, 1.0, end="naive", law="tsuji-hertz")
    l = -math.log(0.3) / math.pi
    assert c.law == "tsuji-hertz"
    assert c.zeta == pytest.approx(math.sqrt(5 * l * l / (1 + l * l)), rel=1e-8)
    d = restitution.calibrate(0.3, 1.0, end="naive", law="linear-dashpot")
    assert d.parameter == pytest.approx(l / math.sqrt(1 + l * l), rel=1e-8)


def test_bad_laws_are_refused_in_words():
    with pytest.raises(ValueError, match="law must be one of"):
        restitution.eps(1.0, law="hooke")
    with pytest.raises(TypeError, match="law='tsuji-hertz' takes zeta"):
        restitution.eps(beta=0.1, velocity=1.0, law="tsuji-hertz")
    with pytest.raises(ValueError, match="naive end does not exist"):
        restitution.eps(3.0, end="naive", law="tsuji-hertz")
