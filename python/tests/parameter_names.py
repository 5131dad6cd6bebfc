# SPDX-License-Identifier: BSD-3-Clause
"""What a study's front ends name, read from them, for the tests that compare them with the study's table
(test_gas_parameters.py, test_oblique_parameters.py): a function's keyword-only parameters, the names its
docstring's Parameters section documents, a stub's parameters and the options of a command's --help."""

import inspect
import os
import re
import subprocess


def signature_names(function):
    parameters = inspect.signature(function).parameters.values()
    assert all(p.kind is inspect.Parameter.KEYWORD_ONLY for p in parameters)
    return [p.name for p in parameters]


def documented_names(function):
    text = function.__doc__
    section = text[text.index("Parameters\n"):text.index("Returns\n")]
    documented = []
    for line in section.splitlines():
        match = re.fullmatch(r" {4}([a-z_0-9, ]+) : .*", line)
        if match:
            documented += [name.strip() for name in match.group(1).split(",")]
    return documented


def stub_names(stub, function):
    """The parameters of each `def function(` in the stub text (one list per overload)."""
    blocks = re.findall(rf"^def {function}\(\n(.*?)\n\) ->", stub, re.S | re.M)
    assert blocks
    return [re.findall(r"^\s+([a-z_0-9]+):", block, re.M) for block in blocks]


def help_options(command):
    help_text = subprocess.run([os.environ["RESTITUTION_CLI"], command, "--help"], capture_output=True, text=True,
                               check=True).stdout
    return set(re.findall(r"^\s+(--[a-z0-9-]+)", help_text, re.M))


def options_of(names):
    return {"--" + name.replace("_", "-") for name in names}
