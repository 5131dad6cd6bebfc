# SPDX-License-Identifier: BSD-3-Clause
"""Debian's mypy (python3-mypy) on the package's stubs as a typed program uses them: every line of
typing/typed_usage.py is accepted, and every line of typing/rejected_usage.py marked `# rejected` is an error (a
float for an array, an array for a float, a missing end used as present, an unknown end)."""

import os
import pathlib
import re
import subprocess
import sys

import pytest

HERE = pathlib.Path(__file__).resolve().parent / "typing"


def _mypy(path, cache):
    try:
        import mypy  # noqa: F401
    except ImportError:
        pytest.fail("mypy is missing: install Debian's python3-mypy (scripts/setup does)")
    # --python-executable: the interpreter running the tests, whose sys.path (PYTHONPATH, made absolute for
    # the run in another folder, or a venv's site-packages) holds the package under test.
    env = dict(os.environ)
    if env.get("PYTHONPATH"):
        env["PYTHONPATH"] = os.pathsep.join(os.path.abspath(p) for p in env["PYTHONPATH"].split(os.pathsep))
    done = subprocess.run([sys.executable, "-m", "mypy", "--python-executable", sys.executable, "--cache-dir", str(cache),
                           "--no-error-summary", "--hide-error-context", str(path)],
                          capture_output=True, text=True, timeout=240, cwd=cache, env=env)
    return done.returncode, [line for line in done.stdout.splitlines() if ": error:" in line]


def test_typed_usage_passes(tmp_path):
    code, errors = _mypy(HERE / "typed_usage.py", tmp_path)
    assert code == 0 and not errors, "\n".join(errors)


def test_imprecise_usage_is_rejected_line_by_line(tmp_path):
    source = (HERE / "rejected_usage.py").read_text().splitlines()
    marked = {number for number, line in enumerate(source, 1) if line.endswith("# rejected")}
    code, errors = _mypy(HERE / "rejected_usage.py", tmp_path)
    rejected = {int(re.search(r":(\d+): error:", line).group(1)) for line in errors}
    assert code == 1 and rejected == marked, "\n".join(errors)
