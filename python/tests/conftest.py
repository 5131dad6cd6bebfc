# SPDX-License-Identifier: BSD-3-Clause
"""Shared fixtures: the reference solutions of data/reference_solutions.csv (natural units)."""

import csv
import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("RESTITUTION_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


def pytest_sessionstart(session):
    """tests/pip_install.sh sets RESTITUTION_INSTALLED_UNDER to a venv: then the package under test must be the one
    installed there, never a build tree or the checkout."""
    prefix = os.environ.get("RESTITUTION_INSTALLED_UNDER")
    if prefix:
        import restitution

        where = pathlib.Path(restitution.__file__).resolve()
        if not where.is_relative_to(pathlib.Path(prefix).resolve()):
            pytest.exit(f"testing {where}, not the package installed under {prefix}", returncode=1)


def _reference_rows():
    with open(SOURCE_DIR / "data" / "reference_solutions.csv") as table:
        lines = (line for line in table if not line.startswith("#"))
        return [{key: float(value) if value else float("nan") for key, value in row.items()} for row in csv.DictReader(lines)]


@pytest.fixture(scope="session")
def reference():
    """Rows with zeta, naive_eps, naive_one_minus_eps, delayed_recovery_eps, delayed_recovery_one_minus_eps, ... as floats."""
    return _reference_rows()


@pytest.fixture
def steel():
    """Two equal steel-like spheres, radius 1 cm (A chosen for eps of order 0.9 at 1 m/s)."""
    import restitution

    return restitution.Material(young_modulus=2.0e11, poisson_ratio=0.3, radius=0.01, density=7800.0,
                                dissipative_constant=1.0e-6)


@pytest.fixture
def cli():
    """Runs this build's command line (ctest sets RESTITUTION_CLI) and returns its output; skips where there is none."""
    import subprocess

    path = os.environ.get("RESTITUTION_CLI")
    if not path or not os.path.exists(path):
        pytest.skip("RESTITUTION_CLI names no built command line")

    def run(*args):
        done = subprocess.run([path, *args], capture_output=True, text=True, timeout=120)
        assert done.returncode == 0, done.stderr
        return done.stdout

    return run
