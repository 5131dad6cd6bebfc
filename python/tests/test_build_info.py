# SPDX-License-Identifier: BSD-3-Clause
"""restitution.build_info(): the module's version and its SUNDIALS build, as the command line's --version says."""

import subprocess
import sys

import restitution


def test_build_info_names_version_and_sundials():
    info = restitution.build_info()
    assert info["version"] == restitution.__version__
    sundials = info["sundials"]
    assert isinstance(sundials["optimized"], bool)
    assert sundials["version"].count(".") == 2 and sundials["description"].startswith(sundials["version"])
    assert ("unoptimized" in sundials["description"]) != sundials["optimized"]


def test_build_info_matches_the_command_line(cli):
    assert restitution.build_info()["sundials"]["description"] in cli("--version")


def test_import_never_warns_of_the_sundials_build():
    # Configure says which SUNDIALS a build links, in one line; the module only answers build_info().
    code = "import warnings; warnings.simplefilter('error'); import restitution"
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert result.returncode == 0 and result.stderr == "", result.stderr
