# SPDX-License-Identifier: BSD-3-Clause
"""restitution.oblique (docs/oblique.md): the command line's numbers for the same impacts, the closed form of a
contact that slides throughout, arrays over angle and spin, the result's repr, pickling and its doctest, and
bad arguments named."""

import doctest
import json
import math
import pickle
import warnings

import numpy as np
import pytest

import restitution
import restitution._oblique

STEEL = dict(young_modulus=2e11, poisson_ratio=0.3, radius=1e-3, density=7800.0)
ELASTIC = dict(STEEL, dissipative_constant=0.0)  # the damping is required: 0 says elastic
STEEL_CLI = ["--young-modulus", "2e11", "--poisson-ratio", "0.3", "--radius", "1e-3", "--density", "7800"]


@pytest.fixture
def steel_damped():
    return restitution.Material(**STEEL, dissipative_constant=1e-7)


def test_equals_the_command_line_value_for_value(cli, steel_damped):
    angles, spins = [0.0, 5.0, 20.0, 45.0, 80.0], [0.0, 300.0]
    arguments = dict(friction=0.3, tangential="linear_history", tangential_stiffness=2.2e6, tangential_damping=0.5)
    for wall in (True, False):
        out = json.loads(cli("oblique", *STEEL_CLI, "--dissipative-constant", "1e-7", "--tangential", "linear_history",
                             "--tangential-stiffness", "2.2e6", "--tangential-damping", "0.5", "--friction", "0.3",
                             "--angle", ",".join(map(str, angles)), "--spin", ",".join(map(str, spins)), "--json",
                             *(["--wall"] if wall else [])))
        r = restitution.oblique(material=steel_damped, angle=np.array(angles)[:, None], spin=spins, wall=wall,
                                **arguments)
        assert r.tangential_restitution.shape == (5, 2)
        for impact, (i, j) in zip(out["impacts"], np.ndindex(5, 2)):
            assert impact["angle_deg"] == r.angle_deg[i, j] and impact["initial_spin_rad_s"] == r.initial_spin_rad_s[i, j]
            e_t = impact["tangential_restitution"]
            assert (e_t is None and math.isnan(r.tangential_restitution[i, j])) or e_t == r.tangential_restitution[i, j]
            assert impact["normal_restitution"] == r.normal_restitution[i, j]
            assert impact["rebound_angle_deg"] == pytest.approx(r.rebound_angle_deg[i, j], rel=1e-15, abs=1e-15)
            assert impact["spin_rad_s"] == r.spin_rad_s[i, j] and impact["impulse_ratio"] == r.impulse_ratio[i, j]
            assert impact["stick_time_s"] == r.stick_time_s[i, j] and impact["slip_time_s"] == r.slip_time_s[i, j]
            assert [m["time_s"] for m in impact["modes"]] == list(r.switch_times[i, j])
            assert tuple(m["mode"] for m in impact["modes"]) == r.modes[i, j]
            assert impact["psi_out"] == r.psi_out[i, j]


def test_gross_sliding_closed_form(steel_damped):
    # A sphere on a wall that slides throughout: the contact-point velocity changes by -mu (1 + eps) v_n (1 + mR^2/I),
    # 1 + mR^2/I = 7/2, the spin by -mu (1 + eps) v_n m R/I, J_t/J_n = -mu (issue 37's closed form).
    mu, speed = 0.2, 2.0
    # linear_nohistory's force is min(cap, damping): a large damping keeps it at the cap.
    for tangential, stiffness, damping in (("linear_history", 2.2e6, 0.5), ("mindlin", None, 0.5),
                                           ("linear_nohistory", None, 1e3)):
        r = restitution.oblique(material=steel_damped, friction=mu, angle=[80.0, 85.0], spin=[0.0, 100.0],
                                impact_velocity=speed, wall=True, tangential=tangential, tangential_stiffness=stiffness,
                                tangential_damping=damping)
        v_n = speed * np.cos(np.radians(r.angle_deg))
        slip_in = speed * np.sin(np.radians(r.angle_deg)) + 1e-3 * r.initial_spin_rad_s
        change = -mu * (1.0 + r.normal_restitution) * v_n * 3.5
        assert all(modes == ("slip",) for modes in r.modes), (tangential, r.modes)
        np.testing.assert_allclose(r.slip_velocity, slip_in + change, rtol=1e-10)
        np.testing.assert_allclose(r.spin_rad_s - r.initial_spin_rad_s, change / 3.5 * 2.5 / 1e-3, rtol=1e-10)
        np.testing.assert_allclose(r.impulse_ratio, -mu, rtol=1e-10)
        np.testing.assert_allclose(np.tan(r.rebound_angle), r.tangential_velocity / r.normal_velocity, rtol=1e-14)
        np.testing.assert_allclose(r.rebound_angle_deg, np.degrees(r.rebound_angle), rtol=1e-15)
        np.testing.assert_allclose(r.stick_time_s + r.slip_time_s, r.contact_time_s, rtol=1e-12)


def test_frictionless_keeps_the_tangential_motion():
    # On a wall (a pair's line of centres turns, which moves u even without friction).
    r = restitution.oblique(material=restitution.Material(**ELASTIC), friction=0.0, angle=30.0, spin=50.0,
                            tangential="mindlin", wall=True)
    assert r.spin_rad_s == 50.0 and r.tangential_restitution == -1.0
    assert math.isnan(r.psi_in) and math.isnan(r.psi_out)


def test_scalars_give_floats_and_arrays_broadcast():
    steel = restitution.Material(**ELASTIC)
    one = restitution.oblique(material=steel, friction=0.3, angle=20, tangential="mindlin", wall=True)
    assert isinstance(one.tangential_restitution, float) and isinstance(one.modes, tuple)
    assert one.switch_times.dtype == np.float64 and one.switch_times[0] == 0.0
    many = restitution.oblique(material=steel, friction=0.3, angle=[10.0, 20.0, 30.0], tangential="mindlin",
                               wall=True)
    assert many.spin_rad_s.shape == (3,) and many.modes.shape == (3,)
    assert many.tangential_restitution[1] == one.tangential_restitution
    assert many.maw_chi == pytest.approx(3.5 * 0.7 / 1.7, rel=1e-15)


def test_repr_shows_units_and_results_pickle():
    r = restitution.oblique(material=restitution.Material(**ELASTIC), friction=0.3, angle=[10.0, 80.0],
                            tangential="mindlin", wall=True)
    text = repr(r)
    for piece in ("tangential_model='mindlin'", "rad/s", " deg", " s,", "rebound_angle=", "tangential_restitution="):
        assert piece in text
    one = restitution.oblique(material=restitution.Material(**ELASTIC), friction=0.3, angle=10.0, tangential="mindlin")
    assert "modes=stick from 0 s" in repr(one)
    for result in (r, one):
        back = pickle.loads(pickle.dumps(result))
        assert back == result and repr(back) == repr(result)
    assert r != one


def test_docstring_example_runs():
    result = doctest.testmod(restitution._oblique, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.attempted >= 5 and result.failed == 0


@pytest.mark.parametrize("arguments, error, words", [
    (dict(angle=95.0), ValueError, "angle must be in [0, 90)"),
    (dict(angle=10.0, spin=float("nan")), ValueError, "spin must be finite"),
    (dict(angle=10.0, friction=None), ValueError, "give friction"),
    (dict(angle=10.0, tangential="linear_histroy"), ValueError, "linear_histroy"),
    (dict(angle=10.0, tangential="linear_history", tangential_stiffness=None), ValueError, "tangential_stiffness"),
    (dict(angle=10.0, impact_velocity=-1.0), ValueError, "impact_velocity"),
    (dict(angle="10"), TypeError, "angle"),
    (dict(angle=10.0, wall=1), TypeError, "wall"),
    (dict(angle=[10.0, 20.0], spin=[1.0, 2.0, 3.0]), ValueError, "broadcast"),
    (dict(angle=10.0, wall=True, material=restitution.Material(young_modulus=2e11, poisson_ratio=0.3,
                                                               radii=(1e-3, 2e-3), density=7800.0)),
     ValueError, "wall takes one sphere"),
])
def test_bad_arguments_are_named(arguments, error, words):
    keywords = dict(material=restitution.Material(**ELASTIC), friction=0.3, tangential="mindlin")
    keywords.update(arguments)  # a material of its own replaces the default
    with pytest.raises(error, match=None) as caught:
        restitution.oblique(**keywords)
    assert words in str(caught.value)


def test_damping_is_required_or_calibrated_and_the_wall_is_rigid():
    # Issue 44 item 11: a Material without A was silently elastic; item 12: the wall of `dem --wall`.
    with pytest.raises(ValueError) as caught:
        restitution.oblique(material=restitution.Material(**STEEL), friction=0.3, angle=10.0)
    assert "dissipative_constant" in str(caught.value) and "eps" in str(caught.value)
    r = restitution.oblique(material=restitution.Material(**STEEL), eps=0.85, velocity=2.0, impact_velocity=2.0,
                            friction=0.3, angle=0.0, wall=True)
    assert r.normal_restitution == pytest.approx(0.85, abs=1e-9)
    assert r.rigid_wall and r.tangential_model == "mindlin" and r.dissipative_constant_s > 0.0
    own = restitution.oblique(material=restitution.Material(**STEEL), eps=0.85, velocity=2.0, impact_velocity=2.0,
                              friction=0.3, angle=0.0, wall=True, wall_young_modulus=2e11, wall_poisson_ratio=0.3)
    assert not own.rigid_wall and own.normal_restitution == pytest.approx(0.85, abs=1e-9)
    assert own.dissipative_constant_s != r.dissipative_constant_s  # calibrated on each contact
    with pytest.raises(ValueError, match="wall_poisson_ratio"):
        restitution.oblique(material=restitution.Material(**ELASTIC), friction=0.3, angle=10.0, wall=True,
                            wall_young_modulus=2e11)


def test_an_ill_conditioned_impact_warns_as_the_command_line_does(cli, steel_damped):
    # Near the stick/slip boundary (a second stick phase appears near 17.95 deg for this wall impact) the contract
    # cannot be shown: the command line says so on stderr and in the JSON, Python with a RuntimeWarning. A steel
    # wall (the boundary's angle is that of a wall of the sphere's material).
    arguments = dict(friction=0.3, tangential="linear_history", tangential_stiffness=2.2e6, tangential_damping=0.5,
                     wall=True, wall_young_modulus=2e11, wall_poisson_ratio=0.3)
    angles = np.linspace(17.94, 17.96, 21)
    out = json.loads(cli("oblique", *STEEL_CLI, "--dissipative-constant", "1e-7", "--tangential", "linear_history",
                         "--tangential-stiffness", "2.2e6", "--tangential-damping", "0.5", "--friction", "0.3",
                         "--wall", "--wall-young-modulus", "2e11", "--wall-poisson-ratio", "0.3",
                         "--angle", ",".join(repr(a) for a in angles), "--json"))
    flagged = [impact["angle_deg"] for impact in out["impacts"] if impact["conditioning"] != "well-conditioned"]
    assert flagged, "no flagged impact: the case no longer crosses the boundary"
    with pytest.warns(RuntimeWarning, match="ill-conditioned") as caught:
        restitution.oblique(material=steel_damped, angle=angles, **arguments)
    assert len([w for w in caught if "ill-conditioned" in str(w.message)]) == len(flagged)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        restitution.oblique(material=steel_damped, angle=[5.0, 45.0], **arguments)
