# SPDX-License-Identifier: BSD-3-Clause
"""One vocabulary (issue 44, item 13; docs/cli.md, "Spellings"): oblique's impact speed is impact_velocity as on
the command line, the old keyword speed still works with a DeprecationWarning; end takes the attribute's
spelling "delayed_recovery"; a 0-d numpy array is the number it holds; result attributes carry the JSON's names
with their units, the old names warn and give the same values."""

import json
import warnings

import numpy as np
import pytest

import restitution

STEEL = dict(young_modulus=2e11, poisson_ratio=0.3, radius=1e-3, density=7800.0, dissipative_constant=1e-7)
STEEL_CLI = ["--young-modulus", "2e11", "--poisson-ratio", "0.3", "--radius", "1e-3", "--density", "7800"]


def test_oblique_takes_impact_velocity_and_warns_for_speed():
    steel = restitution.Material(**STEEL)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the new name warns of nothing
        new = restitution.oblique(material=steel, friction=0.3, angle=30.0, impact_velocity=2.0)
    with pytest.warns(DeprecationWarning, match="impact_velocity"):
        old = restitution.oblique(material=steel, friction=0.3, angle=30.0, speed=2.0)
    assert old == new
    slower = restitution.oblique(material=steel, friction=0.3, angle=30.0, impact_velocity=1.0)
    assert slower.contact_time_s != new.contact_time_s  # the speed is used, not ignored


def test_oblique_names_impact_velocity_in_its_refusal():
    with pytest.raises(ValueError, match="impact_velocity"):
        restitution.oblique(material=restitution.Material(**STEEL), friction=0.3, angle=30.0, impact_velocity=-1.0)


def test_end_takes_the_attribute_spelling():
    assert restitution.eps(1.0, end="delayed_recovery") == restitution.eps(1.0, end="delayed-recovery")
    assert restitution.fast.eps(1.0, end="delayed_recovery") == restitution.fast.eps(1.0, end="delayed-recovery")
    result = restitution.solve(1.0, end="delayed_recovery")
    assert result.naive is None and result.delayed_recovery.eps == restitution.eps(1.0)
    c = restitution.calibrate(0.8, 1.0, end="delayed_recovery")
    assert c.beta == restitution.calibrate(0.8, 1.0).beta


def test_a_zero_dimensional_array_is_a_number():
    assert restitution.calibrate(np.array(0.8), np.array(1.0)).beta == restitution.calibrate(0.8, 1.0).beta
    assert restitution.eps(1.0, tolerance=np.array(1e-8)) == restitution.eps(1.0, tolerance=1e-8)
    steel = restitution.Material(**STEEL)
    assert (restitution.oblique(material=steel, friction=np.array(0.3), angle=30.0, impact_velocity=np.array(2.0))
            == restitution.oblique(material=steel, friction=0.3, angle=30.0, impact_velocity=2.0))
    gas = dict(radius=0.005, density=920.0, eps=0.8, packing_fraction=0.1, rms_speed=1.0, haff_times=100.0)
    assert (restitution.gas(**gas, velocity=np.array(2.0))["tau0_s"]
            == restitution.gas(**gas, velocity=2.0)["tau0_s"])


def _new_names_are_the_json_keys(result, json_object, renamed):
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the new names warn of nothing
        for _, new in renamed:
            assert getattr(result, new) == json_object[new], new
    for old, new in renamed:
        with pytest.warns(DeprecationWarning, match=f"{old} is deprecated.*0.5.0; use {new}$"):
            assert getattr(result, old) == getattr(result, new), old


def test_oblique_results_are_named_as_the_json(cli):
    out = json.loads(cli("oblique", *STEEL_CLI, "--dissipative-constant", "1e-7", "--friction", "0.3", "--angle", "30",
                         "--spin", "100", "--json"))
    r = restitution.oblique(material=restitution.Material(**STEEL), friction=0.3, angle=30.0, spin=100.0)
    assert r.spin_rad_s != r.initial_spin_rad_s and r.stick_time_s != r.slip_time_s  # no value stands in for another
    _new_names_are_the_json_keys(r, out["impacts"][0], (
        ("initial_spin", "initial_spin_rad_s"), ("spin", "spin_rad_s"), ("spin2", "spin2_rad_s"),
        ("contact_time", "contact_time_s"), ("stick_time", "stick_time_s"), ("slip_time", "slip_time_s")))
    _new_names_are_the_json_keys(r, out, (("dissipative_constant", "dissipative_constant_s"),))


def test_calibration_is_named_as_the_json(cli):
    out = json.loads(cli("calibrate", "--eps", "0.8", "--velocity", "2", *STEEL_CLI, "--json"))
    c = restitution.calibrate(0.8, 2.0, material=restitution.Material(**STEEL))
    _new_names_are_the_json_keys(c, out, (("characteristic_velocity", "characteristic_velocity_m_s"),
                                          ("dissipative_constant", "dissipative_constant_s")))
