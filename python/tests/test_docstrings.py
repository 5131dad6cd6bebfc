# SPDX-License-Identifier: BSD-3-Clause
"""The examples in the package's docstrings run (doctest) against the package under test, and every public
function documents its Parameters, Returns and Examples (numpydoc)."""

import doctest
import inspect

import pytest

import restitution
import restitution.fast
import restitution.series

MODULES = [restitution, restitution.fast, restitution.series, restitution._restitution]  # the last: Material


@pytest.mark.parametrize("module", MODULES, ids=lambda m: m.__name__)
def test_docstring_examples_run(module):
    result = doctest.testmod(module, optionflags=doctest.NORMALIZE_WHITESPACE, verbose=False)
    assert result.failed == 0, f"{result.failed} of {result.attempted} examples failed in {module.__name__}"


def test_the_package_has_examples_to_run():
    assert doctest.testmod(restitution).attempted >= 25
    assert doctest.testmod(restitution._restitution).attempted >= 4  # Material's


@pytest.mark.parametrize("name", ["eps", "solve", "calibrate", "fit_data", "zeta_of", "build_info"])
def test_public_functions_have_numpydoc_sections(name):
    text = inspect.getdoc(getattr(restitution, name))
    sections = ["Returns\n-------", "Examples\n--------"] + (["Parameters\n----------"] if name != "build_info" else [])
    for section in sections:
        assert section in text, (name, section.split()[0])
