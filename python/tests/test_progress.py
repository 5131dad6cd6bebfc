# SPDX-License-Identifier: BSD-3-Clause
"""progress= on array calls: a callable(done, total) called a few times a second from the calling thread and once at
the end, True for a tqdm bar; an exception it raises stops the call."""

import threading
import time

import numpy as np
import pytest

import restitution

SLOW = np.full(3000, 10.0)  # ~1 s of BDF solves on two cores: several progress calls


def test_callable_sees_done_grow_to_total_on_the_calling_thread():
    calls = []
    caller = threading.get_ident()
    eps = restitution.eps(SLOW, method="bdf", threads=2,
                          progress=lambda done, total: calls.append((done, total, threading.get_ident(), time.monotonic())))
    assert np.all(eps == eps[0])
    assert calls[-1][:2] == (SLOW.size, SLOW.size)
    assert all(total == SLOW.size and thread == caller for _, total, thread, _ in calls)
    done = [c[0] for c in calls]
    assert done == sorted(done) and len(calls) >= 2
    gaps = np.diff([c[3] for c in calls[:-1]])
    assert np.all(gaps >= 0.2), gaps  # a few per second, not one per point


def test_an_exception_in_the_callable_stops_the_call():
    def stop(done, total):
        raise RuntimeError(f"stopped at {done} of {total}")

    started = time.monotonic()
    with pytest.raises(RuntimeError, match="stopped at"):
        restitution.eps(np.full(20000, 10.0), method="bdf", threads=2, progress=stop)
    assert time.monotonic() - started < 3.0  # 20000 BDF solves would take several seconds


def test_true_draws_a_tqdm_bar(capsys):
    pytest.importorskip("tqdm", reason="tqdm (Debian: python3-tqdm) draws the bar")
    restitution.eps(np.linspace(0.1, 1.0, 50), progress=True)
    assert "50/50" in capsys.readouterr().err


def test_false_and_none_make_no_calls_and_a_scalar_none():
    calls = []
    assert restitution.eps(1.0, progress=lambda *a: calls.append(a)) == restitution.eps(1.0)
    assert calls == []
    assert restitution.eps([1.0], progress=False)[0] == restitution.eps([1.0], progress=None)[0]


@pytest.mark.parametrize("bad", ["yes", 1, 0.5])
def test_a_wrong_progress_is_a_type_error(bad):
    with pytest.raises(TypeError, match="progress must be"):
        restitution.eps([1.0], progress=bad)
