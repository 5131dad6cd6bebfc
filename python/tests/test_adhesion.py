# SPDX-License-Identifier: BSD-3-Clause
"""restitution.adhesive_collision and restitution.sticking_speed (docs/adhesion.md): the command line's numbers for
the same collisions (sjkr included), the undamped closed forms eps(v) = sqrt(1 - W/(m* v^2/2)) and v_s = sqrt(2W/m*) with W of
each break rule, the stub's model names, the doctests and bad arguments named."""

import doctest
import json
import math

import pytest

import restitution
import restitution._adhesion
from restitution import _restitution as _core

# µm water ice, docs/adhesion.md §7.
ICE = dict(young_modulus=7e9, poisson_ratio=0.25, radius=1.5e-6, density=920.0)
ICE_CLI = ["--young-modulus", "7e9", "--poisson-ratio", "0.25", "--radius", "1.5e-6", "--density", "920"]
GAMMA = 0.19
# The elastic hysteresis work of each JKR break rule in units of pi w A^2 (docs/adhesion.md §2):
# LAMMPS's force-controlled pull-off (3/5)2^(2/3) - (2/5)(9/8)^(2/3), the textbook one 1/10 + (3/5)2^(2/3).
W_SCALED = {"jkr-lammps": 0.6 * 2 ** (2 / 3) - 0.4 * (9 / 8) ** (2 / 3), "jkr": 0.1 + 0.6 * 2 ** (2 / 3)}


@pytest.fixture
def ice():
    return restitution.Material(**ICE)


def _closed_form_work_j(material, adhesion):
    e_star = material.young_modulus / (2 * (1 - material.poisson_ratio ** 2))
    w = 2 * GAMMA
    a_cubed = math.pi * w * material.effective_radius ** 2 / e_star
    return W_SCALED[adhesion] * math.pi * w * a_cubed ** (2 / 3)


@pytest.mark.parametrize("adhesion", ["jkr", "jkr-lammps", "dmt"])
@pytest.mark.parametrize("velocity, damping", [(0.5, None), (2.0, None), (2.0, 2e-10), (20.0, 2e-10), (0.9, 2e-9)])
def test_equals_the_command_line_value_for_value(cli, ice, adhesion, velocity, damping):
    extra = ["--dissipative-constant", str(damping)] if damping is not None else []
    out = json.loads(cli("eps", "--adhesion", adhesion, "--surface-energy", str(GAMMA), *ICE_CLI, "--velocity",
                         str(velocity), *extra, "--json"))
    r = restitution.adhesive_collision(velocity, material=ice, adhesion=adhesion, surface_energy=GAMMA,
                                       dissipative_constant=damping)
    assert r.adhesion == out["adhesion"] and r.velocity_m_per_s == out["velocity_m_per_s"]
    assert r.outcome == out["outcome"]
    for name in ("eps", "one_minus_eps", "contact_time_s", "max_compression_m", "hysteresis_work_j", "viscous_work_j",
                 "kinetic_to_adhesion_energy"):
        assert getattr(r, name) == out[name], name
    v_s = restitution.sticking_speed(material=ice, adhesion=adhesion, surface_energy=GAMMA,
                                     dissipative_constant=damping)
    assert v_s == out["sticking_speed_m_per_s"]
    assert r.outcome == ("stuck" if velocity < v_s else "bounced")


# LIGGGHTS's sjkr (docs/adhesion.md §10): the soft spheres of its `dem --code liggghts` example, equal and unequal.
SOFT = dict(young_modulus=5e6, poisson_ratio=0.45, density=2500.0)
K_C = 1e5


@pytest.mark.parametrize("radii", [(1e-3, 1e-3), (1e-3, 3e-4)])
@pytest.mark.parametrize("velocity, damping", [(0.02, 1e-5), (0.1, 1e-5), (1.0, 1e-6), (0.3, None)])
def test_sjkr_equals_the_command_line_value_for_value(cli, radii, velocity, damping):
    material = restitution.Material(**SOFT, radii=radii)
    extra = ["--dissipative-constant", str(damping)] if damping is not None else []
    out = json.loads(cli("eps", "--adhesion", "sjkr", "--cohesion-energy-density", str(K_C), "--young-modulus", "5e6",
                         "--poisson-ratio", "0.45", "--radius", str(radii[0]), "--radius2", str(radii[1]),
                         "--density", "2500", "--velocity", str(velocity), *extra, "--json"))
    r = restitution.adhesive_collision(velocity, material=material, adhesion="sjkr", cohesion_energy_density=K_C,
                                       dissipative_constant=damping)
    assert r.adhesion == out["adhesion"] == "sjkr" and r.outcome == out["outcome"]
    for name in ("eps", "one_minus_eps", "contact_time_s", "max_compression_m", "hysteresis_work_j", "viscous_work_j",
                 "kinetic_to_adhesion_energy"):
        assert getattr(r, name) == out[name], name
    v_s = restitution.sticking_speed(material=material, adhesion="sjkr", cohesion_energy_density=K_C,
                                     dissipative_constant=damping)
    assert v_s == out["sticking_speed_m_per_s"]
    assert r.outcome == ("stuck" if velocity < v_s else "bounced")
    forms = restitution.adhesive_closed_forms(material=material, adhesion="sjkr", cohesion_energy_density=K_C)
    assert forms == {"break_overlap_m": out["break_overlap_m"],
                     "elastic_hysteresis_work_j": out["elastic_hysteresis_work_j"],
                     "effective_modulus_pa": out["effective_modulus_pa"]}


def test_undamped_sjkr_is_conservative():
    # Elastic, the cohesion -k_c A(delta) is a conservative force that starts and ends at delta = 0: eps = 1, never stuck.
    material = restitution.Material(**SOFT, radius=1e-3)
    for velocity in (0.01, 0.1, 1.0):
        r = restitution.adhesive_collision(velocity, material=material, adhesion="sjkr", cohesion_energy_density=K_C,
                                           dissipative_constant=0.0)
        assert r.outcome == "bounced" and r.eps == pytest.approx(1.0, abs=1e-12)
    assert restitution.sticking_speed(material=material, adhesion="sjkr", cohesion_energy_density=K_C,
                                      dissipative_constant=0.0) == 0.0


def test_the_unequal_sjkr_lens_is_not_the_equal_one():
    # The intersection circle depends on both radii (docs/adhesion.md §10): spheres of 1 mm and 0.3 mm differ from
    # two equal spheres of the same effective radius and mass (radius 2R each).
    unequal = restitution.Material(**SOFT, radii=(1e-3, 3e-4))
    r_eff, m_eff = unequal.effective_radius, unequal.effective_mass
    equal = restitution.Material(young_modulus=5e6, poisson_ratio=0.45, radius=2 * r_eff, mass=2 * m_eff)
    assert equal.effective_radius == pytest.approx(r_eff, rel=1e-15)
    assert equal.effective_mass == pytest.approx(m_eff, rel=1e-15)
    eps = [restitution.adhesive_collision(0.5, material=m, adhesion="sjkr", cohesion_energy_density=K_C,
                                          dissipative_constant=1e-6).eps for m in (unequal, equal)]
    assert abs(eps[0] - eps[1]) > 1e-6


@pytest.mark.parametrize("adhesion", ["jkr", "jkr-lammps"])
def test_undamped_closed_forms(ice, adhesion):
    work_j = _closed_form_work_j(ice, adhesion)
    m_eff = ice.effective_mass
    v_s = restitution.sticking_speed(material=ice, adhesion=adhesion, surface_energy=GAMMA, dissipative_constant=0.0)
    assert v_s == pytest.approx(math.sqrt(2 * work_j / m_eff), rel=1e-10)
    for factor in (1.001, 1.1, 2.0, 10.0, 100.0):
        v = factor * v_s
        r = restitution.adhesive_collision(v, material=ice, adhesion=adhesion, surface_energy=GAMMA,
                                           dissipative_constant=0.0)
        expected = math.sqrt(1 - work_j / (0.5 * m_eff * v * v))
        assert r.outcome == "bounced"
        assert abs(r.eps - expected) <= 1e-10 * min(expected, 1 - expected) + 1e-15, factor
        assert r.hysteresis_work_j == pytest.approx(work_j, rel=1e-10)
        assert r.viscous_work_j == 0.0
    stuck = restitution.adhesive_collision(0.9 * v_s, material=ice, adhesion=adhesion, surface_energy=GAMMA)
    assert stuck.outcome == "stuck" and stuck.eps == 0.0


def test_the_break_rules_sticking_speeds_ratio(ice):
    ratio = (restitution.sticking_speed(material=ice, adhesion="jkr-lammps", surface_energy=GAMMA)
             / restitution.sticking_speed(material=ice, adhesion="jkr", surface_energy=GAMMA))
    assert ratio == pytest.approx(0.7027567572, rel=1e-9)


def test_undamped_dmt_bounces_elastically_and_never_sticks(ice):
    r = restitution.adhesive_collision(0.3, material=ice, adhesion="dmt", surface_energy=GAMMA)
    assert r.outcome == "bounced" and r.eps == pytest.approx(1.0, abs=1e-12)
    assert restitution.sticking_speed(material=ice, adhesion="dmt", surface_energy=GAMMA) == 0.0


def test_the_material_s_dissipation_is_the_default_damping():
    damped = restitution.Material(**ICE, dissipative_constant=2e-9)
    given = restitution.adhesive_collision(12.0, material=restitution.Material(**ICE), surface_energy=GAMMA,
                                           dissipative_constant=2e-9)
    assert restitution.adhesive_collision(12.0, material=damped, surface_energy=GAMMA).eps == given.eps
    assert restitution.adhesive_collision(12.0, material=damped, surface_energy=GAMMA,
                                          dissipative_constant=0.0).viscous_work_j == 0.0


def test_the_stub_names_the_library_s_models():
    import ast
    import pathlib

    stub = pathlib.Path(restitution.__file__).with_name("_adhesion.pyi")
    for node in ast.parse(stub.read_text()).body:
        if isinstance(node, ast.Assign) and [t.id for t in node.targets] == ["Adhesion"]:
            assert [e.value for e in node.value.slice.elts] == list(_core.adhesive_model_names)
            return
    raise AssertionError("_adhesion.pyi has no Adhesion = Literal[...]")


def test_repr_and_doctests(ice):
    r = restitution.adhesive_collision(2.0, material=ice, surface_energy=GAMMA)
    assert repr(r).startswith("AdhesiveCollision(adhesion='jkr', velocity_m_per_s=2, outcome='bounced'")
    result = doctest.testmod(restitution._adhesion, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.attempted >= 2 and result.failed == 0


@pytest.mark.parametrize("arguments, error, words", [
    (dict(adhesion="sticky"), ValueError, "adhesion must be one of jkr-lammps, jkr, dmt, sjkr"),
    # LIGGGHTS's sjkr takes a cohesion energy density, not a surface energy; the others the reverse.
    (dict(adhesion="sjkr", surface_energy=None), TypeError, "cohesion_energy_density"),
    (dict(adhesion="sjkr", cohesion_energy_density=1e5), ValueError, "adhesion='sjkr' does not take surface_energy"),
    (dict(cohesion_energy_density=1e5), ValueError, "adhesion='jkr' does not take cohesion_energy_density"),
    (dict(adhesion="sjkr", surface_energy=None, cohesion_energy_density=-1.0), ValueError, "cohesion energy density"),
    (dict(surface_energy=None), TypeError, "surface_energy"),
    (dict(surface_energy="0.19"), TypeError, "surface_energy"),
    (dict(dissipative_constant=-1e-9), ValueError, "dissipative constant A must be finite and not negative"),
    (dict(velocity=-1.0), ValueError, "speed"),
    (dict(tolerance=1e-20), ValueError, "tolerance"),
])
def test_bad_arguments_are_named(ice, arguments, error, words):
    given = dict(velocity=2.0, material=ice, surface_energy=GAMMA) | arguments
    with pytest.raises(error, match=words):
        restitution.adhesive_collision(given.pop("velocity"), **given)


def test_material_must_be_a_material():
    with pytest.raises(TypeError, match="restitution.Material"):
        restitution.sticking_speed(material=ICE, surface_energy=GAMMA)


@pytest.mark.parametrize("adhesion, damping", [("jkr", None), ("jkr-lammps", 2e-10)])
def test_the_adhesive_sweep_s_rows_are_the_module_s_collisions(cli, tmp_path, ice, adhesion, damping):
    import csv

    out = tmp_path / "sweep.csv"
    extra = ["--dissipative-constant", str(damping)] if damping is not None else []
    said = cli("sweep", "--adhesion", adhesion, "--surface-energy", str(GAMMA), *ICE_CLI, *extra,
               "--velocity-range", "0.3:30:9", "--log", "--out", str(out))
    assert said == f"wrote {out}: 9 points\n"
    with open(out, newline="") as table:
        rows = list(csv.DictReader(table))
    assert len(rows) == 9 and float(rows[0]["velocity_m_per_s"]) == 0.3 and float(rows[-1]["velocity_m_per_s"]) == 30.0
    v_s = restitution.sticking_speed(material=ice, adhesion=adhesion, surface_energy=GAMMA,
                                     dissipative_constant=damping)
    assert {float(row["sticking_speed_m_per_s"]) for row in rows} == {v_s}
    outcomes = set()
    for row in rows:
        v = float(row["velocity_m_per_s"])
        r = restitution.adhesive_collision(v, material=ice, adhesion=adhesion, surface_energy=GAMMA,
                                           dissipative_constant=damping)
        assert row["outcome"] == r.outcome == ("stuck" if v < v_s else "bounced")
        for name in ("eps", "one_minus_eps", "contact_time_s", "max_compression_m", "hysteresis_work_j",
                     "viscous_work_j", "kinetic_to_adhesion_energy"):
            assert float(row[name]) == getattr(r, name), name
        if r.outcome == "stuck":
            assert float(row["eps"]) == 0.0
        outcomes.add(r.outcome)
    assert outcomes == {"stuck", "bounced"}


@pytest.mark.parametrize("adhesion", ["jkr", "jkr-lammps", "dmt"])
@pytest.mark.parametrize("velocity, damping", [(3.0, 3e-10), (20.0, 1e-9)])
def test_calibrate_finds_the_damping_back(cli, ice, adhesion, velocity, damping):
    # Round trip: eps of a known A, then `calibrate --adhesion` from that eps must give A back.
    r = restitution.adhesive_collision(velocity, material=ice, adhesion=adhesion, surface_energy=GAMMA,
                                       dissipative_constant=damping)
    assert r.outcome == "bounced"
    out = json.loads(cli("calibrate", "--adhesion", adhesion, "--surface-energy", str(GAMMA), *ICE_CLI, "--velocity",
                         str(velocity), "--eps", repr(r.eps), "--json"))
    assert out["dissipative_constant_s"] == pytest.approx(damping, rel=1e-8)
    assert out["eps_at_velocity"] == pytest.approx(r.eps, rel=1e-9)
    assert out["solves"] <= 60
    if adhesion != "jkr":  # LAMMPS's damp = 2 A E*/m_eff
        e_star = ICE["young_modulus"] / (2 * (1 - ICE["poisson_ratio"] ** 2))
        assert out["lammps_damping_per_m_s"] == pytest.approx(2 * out["dissipative_constant_s"] * e_star
                                                              / ice.effective_mass, rel=1e-14)


def test_calibrate_refuses_an_eps_above_the_undamped_one(ice):
    import os
    import subprocess

    path = os.environ.get("RESTITUTION_CLI")
    if not path:
        pytest.skip("RESTITUTION_CLI names no built command line")
    elastic = restitution.adhesive_collision(3.0, material=ice, surface_energy=GAMMA, dissipative_constant=0.0).eps
    done = subprocess.run([path, "calibrate", "--adhesion", "jkr", "--surface-energy", str(GAMMA), *ICE_CLI,
                           "--velocity", "3", "--eps", str(min(0.999, elastic + 0.01))], capture_output=True, text=True)
    assert done.returncode == 2 and "damping only lowers eps" in done.stderr
