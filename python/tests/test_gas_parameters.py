# SPDX-License-Identifier: BSD-3-Clause
"""Issue 46 item 4: the gas study's parameters are declared once, in its table (restitution_gas/gas_parameters.hpp,
seen here as _core.gas_parameters). restitution.gas's signature, its docstring's Parameters, the .pyi and the
command line's `gas --help` list exactly the table's names; an argument the table lacks is refused."""

import os
import pathlib

import pytest
from parameter_names import documented_names, help_options, options_of, signature_names, stub_names

import restitution
from restitution import _restitution as core

TABLE = [name for name, *_ in core.gas_parameters]
PACKAGE = pathlib.Path(restitution.__file__).parent


def test_the_table_names_each_parameter_once():
    assert len(TABLE) == len(set(TABLE)) > 20
    assert {kind for _, kind, *_ in core.gas_parameters} <= {"optional number", "number", "whole number", "word",
                                                             "optional word", "number or word"}


def test_the_signature_lists_the_table():
    assert sorted(signature_names(restitution.gas)) == sorted(TABLE)


def test_the_docstring_documents_the_table():
    assert sorted(documented_names(restitution.gas)) == sorted(TABLE)


def test_the_stub_lists_the_table():
    assert [sorted(names) for names in stub_names((PACKAGE / "__init__.pyi").read_text(), "gas")] == [sorted(TABLE)]


@pytest.mark.skipif("RESTITUTION_CLI" not in os.environ, reason="needs the command line of this build")
def test_the_command_line_takes_the_table():
    options = help_options("gas")
    table = options_of(TABLE)
    # Beside the table: the refused second sphere, the deck's options and the outputs.
    assert table <= options
    assert options - table == {"--radius2", "--mass2", "--deck", "--compare", "--compare-output",
                               "--particles", "--seed", "--max-eps-error", "--code", "--json", "--out", "--plot",
                               "--format"}


def test_an_argument_the_table_lacks_is_refused():
    with pytest.raises(TypeError, match="unexpected keyword argument 'bogus'"):
        core.gas({"bogus": 1.0})
