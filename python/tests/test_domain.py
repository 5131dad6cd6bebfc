# SPDX-License-Identifier: BSD-3-Clause
"""The domain every front end applies (issue 25, item 3): zeta <= 1e6 and, for a partial sum, its radius of
convergence; Python's series.eval refuses what `restitution series eval` refuses, in the same words."""

import pytest

import restitution


@pytest.mark.parametrize("kind,zeta,words", [
    ("naive-series", 5.0, "zeta = 5 is outside the radius of convergence of the naive-series series"),
    ("delayed-recovery", 2.0, "zeta = 2 is outside the radius of convergence of the delayed-recovery series"),
    ("pade-2011-3-6", 1e300, "zeta = 1e+300 is outside the checked range 0 <= zeta <= 1e+06"),
    ("simple-theory-1999", 2e6, "zeta = 2000000 is outside the checked range 0 <= zeta <= 1e+06"),
])
def test_series_eval_refuses_outside_the_domain(kind, zeta, words):
    with pytest.raises(ValueError, match=words.replace("+", r"\+")):
        restitution.series.eval(kind, zeta)


def test_series_eval_names_the_index_of_a_value_outside_the_domain():
    with pytest.raises(ValueError, match=r"outside the checked range .*\(zeta at index 1\)"):
        restitution.series.eval("pade-2011-1-4", [1.0, 1e7])


def test_series_eval_inside_the_domain_is_finite():
    assert 0.0 < restitution.series.eval("pade-2011-3-6", 1e6) < 1.0
    assert 0.0 < restitution.series.eval("naive-series", 1.0) < 1.0
