# SPDX-License-Identifier: BSD-3-Clause
"""Bad input raises the documented exception with a message naming the value (and the index)."""

import math

import numpy as np
import pytest

import restitution


@pytest.mark.parametrize("zeta,shown", [(math.nan, "nan"), (-1.0, "-1"), (math.inf, "inf")])
def test_bad_zeta_scalar(zeta, shown):
    with pytest.raises(ValueError, match=f"zeta must be finite and >= 0, got {shown}$"):
        restitution.eps(zeta)


def test_bad_zeta_in_array_names_the_index():
    with pytest.raises(ValueError, match=r"got nan \(zeta at index 2\)"):
        restitution.eps([0.1, 0.2, math.nan, 0.3])
    with pytest.raises(ValueError, match=r"got -1 \(zeta at index \(1, 0\)\)"):
        restitution.eps([[0.1, 0.2], [-1.0, 0.3]])
    with pytest.raises(ValueError, match=r"velocity must be finite and > 0, got 0 \(beta, velocity at index 1\)"):
        restitution.eps(beta=0.1, velocity=[1.0, 0.0])


def test_taylor_naive_end_beyond_its_range_names_the_index():
    with pytest.raises(ValueError, match=r"naive end only for zeta <= 100.*got zeta=1000.*\(zeta at index 3\)"):
        restitution.eps([1.0, 10.0, 100.0, 1000.0], end="naive", method="taylor")


def test_empty_arrays():
    with pytest.raises(ValueError, match="empty array"):
        restitution.eps([])
    with pytest.raises(ValueError, match="empty array"):
        restitution.eps(np.zeros((0, 3)))
    with pytest.raises(ValueError, match="empty array"):
        restitution.series.eval("naive", [])


def test_wrong_end_method_and_tolerance():
    with pytest.raises(ValueError, match="end must be naive or delayed-recovery, got 'delayed'"):
        restitution.eps(0.1, end="delayed")
    with pytest.raises(ValueError, match="end must be naive or delayed-recovery, got 'both'"):
        restitution.eps([0.1], end="both")
    with pytest.raises(ValueError, match="end must be naive, delayed-recovery or both, got 'x'"):
        restitution.solve(0.1, end="x")
    with pytest.raises(ValueError, match="method must be bdf, adams, auto or taylor, got 'rk4'"):
        restitution.eps(0.1, method="rk4")
    with pytest.raises(ValueError, match="tolerance"):
        restitution.eps([0.1, 0.2], tolerance=1.0)


def test_wrong_types():
    with pytest.raises(TypeError, match="zeta must be a real number"):
        restitution.eps("0.1")
    with pytest.raises(TypeError, match="zeta must hold real numbers"):
        restitution.eps(["a", "b"])
    with pytest.raises(TypeError, match="zeta must hold real numbers"):
        restitution.eps([1 + 2j])
    with pytest.raises(TypeError, match="end must be a str"):
        restitution.eps([0.1], end=1)
    with pytest.raises(TypeError, match="tolerance must be a real number"):
        restitution.eps([0.1], tolerance="small")
    with pytest.raises(TypeError, match="exactly one of zeta, beta"):
        restitution.eps(0.1, beta=0.1, velocity=1.0)
    with pytest.raises(TypeError, match="need velocity"):
        restitution.eps(beta=0.1)
    with pytest.raises(TypeError, match="material must be a restitution.Material"):
        restitution.eps(material={"young_modulus": 1e9}, velocity=1.0)
    with pytest.raises(TypeError, match="solve\\(\\) takes one collision"):
        restitution.solve([0.1, 0.2])
    with pytest.raises(TypeError, match="count must be an int"):
        restitution.series.coefficients("naive", 2.5)


def test_calibrate_eps_outside_the_unit_interval():
    for eps in (0.0, 1.0, 1.5, -0.2, math.nan):
        with pytest.raises(ValueError, match="eps"):
            restitution.calibrate(eps, 1.0)
    with pytest.raises(ValueError, match="velocity"):
        restitution.calibrate(0.5, -1.0)


def test_material_errors_name_the_field():
    base = dict(young_modulus=1e9, poisson_ratio=0.3, radius=0.01, density=1000.0)
    with pytest.raises(ValueError, match="poisson_ratio must be in \\(-1, 0.5\\), got 0.7"):
        restitution.Material(**{**base, "poisson_ratio": 0.7})
    with pytest.raises(ValueError, match="young_modulus must be finite and > 0, got -1"):
        restitution.Material(**{**base, "young_modulus": -1.0})
    with pytest.raises(ValueError, match="give radius"):
        restitution.Material(**{**base, "radii": (0.01, 0.02)})
    with pytest.raises(ValueError, match="exactly one of dissipative_constant and viscosities"):
        restitution.Material(**base).beta
    with pytest.raises(TypeError):
        restitution.Material(**{**base, "radius": "big"})


def test_series_errors():
    with pytest.raises(ValueError, match="count 61 out of range \\[1, 60\\] for kind naive"):
        restitution.series.coefficients("naive", 61)
    with pytest.raises(ValueError, match="kind must be one of"):
        restitution.series.coefficients("wrong", 3)
    with pytest.raises(ValueError, match="terms applies to kind naive-series and delayed-recovery-series only, not pade-1999"):
        restitution.series.eval("pade-1999", 0.1, terms=3)
    with pytest.raises(ValueError, match="zeta at index 1"):
        restitution.series.eval("naive", [0.1, -0.1])


def test_numerical_failure_is_an_arithmetic_error():
    assert issubclass(restitution.NumericalFailure, ArithmeticError)


def test_zeta_beyond_the_checked_range_is_refused_like_the_cli():
    # One contract for every entry point: 0 <= zeta <= 1e6 (kLargestCheckedZeta), refused above it.
    checked = r"outside the checked range 0 <= zeta <= 1e\+06"
    with pytest.raises(ValueError, match=checked):
        restitution.eps(2e6)
    with pytest.raises(ValueError, match=checked + r".*\(zeta at index 1\)"):
        restitution.eps([1.0, 1e7])
    with pytest.raises(ValueError, match=checked):
        restitution.solve(1e10)
    with pytest.raises(ValueError, match=checked):
        restitution.eps(beta=10.0, velocity=1e31)  # zeta = 10 * (1e31)^(1/5) = 1e7
    assert restitution.eps(1e6) > 0.0  # the end of the range itself is computed


def test_calibration_below_the_checked_range_is_refused():
    with pytest.raises(ValueError, match="checked range"):
        restitution.calibrate(1e-12, velocity=1.0)
