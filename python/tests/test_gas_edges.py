# SPDX-License-Identifier: BSD-3-Clause
"""restitution.gas at the edges of its domain (issue 44 items 3 and 6, issue 45 item 10): the collisions per
sphere to rounding at the first instants, --tolerance checked for every law, an extremely dilute gas computed
right and one beyond the doubles refused with the range that works."""

import math

import numpy as np
import pytest

import restitution

SPHERES = dict(radius=0.005, density=920.0, rms_speed=1.0)
GAS = dict(SPHERES, eps=0.8, velocity=2.0, packing_fraction=0.1)


def _collision_frequency_at_t0(phi):
    """Enskog's rate of one sphere at T0 [1/s]: 4 sqrt(pi) n g2 sigma^2 sqrt(T0/m), sqrt(T0/m) = rms speed."""
    sigma = 2.0 * SPHERES["radius"]
    n = 6.0 * phi / (math.pi * sigma**3)
    g2 = (1.0 - phi / 2.0) / (1.0 - phi) ** 3
    return 4.0 * math.sqrt(math.pi) * n * g2 * sigma**2 * SPHERES["rms_speed"]


def test_collisions_per_sphere_at_the_first_instants():
    # N(t) = omega0 t (1 - t/(2 tau0) + O((t/tau0)^2)): to 1e-13 relative below 1e-7 tau0.
    g = restitution.gas(**GAS, haff_times=1.0, first_time=1e-20, points_per_decade=1)
    t = g["time_s"]
    early = t <= 1e-7 * g["tau0_s"]
    assert early.sum() >= 12
    expected = _collision_frequency_at_t0(0.1) * t[early] * (1.0 - t[early] / (2.0 * g["tau0_s"]))
    np.testing.assert_allclose(g["collisions_per_particle"][early], expected, rtol=1e-13, atol=0.0)


@pytest.mark.parametrize("law", ["viscoelastic-hertz", "tsuji-hertz"])
@pytest.mark.parametrize("tolerance", [-1.0, float("nan"), 1e-20, 0.5])
def test_tolerance_is_checked_for_every_law(law, tolerance):
    with pytest.raises(ValueError, match=r"tolerance must be in \[1e-11, 0.01\]"):
        restitution.gas(**GAS, law=law, duration=1.0, tolerance=tolerance)


def test_extremely_dilute_gas_cools_like_any_dilute_one():
    # tau0 ~ 1e298 s; main gave T/T0 = 0.61 (the end of the first panel) and a local exponent of -15.
    dilute = restitution.gas(**{**GAS, "packing_fraction": 1e-12}, haff_times=10, points_per_decade=2)
    extreme = restitution.gas(**{**GAS, "packing_fraction": 1e-300}, haff_times=10, points_per_decade=2)
    np.testing.assert_allclose(extreme["temperature_j"], dilute["temperature_j"], rtol=1e-12)
    np.testing.assert_allclose(extreme["local_exponent"], dilute["local_exponent"], rtol=1e-12)
    assert extreme["temperature_j"][-1] / extreme["initial_temperature_j"] == pytest.approx(0.012565, abs=1e-6)
    assert extreme["local_exponent"][-1] == pytest.approx(-1.5856, abs=1e-4)


def test_haff_time_beyond_the_doubles_is_refused_with_the_range():
    with pytest.raises(ValueError, match=r"tau0 = 1e303 s.*packing_fraction must be in \[1\.19e-302, 0\.5\) here"):
        restitution.gas(**{**GAS, "packing_fraction": 1e-305}, haff_times=100)
