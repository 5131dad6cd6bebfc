# SPDX-License-Identifier: BSD-3-Clause
"""Facts the module shares with the library and the command line have one home: the module reads them from the
library, and these tests fail when a copy typed by hand (a docstring, the .pyi, the CLI's help) drifts."""

import ast
import pathlib
import re

import pytest

import restitution
from restitution import _restitution as _core


def test_the_thread_bound_is_the_library_s():
    bound = _core.max_threads
    assert bound >= 1
    assert restitution.eps([0.1, 0.2], threads=bound).shape == (2,)
    with pytest.raises(ValueError, match=rf"\[1, {bound}\]"):
        restitution.eps([0.1, 0.2], threads=bound + 1)
    assert f"[1, {bound}]" in restitution.eps.__doc__


@pytest.mark.parametrize("command", ["sweep", "run"])
def test_the_command_line_s_thread_bound_is_the_module_s(command, cli):
    assert f"[1, {_core.max_threads}]" in cli(command, "--help")


def _pyi_literal(name, stub_name="__init__.pyi"):
    """The strings of `NAME = Literal[...]` in one of the package's stubs (installed next to __init__.py)."""
    stub = pathlib.Path(restitution.__file__).with_name(stub_name)
    for node in ast.parse(stub.read_text()).body:
        if isinstance(node, ast.Assign) and [t.id for t in node.targets if isinstance(t, ast.Name)] == [name]:
            return [element.value for element in node.value.slice.elts]
    raise AssertionError(f"{stub} has no {name} = Literal[...]")


def test_the_stub_s_law_literal_is_the_family_table():
    assert _pyi_literal("Law") == list(_core.law_names)


def test_the_oblique_stub_s_tangential_literal_is_the_model_table():
    assert _pyi_literal("Tangential", "_oblique.pyi") == list(_core.oblique_tangential_names)


def test_the_oblique_docstring_names_every_model_it_runs():
    doc = restitution.oblique.__doc__
    assert "{TANGENTIAL_MODELS}" not in doc
    listed = re.search(r"tangential : \{(.*?)\}", " ".join(doc.split())).group(1)
    assert re.findall(r'"([^"]+)"', listed) == list(_core.oblique_tangential_names)


def test_the_oblique_help_lists_the_model_table(cli):
    text = " ".join(cli("oblique", "--help").split())
    listed = re.search(r"tangential model: ([^:]*?) \(docs/oblique\.md\)", text).group(1)
    assert listed.split(", ") == list(_core.oblique_tangential_names)


def test_the_eps_docstring_names_every_law():
    for name in _core.law_names:
        assert f'"{name}"' in restitution.eps.__doc__, name


@pytest.mark.parametrize("law", list(_core.law_names))
def test_beta_and_material_follow_the_family_table(law, steel):
    if _core.has_dissipative_constant(law):
        assert 0 < restitution.eps(beta=1e-3, velocity=1.0, law=law) < 1
        assert restitution.calibrate(0.8, 1.0, material=steel, law=law).dissipative_constant_s > 0
    else:
        with pytest.raises(TypeError, match="describe law='viscoelastic-hertz'"):
            restitution.eps(beta=1e-3, velocity=1.0, law=law)
        with pytest.raises(TypeError, match="describe law='viscoelastic-hertz'"):
            restitution.calibrate(0.8, 1.0, material=steel, law=law)


@pytest.mark.parametrize("command", ["eps", "sweep", "calibrate"])
def test_the_law_help_lists_the_family_table(command, cli):
    text = " ".join(cli(command, "--help").split())
    listed = re.search(r"contact law: (.*?) \(docs/contact_laws\.md\)", text).group(1)
    assert re.split(r", | or ", listed) == list(_core.law_names)



# A Material is assembled by the library's material_from_fields for Python, scenes and the command line alike:
# the same rule in the same words everywhere (the scene parser's test checks its side).
@pytest.mark.parametrize(
    "fields, words",
    [
        (dict(radius=0.01, radii=(0.01, 0.02)), "material: radius: give radius (both spheres) or radii = [R1, R2]"),
        (dict(), "material: radius: give radius (both spheres) or radii = [R1, R2]"),
        (dict(radius=0.01, mass=1.0, masses=(1.0, 2.0)), "material: mass: give mass or masses, not both"),
    ],
)
def test_material_fields_follow_the_library_s_rules(fields, words):
    with pytest.raises(ValueError) as error:
        restitution.Material(young_modulus=6e10, poisson_ratio=0.2, density=2500.0, **fields)
    assert str(error.value) == words
