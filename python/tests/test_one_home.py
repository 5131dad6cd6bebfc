# SPDX-License-Identifier: BSD-3-Clause
"""Facts the module shares with the library and the command line have one home: the module reads them from the
library, and these tests fail when a copy typed by hand (a docstring, the .pyi, the CLI's help) drifts."""

import os
import subprocess

import pytest

import restitution
from restitution import _restitution as _core


def _cli(*args):
    """The output of this build's command line (ctest sets RESTITUTION_CLI), or skip where there is none."""
    cli = os.environ.get("RESTITUTION_CLI")
    if not cli or not os.path.exists(cli):
        pytest.skip("RESTITUTION_CLI names no built command line")
    done = subprocess.run([cli, *args], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_the_thread_bound_is_the_library_s():
    bound = _core.max_threads
    assert bound >= 1
    assert restitution.eps([0.1, 0.2], threads=bound).shape == (2,)
    with pytest.raises(ValueError, match=rf"\[1, {bound}\]"):
        restitution.eps([0.1, 0.2], threads=bound + 1)
    assert f"[1, {bound}]" in restitution.eps.__doc__


@pytest.mark.parametrize("command", ["sweep", "run"])
def test_the_command_line_s_thread_bound_is_the_module_s(command):
    assert f"[1, {_core.max_threads}]" in _cli(command, "--help")
