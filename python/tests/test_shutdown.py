# SPDX-License-Identifier: BSD-3-Clause
"""The interpreter exits cleanly while other threads are inside restitution calls.

At exit CPython 3.11 ends every other thread that asks for the GIL back with pthread_exit, a forced unwind
that aborted the process (rc 134, "terminate called without an active exception") while the GIL was taken
back in a C++ destructor: 20 of 20 runs of the daemon-thread script below, 16 of 16 of the Ctrl-C one.
"""

import signal
import subprocess
import sys
import textwrap

# A daemon thread loops on every kind of call that releases the GIL: a scalar solve (on the calling thread),
# an array solve (the library's thread pool), the fast table, a calibration and a fit; the main thread exits
# while it is inside one.
DAEMON_THREAD_AT_EXIT = textwrap.dedent("""
    import threading, time
    import numpy as np
    import restitution

    zetas = np.linspace(0.01, 1.0, 64)
    started = threading.Event()

    def loop():
        while True:
            restitution.eps(0.5)
            restitution.eps(zetas, threads=2)
            restitution.fast.eps(zetas)
            restitution.calibrate(0.8, 1.0)
            restitution.fit_data([0.5, 1.0, 2.0], [0.82, 0.8, 0.78])
            started.set()

    threading.Thread(target=loop, daemon=True).start()
    assert started.wait(60)
    time.sleep(0.05)
""")

# Four threads inside calls, the main thread waiting in join() when SIGINT arrives: KeyboardInterrupt ends
# the interpreter with the threads still running.
CTRL_C_DURING_JOIN = textwrap.dedent("""
    import signal, threading
    import numpy as np
    import restitution

    zetas = np.linspace(0.01, 1.0, 200)
    running = threading.Barrier(5)

    def work(k):
        running.wait()
        while True:
            if k % 2:
                restitution.eps(0.3 + 0.1 * k)
            else:
                restitution.eps(zetas, threads=2)

    threads = [threading.Thread(target=work, args=(k,), daemon=True) for k in range(4)]
    for t in threads:
        t.start()
    running.wait()
    # Ctrl-C, sent to the main thread: a SIGINT the kernel hands to another thread would not wake join()
    # (CPython waits there without a timeout), and a shell may start the test with SIGINT ignored.
    signal.signal(signal.SIGINT, signal.default_int_handler)
    threading.Timer(0.1, signal.pthread_kill, args=(threading.main_thread().ident, signal.SIGINT)).start()
    for t in threads:
        t.join()
""")


def run_children(script, count):
    """Runs the script in `count` fresh interpreters, four at a time (each mostly waits for its imports)."""
    outcomes = []
    for first in range(0, count, 4):
        children = [subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.DEVNULL,
                                     stderr=subprocess.PIPE, text=True) for _ in range(min(4, count - first))]
        outcomes += [(child.communicate(timeout=120)[1], child.returncode) for child in children]
    return outcomes


def test_exit_with_a_daemon_thread_inside_a_call_is_clean_20_times():
    outcomes = run_children(DAEMON_THREAD_AT_EXIT, 20)
    failed = [(returncode, stderr[-300:]) for stderr, returncode in outcomes if returncode != 0]
    assert not failed, f"{len(failed)}/20 exits failed, e.g. {failed[0]}"


def test_ctrl_c_during_join_ends_with_keyboard_interrupt_not_abort():
    for stderr, returncode in run_children(CTRL_C_DURING_JOIN, 8):
        # An uncaught KeyboardInterrupt ends the interpreter by SIGINT (status 130 in a shell).
        assert returncode == -signal.SIGINT, (returncode, stderr[-300:])
        assert "KeyboardInterrupt" in stderr
        assert "terminate called" not in stderr
