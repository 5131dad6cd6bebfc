# SPDX-License-Identifier: BSD-3-Clause
"""eps against the certified reference solutions at both ends, scalar and array, to the requested tolerance."""

import numpy as np
import pytest

import restitution

ENDS = {"naive": "naive", "delayed-recovery": "delayed_recovery"}  # the reference file's column prefixes


def _bound(row, prefix, tolerance):
    """The accuracy contract: |eps - eps*| <= tolerance * min(eps*, 1 - eps*)."""
    return tolerance * min(row[prefix + "_eps"], row[prefix + "_one_minus_eps"])


@pytest.mark.parametrize("end", ENDS)
@pytest.mark.parametrize("method,tolerance", [("auto", 1e-10), ("taylor", 1e-10), ("taylor", 1e-6)])
def test_array_matches_reference(reference, end, method, tolerance):
    rows = [row for row in reference if row["zeta"] <= 10.0]
    zetas = np.array([row["zeta"] for row in rows])
    eps = restitution.eps(zetas, end=end, tolerance=tolerance, method=method)
    prefix = ENDS[end]
    for row, value in zip(rows, eps):
        assert abs(value - row[prefix + "_eps"]) <= _bound(row, prefix, tolerance), row["zeta"]


@pytest.mark.parametrize("end", ENDS)
def test_scalar_matches_reference_and_array(reference, end):
    prefix = ENDS[end]
    zetas = np.array([row["zeta"] for row in reference[::5]])
    array = restitution.eps(zetas, end=end)
    for row, from_array in zip(reference[::5], array):
        value = restitution.eps(row["zeta"], end=end)
        assert isinstance(value, float)
        assert abs(value - row[prefix + "_eps"]) <= _bound(row, prefix, 1e-10)
        assert value == from_array  # a parallel sweep gives bitwise the serial numbers


def test_solve_reports_both_ends_and_max_compression(reference):
    row = next(r for r in reference if r["zeta"] == 1.0)
    result = restitution.solve(1.0)
    for prefix, end in (("naive", result.naive), ("delayed_recovery", result.delayed_recovery)):
        assert abs(end.eps - row[prefix + "_eps"]) <= _bound(row, prefix, 1e-10)
        assert abs(end.one_minus_eps - row[prefix + "_one_minus_eps"]) <= _bound(row, prefix, 1e-10)
        assert end.tau == pytest.approx(row[prefix + "_tau"], rel=1e-6)
        assert end.x == pytest.approx(row[prefix + "_x"], rel=1e-6, abs=1e-12)
    assert result.max_compression.x == pytest.approx(row["max_compression_x"], rel=1e-6)
    assert result.max_compression.tau == pytest.approx(row["max_compression_tau"], rel=1e-6)
    assert result.stats.steps > 0 and result.stats.rhs_evaluations > 0
    assert result.method in ("bdf", "adams") and result.zeta == 1.0 and result.tolerance == 1e-10
    assert not result.has_trajectory and result.tau.size == 0


def test_solve_one_end_and_trajectory():
    result = restitution.solve(0.5, end="delayed-recovery", trajectory=True)
    assert result.naive is None and result.delayed_recovery is not None
    tau, x, v, a = result.tau, result.x, result.velocity, result.acceleration
    assert tau.shape == x.shape == v.shape == a.shape and tau.size > 3
    assert np.all(np.diff(tau) > 0) and tau[0] == 0.0 and x[0] == 0.0 and v[0] == 1.0
    # The equation of motion holds along the recorded trajectory: x'' = -sqrt(x) (zeta x' + x).
    np.testing.assert_allclose(a, -np.sqrt(np.maximum(x, 0)) * (0.5 * v + x), rtol=1e-9, atol=1e-12)
    assert tau[-1] == pytest.approx(result.delayed_recovery.tau)


def test_beta_velocity_and_material_give_zeta_beta_v_to_the_fifth(steel):
    velocity = np.array([0.01, 0.1, 1.0, 10.0])
    expected = restitution.eps(steel.beta * velocity ** 0.2)
    # zeta agrees to rounding; eps then within the solver's tolerance.
    np.testing.assert_allclose(restitution.zeta_of(material=steel, velocity=velocity), steel.beta * velocity ** 0.2,
                               rtol=1e-15)
    np.testing.assert_allclose(restitution.eps(material=steel, velocity=velocity), expected, rtol=1e-12)
    np.testing.assert_array_equal(restitution.eps(beta=steel.beta, velocity=velocity),
                                  restitution.eps(material=steel, velocity=velocity))
    assert restitution.eps(material=steel, velocity=1.0) == restitution.eps(material=steel, velocity=[1.0])[0]


def test_material_constants_follow_the_formulas(steel):
    r_eff, m_eff = 0.005, 4.0 / 3.0 * np.pi * 0.01 ** 3 * 7800.0 / 2
    rho = 2 * 2.0e11 * np.sqrt(r_eff) / (3 * (1 - 0.3 ** 2))
    assert steel.effective_radius == pytest.approx(r_eff, rel=1e-15)
    assert steel.effective_mass == pytest.approx(m_eff, rel=1e-15)
    assert steel.k == pytest.approx(rho / m_eff, rel=1e-14)
    assert steel.beta == pytest.approx(1.5 * 1.0e-6 * steel.k ** 0.4, rel=1e-14)
    other = restitution.Material(young_modulus=2.0e11, poisson_ratio=0.3, radii=(0.01, 0.01),
                                 masses=(steel.effective_mass * 2,) * 2, dissipative_constant=1.0e-6)
    assert other.beta == pytest.approx(steel.beta, rel=1e-14)
    assert other.radii == (0.01, 0.01) and other.masses == (steel.effective_mass * 2,) * 2
    assert other.density is None and steel.masses is None and steel.viscosities is None


def test_calibrate_inverts_eps(steel):
    for end in ENDS:
        calibration = restitution.calibrate(0.8, 2.0, end=end, material=steel)
        assert restitution.eps(calibration.zeta, end=end) == pytest.approx(0.8, abs=1e-8)
        assert calibration.beta == pytest.approx(calibration.zeta / 2.0 ** 0.2, rel=1e-14)
        assert calibration.dissipative_constant_s == pytest.approx(calibration.beta / (1.5 * steel.k ** 0.4))
    # g* of the 1999 paper: (g/g*)^(1/5) = C1 zeta, C1 = 1.1534488580952888.
    assert calibration.characteristic_velocity_m_s == pytest.approx((1.1534488580952888 * calibration.beta) ** -5)
    assert restitution.calibrate(0.8, 2.0).dissipative_constant_s is None


def test_series_coefficients_match_the_2008_tables():
    c = restitution.series.coefficients("naive", 10)
    # c_1 = -C1 in closed form (1999 paper, Eq. 30); the 2008 table prints -1.153448854.
    assert c.shape == (10,) and c[0] == pytest.approx(-1.1534488580952888, rel=1e-15)
    assert c[1] == pytest.approx(0.7982665553, abs=1e-8)  # printed digits off at 1e-8: docs/series.md
    h = restitution.series.coefficients("delayed-recovery", 20)
    assert h.shape == (21,) and h[0] == 1.0 and h[5] == pytest.approx(0.2666666667, abs=1e-10)
    a, b = restitution.series.coefficients("max-compression", 5)
    assert a.shape == (5,) and b.shape == (6,) and b[0] == pytest.approx(1.093362074, abs=1e-9)


def test_series_eval_agrees_with_the_solver_at_small_zeta():
    zetas = np.array([[1e-3, 1e-2], [3e-2, 5e-2]])
    for kind, end in (("naive", "naive"), ("delayed-recovery", "delayed-recovery")):
        series = restitution.series.eval(kind, zetas)
        assert series.shape == (2, 2)
        np.testing.assert_allclose(series, restitution.eps(zetas, end=end), rtol=1e-9)
    assert isinstance(restitution.series.eval("pade-2011-3-6", 0.1), float)
    assert restitution.series.eval("naive", 0.1, terms=10, coefficients="published") == pytest.approx(
        restitution.series.eval("naive", 0.1, terms=10), rel=1e-9)


def test_material_with_viscosities_follows_the_1999_formula():
    young, nu, eta1, eta2 = 1.0e7, 0.4, 1.0e3, 2.0e3
    material = restitution.Material(young_modulus=young, poisson_ratio=nu, radius=0.02, density=1100.0,
                                    viscosities=(eta1, eta2))
    expected = (3 * eta2 - eta1) ** 2 / (3 * (3 * eta2 + 2 * eta1)) * (1 - nu ** 2) * (1 - 2 * nu) / (young * nu ** 2)
    assert material.A == pytest.approx(expected, rel=1e-14)
    assert material.viscosities == (eta1, eta2) and material.dissipative_constant is None


def test_series_eval_takes_every_approximation_name_and_the_old_aliases():
    zeta = [0.2, 0.6]
    for kind in restitution.series.evaluation_kinds:
        assert restitution.series.eval(kind, zeta).shape == (2,)
    assert list(restitution.series.eval("naive", zeta)) == list(restitution.series.eval("naive-series", zeta))
    assert list(restitution.series.eval("naive-series:published", zeta)) == list(
        restitution.series.eval("naive-series", zeta, coefficients="published"))
