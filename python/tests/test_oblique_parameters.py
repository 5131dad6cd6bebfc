# SPDX-License-Identifier: BSD-3-Clause
"""Issue 46 item 4: the oblique study's parameters are declared once, in its table
(restitution_oblique/oblique_parameters.hpp, seen here as _core.oblique_parameters). restitution.oblique's signature,
its docstring's Parameters, the .pyi and the command line's `oblique --help` list the table's names; an argument the
table lacks is refused."""

import os
import pathlib

import pytest
from parameter_names import documented_names, help_options, options_of, signature_names, stub_names

import restitution
from restitution import _restitution as core

# The keywords: the rows but those the Material gives (its A), as for a scene's [materials.X].
TABLE = [name for name, _, _, from_material in core.oblique_parameters if not from_material]
# Beside the table: the Material itself and the old name of impact_velocity (until 0.5.0).
BESIDE = ["material", "speed"]
PACKAGE = pathlib.Path(restitution.__file__).parent


def test_the_table_names_each_parameter_once():
    names = [name for name, *_ in core.oblique_parameters]
    assert len(names) == len(set(names)) > 15
    assert {kind for _, kind, *_ in core.oblique_parameters} <= {"optional number", "number", "word", "flag",
                                                                 "numbers"}


def test_the_signature_lists_the_table():
    assert sorted(signature_names(restitution.oblique)) == sorted(TABLE + BESIDE)


def test_the_docstring_documents_the_table():
    assert sorted(documented_names(restitution.oblique)) == sorted(TABLE + ["material"])


def test_the_stub_lists_the_table():
    overloads = stub_names((PACKAGE / "_oblique.pyi").read_text(), "oblique")
    assert [sorted(names) for names in overloads] == [sorted(TABLE + BESIDE)] * 2


@pytest.mark.skipif("RESTITUTION_CLI" not in os.environ, reason="needs the command line of this build")
def test_the_command_line_takes_the_table():
    options = help_options("oblique")
    table = options_of(name for name, *_ in core.oblique_parameters)
    # Beside the table: the material options every command shares, --angle-range and the outputs (the old
    # --speed is not listed).
    assert table <= options
    assert options - table == {"--young-modulus", "--poisson-ratio", "--radius", "--radius2", "--density", "--mass",
                               "--mass2", "--angle-range", "--json", "--out", "--plot", "--format"}


def test_an_argument_the_table_lacks_is_refused():
    steel = restitution.Material(young_modulus=2e11, poisson_ratio=0.3, radius=1e-3, density=7800.0,
                                 dissipative_constant=0.0)
    with pytest.raises(TypeError, match="unexpected keyword argument 'bogus'"):
        core.oblique_impacts(steel, [10.0], [0.0], {"bogus": 1.0})
