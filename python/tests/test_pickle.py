# SPDX-License-Identifier: BSD-3-Clause
"""Every public value type survives pickle (multiprocessing, joblib, dask) with every field, and its repr shows
every field with its unit."""

import concurrent.futures
import math
import pickle

import numpy as np
import pytest

import restitution

MATERIALS = {
    "density, A": dict(young_modulus=2.0e11, poisson_ratio=0.3, radius=0.01, density=7800.0, dissipative_constant=1e-6),
    "masses, viscosities": dict(young_modulus=1e7, poisson_ratio=0.45, radii=(0.01, 0.02), masses=(0.004, 0.03),
                                viscosities=(1e3, 2e3)),
    "elastic only": dict(young_modulus=1e9, poisson_ratio=0.2, radius=0.005, mass=0.001),
}
MATERIAL_FIELDS = ["young_modulus", "poisson_ratio", "radii", "density", "masses", "dissipative_constant", "viscosities",
                   "effective_radius", "effective_mass", "k"]


def _round_trip(value):
    copy = pickle.loads(pickle.dumps(value, protocol=pickle.HIGHEST_PROTOCOL))
    assert type(copy) is type(value)
    return copy


@pytest.mark.parametrize("fields", MATERIALS.values(), ids=MATERIALS.keys())
def test_material_round_trip(fields):
    material = restitution.Material(**fields)
    copy = _round_trip(material)
    for name in MATERIAL_FIELDS:
        assert getattr(copy, name) == getattr(material, name), name
    if material.dissipative_constant is not None or material.viscosities is not None:
        assert copy.beta == material.beta
    assert repr(copy) == repr(material)


def test_material_repr_shows_every_field_with_its_unit():
    text = repr(restitution.Material(**MATERIALS["density, A"]))
    for part in ["young_modulus=200000000000 Pa", "poisson_ratio=0.3", "radii=(0.01, 0.01) m", "density=7800 kg/m^3",
                 "masses=None", "dissipative_constant=1e-06 s", "viscosities=None"]:
        assert part in text, (part, text)
    text = repr(restitution.Material(**MATERIALS["masses, viscosities"]))
    assert "masses=(0.004, 0.03) kg" in text and "viscosities=(1000, 2000) Pa s" in text and "density=None" in text


def _same_end(a, b):
    for name in ["eps", "one_minus_eps", "tau", "x", "velocity", "dissipated_energy"]:
        assert getattr(a, name) == getattr(b, name), name


@pytest.mark.parametrize("end,trajectory", [("both", True), ("naive", False), ("delayed-recovery", True)])
def test_collision_result_round_trip(end, trajectory):
    result = restitution.solve(0.7, end=end, trajectory=trajectory)
    copy = _round_trip(result)
    for name in ["zeta", "law", "tolerance", "method", "has_trajectory"]:
        assert getattr(copy, name) == getattr(result, name), name
    for end_name in ["naive", "delayed_recovery"]:
        a, b = getattr(result, end_name), getattr(copy, end_name)
        assert (a is None) == (b is None), end_name
        if a is not None:
            _same_end(a, b)
    assert (copy.max_compression.tau, copy.max_compression.x) == (result.max_compression.tau, result.max_compression.x)
    assert repr(copy.stats) == repr(result.stats) and copy.stats.steps == result.stats.steps > 0
    for column in ["tau", "x", "velocity", "acceleration"]:
        np.testing.assert_array_equal(getattr(copy, column), getattr(result, column))
    assert copy.has_trajectory == trajectory
    assert repr(copy) == repr(result)


def test_parts_of_a_result_round_trip():
    result = restitution.solve(1.0, law="linear-dashpot")
    _same_end(_round_trip(result.naive), result.naive)
    assert repr(_round_trip(result.max_compression)) == repr(result.max_compression)
    stats = _round_trip(result.stats)
    for name in ["steps", "rhs_evaluations", "jacobian_evaluations", "root_evaluations", "error_test_failures",
                 "convergence_failures"]:
        assert getattr(stats, name) == getattr(result.stats, name), name
    assert _round_trip(result).law == "linear-dashpot"


def test_result_repr_shows_every_field():
    text = repr(restitution.solve(1.0))
    for part in ["law='viscoelastic-hertz'", "zeta=1,", "tolerance=1e-10", "method=", "max_compression=", "naive=",
                 "delayed_recovery=", "dissipated_energy=", "velocity=", "error_test_failures=",
                 "convergence_failures=", "trajectory=0 points", "natural units"]:
        assert part in text, (part, text)


@pytest.mark.parametrize("law,material", [("viscoelastic-hertz", True), ("viscoelastic-hertz", False),
                                          ("linear-dashpot", False)])
def test_calibration_round_trip(law, material):
    m = restitution.Material(**MATERIALS["elastic only"]) if material else None
    calibration = restitution.calibrate(0.8, 1.5, material=m, law=law)
    copy = _round_trip(calibration)
    for name in ["law", "zeta", "parameter", "beta", "eps_at_zeta", "characteristic_velocity_m_s",
                 "dissipative_constant_s", "solves"]:
        assert getattr(copy, name) == getattr(calibration, name), name
    assert repr(copy) == repr(calibration)
    assert ("dissipative_constant_s=None" in repr(calibration)) != material


def test_calibration_repr_shows_units():
    text = repr(restitution.calibrate(0.8, 1.0, material=restitution.Material(**MATERIALS["elastic only"])))
    for part in ["beta=", "s^(1/5) m^(-1/5)", "characteristic_velocity_m_s=", "m/s", "eps_at_zeta=", "solves=", " s,"]:
        assert part in text, (part, text)


def test_fit_result_round_trip():
    fit = restitution.fit_data([0.5, 1.0, 2.0, 4.0], [0.90, 0.88, 0.86, 0.83])
    assert _round_trip(fit) == fit


@pytest.mark.parametrize("state", [(), (1.0, 2.0)])
def test_a_foreign_state_is_refused_naming_the_type(state):
    with pytest.raises(ValueError, match="cannot unpickle Material"):
        restitution.Material.__new__(restitution.Material).__setstate__(state)


def test_a_state_breaking_the_rules_is_refused():
    state = restitution.Material(**MATERIALS["density, A"]).__getstate__()
    bad = (-1.0,) + tuple(state[1:])  # a negative Young's modulus
    with pytest.raises(ValueError, match="young"):
        restitution.Material.__new__(restitution.Material).__setstate__(bad)


def _eps_of(material):
    return restitution.eps(material=material, velocity=1.0)


def test_materials_cross_processes():
    """What multiprocessing does: a Material pickled to a worker process, its eps pickled back."""
    materials = [restitution.Material(**MATERIALS["density, A"]), restitution.Material(**MATERIALS["masses, viscosities"])]
    with concurrent.futures.ProcessPoolExecutor(max_workers=2) as pool:
        got = list(pool.map(_eps_of, materials))
    assert got == [_eps_of(m) for m in materials]
    assert all(0 < e < 1 and not math.isnan(e) for e in got)
