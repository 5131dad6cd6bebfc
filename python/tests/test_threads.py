# SPDX-License-Identifier: BSD-3-Clause
"""Long array calls release the GIL and stop with KeyboardInterrupt on SIGINT."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import restitution

# BDF at zeta = 1 costs of the order of a millisecond per point: this call would take many seconds.
LONG_CALL = dict(zeta=np.full(20000, 1.0), method="bdf")


@pytest.mark.skipif(not hasattr(signal, "SIGINT"), reason="needs SIGINT")
def test_sigint_interrupts_a_long_array_call():
    timer = threading.Timer(0.3, os.kill, args=(os.getpid(), signal.SIGINT))
    timer.start()
    start = time.monotonic()
    try:
        with pytest.raises(KeyboardInterrupt):
            restitution.eps(**LONG_CALL)
    finally:
        timer.cancel()
    assert time.monotonic() - start < 5.0
    assert restitution.eps([0.1, 0.2]).shape == (2,)  # the module is usable afterwards


def test_another_thread_runs_during_a_long_call():
    ticks = []
    running = threading.Event()
    done = threading.Event()

    def count():
        running.set()
        while not done.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.001)

    thread = threading.Thread(target=count)
    thread.start()
    running.wait()
    start = time.monotonic()
    # Long enough to watch on any build: ~0.3 s of CVODE work with the optimized SUNDIALS (0.05 s was too
    # close to 400 solves there), several times that with Debian's unoptimized library.
    restitution.eps(np.full(4000, 1.0), method="bdf")
    end = time.monotonic()
    done.set()
    thread.join()
    inside = [t for t in ticks if start < t < end]
    assert end - start > 0.05
    # With the GIL held the other thread could not tick at all during the call.
    assert len(inside) >= 10, (len(inside), end - start)


def test_the_thread_count_changes_no_value():
    zetas = np.logspace(-3, 3, 999)
    default = restitution.eps(zetas, method="taylor")
    for threads in (1, 2, 3, np.int64(2)):
        np.testing.assert_array_equal(restitution.eps(zetas, method="taylor", threads=threads), default)
    assert restitution.eps(0.5, threads=1) == restitution.eps(0.5)


@pytest.mark.parametrize("threads, error", [(0, ValueError), (-1, ValueError), (1025, ValueError),
                                            (1.5, TypeError), (True, TypeError), ("2", TypeError)])
def test_bad_thread_counts_are_refused(threads, error):
    with pytest.raises(error, match="threads"):
        restitution.eps([0.1, 0.2], threads=threads)
