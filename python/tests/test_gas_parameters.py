# SPDX-License-Identifier: BSD-3-Clause
"""Issue 46 item 4: the gas study's parameters are declared once, in its table (restitution_gas/gas_parameters.hpp,
seen here as _core.gas_parameters). restitution.gas's signature, its docstring's Parameters, the .pyi and the
command line's `gas --help` list exactly the table's names; an argument the table lacks is refused."""

import inspect
import os
import pathlib
import re
import subprocess

import pytest

import restitution
from restitution import _restitution as core

TABLE = [name for name, _, _ in core.gas_parameters]
PACKAGE = pathlib.Path(restitution.__file__).parent


def test_the_table_names_each_parameter_once():
    assert len(TABLE) == len(set(TABLE)) > 20
    assert {kind for _, kind, _ in core.gas_parameters} <= {"optional number", "number", "whole number", "word",
                                                             "optional word", "number or word"}


def test_the_signature_lists_the_table():
    parameters = inspect.signature(restitution.gas).parameters.values()
    assert all(p.kind is inspect.Parameter.KEYWORD_ONLY for p in parameters)
    assert sorted(p.name for p in parameters) == sorted(TABLE)


def test_the_docstring_documents_the_table():
    text = restitution.gas.__doc__
    section = text[text.index("Parameters\n"):text.index("Returns\n")]
    documented = []
    for line in section.splitlines():
        match = re.fullmatch(r" {4}([a-z_0-9, ]+) : .*", line)
        if match:
            documented += [name.strip() for name in match.group(1).split(",")]
    assert sorted(documented) == sorted(TABLE)


def test_the_stub_lists_the_table():
    stub = (PACKAGE / "__init__.pyi").read_text()
    block = re.search(r"^def gas\(\n(.*?)\n\) ->", stub, re.S | re.M).group(1)
    names = re.findall(r"^\s+([a-z_0-9]+):", block, re.M)
    assert sorted(names) == sorted(TABLE)


@pytest.mark.skipif("RESTITUTION_CLI" not in os.environ, reason="needs the command line of this build")
def test_the_command_line_takes_the_table():
    help_text = subprocess.run([os.environ["RESTITUTION_CLI"], "gas", "--help"], capture_output=True, text=True,
                               check=True).stdout
    options = set(re.findall(r"^\s+(--[a-z0-9-]+)", help_text, re.M))
    table = {"--" + name.replace("_", "-") for name in TABLE}
    # Beside the table: the refused second sphere, the deck's options and the outputs.
    assert table <= options
    assert options - table == {"--radius2", "--mass2", "--deck", "--compare", "--compare-output",
                               "--particles", "--seed", "--max-eps-error", "--code", "--json", "--out", "--plot",
                               "--format"}


def test_an_argument_the_table_lacks_is_refused():
    with pytest.raises(TypeError, match="unexpected keyword argument 'bogus'"):
        core.gas({"bogus": 1.0})
