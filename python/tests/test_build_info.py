# SPDX-License-Identifier: BSD-3-Clause
"""restitution.build_info(): the module's version and its SUNDIALS build, as the command line's --version says."""

import os
import subprocess
import sys
import warnings

import pytest

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


def _info(optimized):
    return {"version": "9.9.9", "sundials": {"version": "6.4.1", "optimized": optimized,
                                             "description": "6.4.1 (Debian's libsundials, unoptimized)"}}


def test_unoptimized_sundials_warns_at_import_unless_accepted():
    # pip shows no build log: the import is where a user learns that every solve costs 2-3x more.
    with pytest.warns(restitution.SlowSundialsWarning, match=r"9\.9\.9 runs 6\.4\.1 .*unoptimized.*2-3x"):
        assert restitution._warn_if_slow_sundials(_info(False), {})
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert not restitution._warn_if_slow_sundials(_info(False), {"RESTITUTION_ACCEPT_SLOW_SUNDIALS": "1"})
        assert not restitution._warn_if_slow_sundials(_info(True), {})


def test_this_module_warned_at_import_exactly_when_unoptimized():
    code = "import warnings; warnings.simplefilter('error'); import restitution"
    env = {k: v for k, v in os.environ.items() if k != "RESTITUTION_ACCEPT_SLOW_SUNDIALS"}
    result = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True)
    optimized = restitution.build_info()["sundials"]["optimized"]
    assert (result.returncode == 0) == optimized, result.stderr
    if not optimized:
        assert "SlowSundialsWarning" in result.stderr
