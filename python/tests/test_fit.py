# SPDX-License-Identifier: BSD-3-Clause
"""restitution.fit_data: recovery of beta from exact data, the keys of the result, bad input."""

import pytest

import restitution


def _data(beta, end):
    v = [0.05, 0.2, 0.5, 1.0, 2.0, 5.0]
    eps = [float(restitution.fast.eps(beta * x ** 0.2, end)) for x in v]
    return v, eps


def test_recovers_beta_and_prefers_the_right_end():
    for end in ("naive", "delayed-recovery"):
        v, eps = _data(0.3, end)
        result = restitution.fit_data(v, eps)
        best = result["fits"][result["best"]]
        assert best["law"] == "viscoelastic-hertz" and best["end"] == end
        assert best["value"] == pytest.approx(0.3, rel=1e-9)
        assert result["sigma_estimated"] is True


def test_intervals_material_and_keys():
    v, eps = _data(0.2, "delayed-recovery")
    eps = [e + (0.01 if i % 2 else -0.01) for i, e in enumerate(eps)]
    steel = restitution.Material(young_modulus=2e11, poisson_ratio=0.3, radius=0.01, density=7800)
    result = restitution.fit_data(v, eps, sigma=[0.01] * len(v), material=steel)
    assert result["sigma_estimated"] is False
    hertz = result["fits"][0]
    assert hertz["parameter"] == "beta" and hertz["converged"]
    low, high = hertz["ci95"]
    assert low < hertz["value"] < high
    assert hertz["ci68"][0] > low and hertz["ci68"][1] < high
    a_low, a_high = hertz["dissipative_constant_ci95"]
    assert a_low < hertz["dissipative_constant_s"] < a_high
    assert [f["parameter"] for f in result["fits"]] == ["beta", "beta", "zeta", "damping-ratio"]


def test_laws_restricts_the_candidates():
    v, eps = _data(0.2, "naive")
    result = restitution.fit_data(v, eps, laws="viscoelastic-hertz")
    assert len(result["fits"]) == 2


@pytest.mark.parametrize("v, eps, sigma", [([1.0], [0.5], None), ([1.0, 2.0], [0.5, 1.5], None),
                                           ([1.0, -2.0], [0.5, 0.4], None), ([1.0, 2.0], [0.5, 0.4], [0.1, 0.0]),
                                           ([1.0, 2.0], [0.5, float("nan")], None)])
def test_bad_data_raise_value_error(v, eps, sigma):
    with pytest.raises(ValueError):
        restitution.fit_data(v, eps, sigma)


# issue 33, items 4, 7 and 9: extreme sigma, laws that are not candidates, untested residuals, 2-D arrays.
def test_extreme_sigma_is_fitted_or_refused_in_words():
    v, eps = _data(0.2, "delayed-recovery")
    for sigma in (1e-100, 1e100):
        result = restitution.fit_data(v, eps, sigma=[sigma] * len(v))
        assert all(f["chi2"] == f["chi2"] for f in result["fits"])  # no NaN
    for sigma in (1e-155, 1e155):
        with pytest.raises(ValueError, match=r"sigma must be in \[1e-100, 1e\+100\]"):
            restitution.fit_data(v, eps, sigma=[sigma] * len(v))


def test_a_law_that_is_not_a_candidate_is_refused():
    v, eps = _data(0.2, "delayed-recovery")
    with pytest.raises(ValueError, match="not a fit candidate: fit-data fits viscoelastic-hertz"):
        restitution.fit_data(v, eps, laws=["hertz-constant-damping"])


def test_residual_tests_that_could_not_run_say_so():
    result = restitution.fit_data([0.5, 1.0], [0.8, 0.75])
    for f in result["fits"]:
        tests = f["residual_tests"]
        assert tests["available"] is False
        assert tests["verdict"] == "n/a" and tests["unavailable"] == "too few points"


def test_two_dimensional_arrays_are_refused_naming_the_argument():
    import numpy as np

    v, eps = _data(0.2, "delayed-recovery")
    for name, args in (("v", (np.array([v, v]), eps + eps)), ("eps", (v + v, np.array([eps, eps]))),
                       ("sigma", (v, eps, np.full((2, 3), 0.01)))):
        with pytest.raises(ValueError, match=f"^{name} must be one-dimensional"):
            restitution.fit_data(*args)
