# SPDX-License-Identifier: BSD-3-Clause
"""eps() and solve() give the same digits for the same request: solve()'s default end="both" solves each end as
eps() does (one solve of both ends plans for both and differed in the 12th digit)."""

import pytest

import restitution

ZETAS = [1e-4, 0.01, 0.1, 1.0, 5.0, 10.0, 100.0, 1e4]
# Adams computes the naive end only up to zeta = 2000 (the stiff tail); it refuses it there, alone or with both.
CASES = [(zeta, method) for zeta in ZETAS for method in ["auto", "bdf", "adams"] if method != "adams" or zeta <= 2000]


@pytest.mark.parametrize("zeta,method", CASES)
def test_solve_both_ends_equals_eps_at_each_end(zeta, method):
    both = restitution.solve(zeta, method=method)
    assert both.delayed_recovery.eps == restitution.eps(zeta, method=method)
    assert both.naive.eps == restitution.eps(zeta, end="naive", method=method)
    assert both.delayed_recovery.one_minus_eps == restitution.solve(zeta, "delayed-recovery", method=method).delayed_recovery.one_minus_eps


@pytest.mark.parametrize("zeta", [0.01, 1.0, 10.0])
def test_array_and_scalar_and_solve_agree(zeta):
    array = restitution.eps([zeta, zeta])
    assert array[0] == array[1] == restitution.eps(zeta) == restitution.solve(zeta).delayed_recovery.eps


def test_both_ends_report_the_whole_collision():
    """The naive end's solve runs through the collision: its trajectory reaches x = 0 after the delayed-recovery
    end, and the statistics count both integrations."""
    both = restitution.solve(1.0, trajectory=True)
    naive = restitution.solve(1.0, end="naive", trajectory=True)
    delayed = restitution.solve(1.0, end="delayed-recovery")
    assert both.tau[-1] == naive.tau[-1] >= both.naive.tau > both.delayed_recovery.tau
    assert both.stats.steps == naive.stats.steps + delayed.stats.steps
    assert both.max_compression.x == naive.max_compression.x


def test_both_ends_refused_where_the_naive_end_does_not_exist():
    with pytest.raises(ValueError, match="naive end does not exist"):
        restitution.solve(3.0, law="linear-dashpot")
