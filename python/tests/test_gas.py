# SPDX-License-Identifier: BSD-3-Clause
"""Issue 35 item 1: restitution.gas gives what `restitution gas --json` gives, key for key and value for value;
a constant eps cools by Haff's law with its closed-form tau0; bad arguments raise errors naming them."""

import json
import math

import numpy as np
import pytest

import restitution

# The issue's gas: eps = 0.8 at 2 m/s, R = 5 mm, rho = 920 kg/m^3, phi = 0.1, rms speed 1 m/s, 1000 Haff times.
ISSUE = dict(radius=0.005, density=920.0, eps=0.8, velocity=2.0, packing_fraction=0.1, rms_speed=1.0,
             haff_times=1000)
# The same spheres by their material's dissipative constant, over 1 s, with van Noije & Ernst's a2.
MATERIAL = dict(radius=0.005, density=920.0, young_modulus=1e8, poisson_ratio=0.4, dissipative_constant=1e-5,
                packing_fraction=0.1, temperature=1e-4, duration=1.0, points_per_decade=5, a2="haff")
# The issue's gas with the evolving a2: its curve gains the array "a2", in place of the number.
EVOLVING = dict(ISSUE, a2="evolving", haff_times=100)
# The issue's gas driven (issue 49): a Langevin bath from a cold start, white noise with the evolving a2.
LANGEVIN = dict(ISSUE, haff_times=10, thermostat="langevin", bath_temperature=1e-3, bath_time=0.5, rms_speed=0.1)
WHITE_NOISE = dict(ISSUE, haff_times=10, thermostat="white-noise", power=1e-4, a2="evolving")


def _options(arguments):
    """The command line's words for the keyword arguments."""
    words = []
    for name, value in arguments.items():
        words += ["--" + name.replace("_", "-"), str(value)]
    return words


def _same(python_value, cli_value, key):
    if isinstance(cli_value, dict):
        assert set(python_value) == set(cli_value), key
        for name in cli_value:
            _same(python_value[name], cli_value[name], f"{key}.{name}")
    elif isinstance(cli_value, list):
        assert isinstance(python_value, np.ndarray) and python_value.dtype == np.float64, key
        assert python_value.tolist() == cli_value, key
    else:
        assert python_value == cli_value, key


@pytest.mark.parametrize("arguments", [ISSUE, MATERIAL, EVOLVING, LANGEVIN, WHITE_NOISE],
                         ids=["issue", "material", "evolving", "langevin", "white-noise"])
def test_gas_equals_the_command_lines_json(cli, arguments):
    expected = json.loads(cli("gas", *_options(arguments), "--json"))
    for build_field in ("restitution", "sundials"):  # what built the program: restitution.build_info() says it
        del expected[build_field]
    got = restitution.gas(**arguments)
    assert set(got) == set(expected)
    for key in expected:
        _same(got[key], expected[key], key)


def test_evolving_a2_is_an_array_of_the_curve():
    g = restitution.gas(**EVOLVING)
    assert g["a2"].shape == g["time_s"].shape
    assert g["a2"][0] == pytest.approx(0.0, abs=1e-4) and g["a2"][-1] < -0.01  # from Maxwellian to negative


def test_mass_gives_what_density_gives():
    by_density = restitution.gas(**ISSUE)
    mass = 4.0 / 3.0 * math.pi * 0.005**3 * 920.0
    by_mass = restitution.gas(**{**ISSUE, "density": None, "mass": mass})
    assert by_mass["mass_kg"] == pytest.approx(by_density["mass_kg"], rel=1e-15)
    np.testing.assert_allclose(by_mass["temperature_j"], by_density["temperature_j"], rtol=1e-13)


def test_a_constant_eps_cools_by_haffs_law():
    # The linear dash-pot's eps does not depend on the speed: Haff's gas, T = T0/(1 + t/tau0)^2 with
    # 1/tau0 = (2 sqrt(pi)/3)(1 - eps^2) n g2 sigma^2 sqrt(T0/m).
    eps, phi, radius, density, rms_speed = 0.8, 0.1, 0.005, 920.0, 1.0
    g = restitution.gas(radius=radius, density=density, eps=eps, velocity=2.0, law="linear-dashpot",
                        packing_fraction=phi, rms_speed=rms_speed, haff_times=1000)
    sigma = 2.0 * radius
    mass = 4.0 / 3.0 * math.pi * radius**3 * density
    n = 6.0 * phi / (math.pi * sigma**3)
    g2 = (1.0 - phi / 2.0) / (1.0 - phi) ** 3
    t0 = mass * rms_speed**2
    tau0 = 1.0 / ((2.0 * math.sqrt(math.pi) / 3.0) * (1.0 - eps**2) * n * g2 * sigma**2 * math.sqrt(t0 / mass))
    assert g["haff_eps"] == pytest.approx(eps, abs=1e-9)
    assert g["contact_correlation"] == pytest.approx(g2, rel=1e-14)
    assert g["tau0_s"] == pytest.approx(tau0, rel=1e-8)
    t = g["time_s"]
    np.testing.assert_allclose(g["temperature_j"], t0 / (1.0 + t / tau0) ** 2, rtol=1e-8)
    np.testing.assert_allclose(g["local_exponent"], -2.0 * t / (t + tau0), rtol=1e-7, atol=1e-12)
    assert t[-1] == pytest.approx(1000 * tau0, rel=1e-8)


@pytest.mark.parametrize("change, words", [
    (dict(packing_fraction=0.5), "packing_fraction must be in"),
    (dict(packing_fraction=None), "needs packing_fraction"),
    (dict(temperature=1e-4), "rms_speed and temperature"),
    (dict(haff_times=None), "duration and haff_times"),
    (dict(radius=None), "needs radius"),
    (dict(radius=-1.0), "radius must be finite and > 0"),
    (dict(mass=1e-3), "mass and density"),
    (dict(velocity=None), "eps with velocity"),
    (dict(dissipative_constant=1e-5), "dissipative_constant excludes eps and velocity"),
    (dict(law="hooke"), "law"),
    (dict(end="late"), "end"),
    (dict(a2="much"), "a2 must be a number, 'haff' or 'evolving'"),
    (dict(points_per_decade=0), "points_per_decade must be in"),
    (dict(first_time=-1.0), "first_time"),
    (dict(collision_rate_factor=0.0), "collision_rate_factor"),
    (dict(rms_speed=float("nan")), "rms_speed must be finite"),
])
def test_bad_arguments_raise_value_errors_naming_them(change, words):
    with pytest.raises(ValueError, match=words):
        restitution.gas(**{**ISSUE, **change})


def test_dissipative_constant_needs_the_elastic_data():
    with pytest.raises(ValueError, match="dissipative_constant needs the material's young_modulus and poisson_ratio"):
        restitution.gas(**{**MATERIAL, "young_modulus": None})


@pytest.mark.parametrize("change", [dict(radius="5 mm"), dict(points_per_decade=2.5), dict(a2=[0.1]),
                                    dict(law=None)])
def test_wrong_types_raise_type_errors(change):
    with pytest.raises(TypeError):
        restitution.gas(**{**ISSUE, **change})


def test_white_noise_with_a_constant_eps_gives_van_noije_and_ernsts_a2():
    # The linear dash-pot's eps does not depend on the speed; van Noije & Ernst (1998), white noise, d = 3.
    eps = 0.8
    g = restitution.gas(**{**WHITE_NOISE, "law": "linear-dashpot"})
    expected = 16 * (1 - eps) * (1 - 2 * eps**2) / (241 - 177 * eps + 30 * eps**2 * (1 - eps))
    assert g["steady_a2"] == pytest.approx(expected, abs=1e-9)  # eps of the calibration: 1e-10
    assert g["constant_eps_driving_exponent"] == pytest.approx(2 / 3, rel=1e-12)


def test_thermostat_arguments_are_named():
    with pytest.raises(ValueError, match="bath_time"):
        restitution.gas(**{**LANGEVIN, "bath_time": None})
    with pytest.raises(ValueError, match="thermostat"):
        restitution.gas(**{**ISSUE, "power": 1.0})
    with pytest.raises(ValueError, match="thermostat"):
        restitution.gas(**{**ISSUE, "thermostat": "shaker", "power": 1.0})
