# SPDX-License-Identifier: BSD-3-Clause
"""restitution.sweep_to_file: the command line's sweep table from Python, kept in path.partial while it runs, so
that a stopped sweep resumes to the bytes of an uninterrupted one."""

import os
import re
import stat

import numpy as np
import pytest

import restitution

POINTS = 3000  # a stop at the first poll (~20 ms) finds the sweep unfinished: a point costs ~50-100 us


def _zeta_column(path):
    """The zeta column of a sweep table, read back exactly (17 significant digits round-trip)."""
    with open(path) as table:
        next(table)
        return np.array([float(line.split(",", 1)[0]) for line in table])


def _stopped(zetas, path, **options):
    """A sweep stopped at its first poll: path.partial holds what finished."""
    outcome = restitution.sweep_to_file(zetas, path, threads=1, stop=lambda: True, **options)
    assert outcome["status"] == "stopped"
    assert outcome["finished"] < len(zetas)
    assert not path.exists()
    assert path.with_name(path.name + ".partial").exists()
    return outcome


def test_the_table_is_the_command_lines(cli, tmp_path):
    reference = tmp_path / "cli.csv"
    cli("sweep", "--zeta-range", "0:2:50", "--threads", "2", "--out", str(reference))
    out = tmp_path / "python.csv"
    outcome = restitution.sweep_to_file(_zeta_column(reference), out, threads=2)
    assert outcome["status"] == "complete"
    assert (outcome["points"], outcome["finished"], outcome["failed"], outcome["resumed"]) == (50, 50, 0, 0)
    assert out.read_bytes() == reference.read_bytes()
    assert not (tmp_path / "python.csv.partial").exists()


def test_a_stopped_sweep_resumes_to_the_same_bytes(tmp_path):
    zetas = np.linspace(0.0, 3.0, POINTS)
    whole = tmp_path / "whole.csv"
    assert restitution.sweep_to_file(zetas, whole, end="naive")["status"] == "complete"
    out = tmp_path / "stopped.csv"
    stopped = _stopped(zetas, out, end="naive")
    partial = tmp_path / "stopped.csv.partial"
    with open(partial, "a") as damaged:  # a line that fails its checksum, then one cut off while being written
        damaged.write("5,0.005,garbage,0123abcd\n7,0.007")
    resumed = restitution.sweep_to_file(zetas, out, end="naive", resume=True)
    assert resumed["status"] == "complete"
    assert resumed["resumed"] == stopped["finished"]
    assert resumed["damaged_lines"] == 1
    assert resumed["first_damaged_line"] == 3 + stopped["finished"]
    assert out.read_bytes() == whole.read_bytes()
    assert not partial.exists()


def test_resuming_a_complete_file_computes_nothing(tmp_path):
    out = tmp_path / "done.csv"
    restitution.sweep_to_file([0.1, 0.2, 0.3], out)
    before = out.stat().st_mtime_ns, out.read_bytes()
    outcome = restitution.sweep_to_file([0.1, 0.2, 0.3], out, resume=True)
    assert outcome["status"] == "already_complete"
    assert outcome["finished"] == 3
    assert (out.stat().st_mtime_ns, out.read_bytes()) == before


def test_a_partial_file_of_another_sweep_is_refused_naming_it(tmp_path):
    zetas = np.linspace(0.0, 3.0, POINTS)
    out = tmp_path / "s.csv"
    _stopped(zetas, out)
    partial = str(tmp_path / "s.csv.partial")
    with pytest.raises(ValueError, match=re.escape(partial) + ".*another sweep"):
        restitution.sweep_to_file(zetas, out, resume=True, tolerance=1e-8)
    with pytest.raises(ValueError, match=re.escape(partial) + ".*written by another sweep"):
        restitution.sweep_to_file(zetas[::-1], out, resume=True)  # another grid of the same size
    with pytest.raises(ValueError, match=re.escape(f"'{partial}' holds an interrupted sweep: add resume=True")):
        restitution.sweep_to_file(zetas, out)
    assert restitution.sweep_to_file(zetas, out, resume=True)["status"] == "complete"


def test_bad_arguments_are_refused_before_any_file(tmp_path):
    out = tmp_path / "bad.csv"
    with pytest.raises(ValueError, match="zeta"):
        restitution.sweep_to_file([0.1, -1.0], out)
    with pytest.raises(ValueError, match="1-d"):
        restitution.sweep_to_file([[0.1]], out)
    with pytest.raises(ValueError, match="must name a file"):
        restitution.sweep_to_file([0.1], tmp_path)
    with pytest.raises(TypeError, match="stop"):
        restitution.sweep_to_file([0.1], out, stop=1)
    assert list(tmp_path.iterdir()) == []


def test_a_device_or_a_link_into_a_missing_folder_is_refused_and_left_alone(tmp_path):
    """A sweep's table is made beside its file and renamed onto it: onto a FIFO or device (as root, /dev/full) that
    would replace the device with a plain file. A link whose target's folder is missing would make folders there."""
    fifo = tmp_path / "pipe.csv"
    os.mkfifo(fifo)
    with pytest.raises(ValueError, match="not a regular file"):
        restitution.sweep_to_file([0.1], fifo)
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
    link = tmp_path / "link.csv"
    link.symlink_to("missing/out.csv")
    with pytest.raises(ValueError, match="whose folder does not exist"):
        restitution.sweep_to_file([0.1], link)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.csv", "pipe.csv"]
