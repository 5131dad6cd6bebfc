# SPDX-License-Identifier: BSD-3-Clause
"""restitution.gas: the freely cooling gas. A constant eps (the Tsuji law) follows Haff's law written out here;
the viscoelastic gas cools more slowly, its late exponent between -2 and -5/3; beta of a Material gives the same
curve as the eps it calibrates to; bad arguments raise ValueError or TypeError naming them."""

import math

import numpy as np
import pytest

import restitution

MASS = 4.0 / 3.0 * math.pi * 0.005 ** 3 * 920.0  # kg: R = 5 mm, 920 kg/m^3
GAS = dict(mass=MASS, diameter=0.01, packing_fraction=0.1, rms_speed=1.0)


def test_constant_eps_follows_haff():
    g = restitution.gas(**GAS, eps=0.7, velocity=2.0, law="tsuji-hertz", haff_times=1e3)
    phi, sigma = 0.1, 0.01
    n = 6 * phi / (math.pi * sigma ** 3)
    g2 = (1 - phi / 2) / (1 - phi) ** 3
    eps = g["haff_eps"]
    assert abs(eps - 0.7) < 1e-9
    tau0 = 1 / (2 * math.sqrt(math.pi) / 3 * (1 - eps * eps) * n * g2 * sigma ** 2 * math.sqrt(1.0))
    assert abs(g["tau0_s"] / tau0 - 1) < 1e-12
    t = g["time_s"]
    assert isinstance(t, np.ndarray) and t.shape == (121,)
    haff = MASS / (1 + t / tau0) ** 2
    assert np.max(np.abs(g["temperature_j"] / haff - 1)) < 1e-10
    assert np.max(np.abs(g["local_exponent"] + 2 * t / (tau0 + t))) < 1e-10


def test_viscoelastic_gas_cools_more_slowly():
    g = restitution.gas(**GAS, eps=0.8, velocity=2.0, haff_times=1e3)
    assert np.all(g["temperature_j"] > g["haff_temperature_j"])
    assert -2.0 < g["local_exponent"][-1] < -5.0 / 3.0
    assert g["effective_eps"][-1] > g["haff_eps"]


def test_beta_gives_the_curve_of_its_eps():
    by_eps = restitution.gas(**GAS, eps=0.8, velocity=2.0, duration=1.0, points_per_decade=2)
    beta = by_eps["zeta_at_reference"] / 2.0 ** 0.2
    by_beta = restitution.gas(**GAS, beta=beta, duration=1.0, points_per_decade=2)
    assert np.allclose(by_beta["temperature_j"], by_eps["temperature_j"], rtol=1e-12, atol=0)


@pytest.mark.parametrize("changes, word", [
    (dict(packing_fraction=0.5), "packing_fraction"),
    (dict(packing_fraction=-0.1), "packing_fraction"),
    (dict(temperature=1e-3), "rms_speed"),
    (dict(rms_speed=float("nan")), "rms_speed"),
    (dict(haff_times=10.0), "haff_times"),
    (dict(mass=0.0), "mass"),
])
def test_bad_values_are_named(changes, word):
    arguments = dict(GAS, eps=0.8, velocity=2.0, duration=1.0)
    arguments.update(changes)
    with pytest.raises(ValueError, match=word):
        restitution.gas(**arguments)


def test_bad_types_are_named():
    with pytest.raises(TypeError, match="mass"):
        restitution.gas(**dict(GAS, mass="heavy"), eps=0.8, velocity=2.0, duration=1.0)
    with pytest.raises(TypeError, match="beta"):
        restitution.gas(**GAS, beta=0.1, law="tsuji-hertz", duration=1.0)
