# SPDX-License-Identifier: BSD-3-Clause
"""calibrate answers only what a law has: beta and g* belong to viscoelastic Hertz, so for another law they are
None (the CLI leaves them out of its table and JSON), never an invented 0."""

import json
import os
import pathlib
import subprocess

import pytest

import restitution


@pytest.mark.parametrize("law", ["linear-dashpot", "tsuji-hertz"])
def test_a_law_without_beta_gives_none_for_beta_and_g_star(law):
    c = restitution.calibrate(0.8, 1.0, law=law)
    assert c.law == law
    assert c.beta is None
    assert c.characteristic_velocity_m_s is None
    assert c.zeta > 0.0
    assert "beta=None" in repr(c)


def test_viscoelastic_hertz_keeps_beta_and_g_star():
    c = restitution.calibrate(0.8, 1.0)
    assert c.beta == pytest.approx(0.20114, rel=1e-4)  # docs/cli.md: eps = 0.8 at 1 m/s
    assert c.characteristic_velocity_m_s > 0.0


def _cli():
    build = os.environ.get("RESTITUTION_EXE")
    if build:
        return pathlib.Path(build)
    source = pathlib.Path(os.environ.get("RESTITUTION_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
    return source / "build" / "release" / "restitution"


@pytest.mark.parametrize("law", ["linear-dashpot", "tsuji-hertz"])
def test_python_and_the_cli_leave_out_the_same_fields(law):
    exe = _cli()
    if not exe.exists():
        pytest.skip(f"no CLI at {exe}")
    out = subprocess.run([str(exe), "calibrate", "--eps", "0.8", "--velocity", "1", "--law", law, "--json"],
                         capture_output=True, text=True, check=True).stdout
    cli = json.loads(out)
    c = restitution.calibrate(0.8, 1.0, law=law)
    assert "beta" not in cli and "characteristic_velocity_m_s" not in cli
    assert c.zeta == pytest.approx(cli["zeta"], rel=1e-8)
