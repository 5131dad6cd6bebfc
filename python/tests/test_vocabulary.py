# SPDX-License-Identifier: BSD-3-Clause
"""One vocabulary (issue 44, item 13; docs/cli.md, "Spellings"): oblique's impact speed is impact_velocity as on
the command line, the old keyword speed still works with a DeprecationWarning; end takes the attribute's
spelling "delayed_recovery"; a 0-d numpy array is the number it holds."""

import warnings

import numpy as np
import pytest

import restitution

STEEL = dict(young_modulus=2e11, poisson_ratio=0.3, radius=1e-3, density=7800.0, dissipative_constant=1e-7)


def test_oblique_takes_impact_velocity_and_warns_for_speed():
    steel = restitution.Material(**STEEL)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the new name warns of nothing
        new = restitution.oblique(material=steel, friction=0.3, angle=30.0, impact_velocity=2.0)
    with pytest.warns(DeprecationWarning, match="impact_velocity"):
        old = restitution.oblique(material=steel, friction=0.3, angle=30.0, speed=2.0)
    assert old == new
    slower = restitution.oblique(material=steel, friction=0.3, angle=30.0, impact_velocity=1.0)
    assert slower.contact_time != new.contact_time  # the speed is used, not ignored


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
