# SPDX-License-Identifier: BSD-3-Clause
"""restitution.fast: the certified table against the reference solutions, the solver, the C header (bit for
bit), its inverse, the shape rules and the errors."""

import math
import os
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

import restitution
from conftest import SOURCE_DIR

ENDS = {"naive": "naive", "delayed-recovery": "delayed_recovery"}  # the reference file's column prefixes
CERTIFIED_ZETA_MAX = {"naive": 1e5, "delayed-recovery": 1e6}  # include/restitution/fast.hpp


def _contract(eps, one_minus_eps, tolerance):
    """The accuracy contract |Δε| <= tolerance · min(ε, 1 − ε)."""
    return tolerance * np.minimum(eps, one_minus_eps)


@pytest.mark.parametrize("end", ENDS)
def test_matches_reference_solutions(reference, end):
    prefix = ENDS[end]
    rows = [row for row in reference if not math.isnan(row[prefix + "_eps"])]
    zetas = np.array([row["zeta"] for row in rows])
    exact = np.array([row[prefix + "_eps"] for row in rows])
    exact_complement = np.array([row[prefix + "_one_minus_eps"] for row in rows])
    # Near eps = 1 a double cannot hold eps to 1e-13 (1 - eps): there one ulp of eps is the bound, and
    # one_minus_eps carries the contract.
    bound = np.maximum(_contract(exact, exact_complement, 1e-13), np.spacing(exact))
    assert np.all(np.abs(restitution.fast.eps(zetas, end=end) - exact) <= bound)
    complement = restitution.fast.one_minus_eps(zetas, end=end)
    assert np.all(np.abs(complement - exact_complement) <= 1e-13 * exact_complement)
    for zeta, value, limit in zip(zetas, exact, bound):
        assert abs(restitution.fast.eps(float(zeta), end=end) - value) <= limit


@pytest.mark.parametrize("end", ENDS)
def test_agrees_with_the_solver(end):
    zetas = np.logspace(-3, 3, 19)
    solved = restitution.eps(zetas, end=end, tolerance=1e-10)
    fast = restitution.fast.eps(zetas, end=end)
    bound = _contract(solved, 1 - solved, 1e-10 + 2e-13)
    assert np.all(np.abs(fast - solved) <= bound)


@pytest.mark.parametrize("end", ENDS)
def test_scalar_equals_array_and_default_end(end):
    zetas = np.concatenate(([0.0], np.logspace(-4, 6, 41)))
    array = restitution.fast.eps(zetas, end=end)
    assert [restitution.fast.eps(float(z), end=end) for z in zetas] == list(array)
    assert array[0] == 1.0
    assert np.all(np.diff(array) < 0)  # eps falls with the damping
    np.testing.assert_array_equal(restitution.fast.eps(zetas), restitution.fast.eps(zetas, "delayed-recovery"))


@pytest.mark.parametrize("end", ENDS)
def test_inverse_round_trip(end):
    eps = np.concatenate((np.linspace(0.02, 0.98, 49), 1 - np.logspace(-9, -3, 7)))
    eps = eps[restitution.fast.eps(CERTIFIED_ZETA_MAX[end], end=end) < eps]  # the certified range
    zetas = restitution.fast.zeta_from_eps(eps, end=end)
    assert np.all(zetas > 0)
    np.testing.assert_allclose(restitution.fast.eps(zetas, end=end), eps, rtol=1e-13, atol=0)
    assert restitution.fast.zeta_from_eps(1.0, end=end) == 0.0
    assert restitution.fast.zeta_from_eps(float(eps[3]), end=end) == zetas[3]


@pytest.mark.parametrize("end", ENDS)
def test_durations_match_reference_solutions(reference, end):
    prefix = ENDS[end]
    rows = [row for row in reference if not math.isnan(row[prefix + "_eps"])]
    zetas = np.array([row["zeta"] for row in rows])
    np.testing.assert_allclose(restitution.fast.collision_duration(zetas, end=end),
                               [row[prefix + "_tau"] for row in rows], rtol=1e-13, atol=0)
    tau_max, x_max = restitution.fast.max_compression(zetas)
    np.testing.assert_allclose(tau_max, [row["max_compression_tau"] for row in rows], rtol=1e-13, atol=0)
    np.testing.assert_allclose(x_max, [row["max_compression_x"] for row in rows], rtol=1e-13, atol=0)
    assert restitution.fast.max_compression(float(zetas[5])) == (tau_max[5], x_max[5])
    assert restitution.fast.collision_duration(float(zetas[5]), end) == restitution.fast.collision_duration(
        zetas, end)[5]


def test_the_domain_of_every_front_end():
    """zeta above 1e6 (and the eps only such zeta give) is refused in the CLI's words, never answered."""
    fast = restitution.fast
    assert fast.collision_duration(1e6, "naive") > 0 and fast.max_compression(np.array([1e-3, 1e6]))[1].shape == (2,)
    for function in (fast.eps, fast.one_minus_eps, fast.collision_duration):
        with pytest.raises(ValueError, match=r"zeta = 2000000 is outside the checked range 0 <= zeta <= 1e\+06$"):
            function(2e6)
        with pytest.raises(ValueError, match=r"zeta must be finite and >= 0, got inf \(zeta at index 1\)"):
            function([1.0, math.inf])
    with pytest.raises(ValueError, match=r"outside the checked range 0 <= zeta <= 1e\+06 \(zeta at index 1\)"):
        fast.max_compression(np.array([1e-3, 1e7]))
    for end in ENDS:
        with pytest.raises(ValueError, match=r"eps = 1e-300 is below eps\(zeta = 1e\+06\) = .* outside the checked range"):
            fast.zeta_from_eps(1e-300, end)
        assert fast.zeta_from_eps(fast.eps(1e6, end), end) <= 1e6 * (1 + 1e-12)
    with pytest.raises(ValueError, match=r"zeta = -1 must be >= 0$"):
        fast.max_compression(-1.0)
    with pytest.raises(ValueError, match=r"zeta = nan must be >= 0 \(zeta at index 1\)"):
        fast.collision_duration([1.0, math.nan])


def test_shapes():
    fast = restitution.fast
    assert isinstance(fast.eps(1.0), float) and isinstance(fast.eps(1), float)
    assert isinstance(fast.eps(np.float32(1.0)), float) and isinstance(fast.eps(np.array(1.0)), float)
    assert isinstance(fast.zeta_from_eps(np.float64(0.5)), float)
    grid = np.linspace(0.1, 2.0, 12)
    for shape in [(12,), (3, 4), (2, 3, 2)]:
        for function, values in ((fast.eps, grid), (fast.one_minus_eps, grid), (fast.zeta_from_eps, grid / 2.5)):
            out = function(values.reshape(shape))
            assert out.shape == shape and out.dtype == np.float64
            np.testing.assert_array_equal(out.ravel(), function(values))
    np.testing.assert_array_equal(fast.eps([[0.5, 1], [2, 4]]), fast.eps(np.array([[0.5, 1.0], [2.0, 4.0]])))
    strided = np.linspace(0.1, 2.0, 24)[::2]  # non-contiguous, and float32
    np.testing.assert_array_equal(fast.eps(strided), fast.eps(strided.copy()))
    np.testing.assert_array_equal(fast.eps(grid.astype(np.float32)), fast.eps(grid.astype(np.float32).astype(float)))
    assert fast.eps([1.0]).shape == (1,)


@pytest.mark.parametrize("function", ["eps", "one_minus_eps"])
def test_bad_zeta(function):
    f = getattr(restitution.fast, function)
    with pytest.raises(ValueError, match=r"zeta = nan must be >= 0$"):
        f(math.nan)
    with pytest.raises(ValueError, match=r"zeta = -1 must be >= 0$"):
        f(-1.0)
    with pytest.raises(ValueError, match=r"zeta = nan must be >= 0 \(zeta at index 2\)"):
        f([0.1, 0.2, math.nan, 0.3])
    with pytest.raises(ValueError, match=r"zeta = -0.5 must be >= 0 \(zeta at index \(1, 0\)\)"):
        f([[0.1, 0.2], [-0.5, 0.3]])


def test_bad_eps():
    f = restitution.fast.zeta_from_eps
    for value, shown in ((0.0, "0"), (1.5, "1.5"), (-0.1, "-0.1"), (math.nan, "nan")):
        with pytest.raises(ValueError, match=rf"eps = {shown} is not in \(0, 1\]$"):
            f(value)
    with pytest.raises(ValueError, match=r"eps = 0 is not in \(0, 1\] \(eps at index 1\)"):
        f([0.5, 0.0])
    with pytest.raises(ValueError, match=r"eps = 2 is not in \(0, 1\] \(eps at index \(0, 1\)\)"):
        f([[0.5, 2.0]], end="naive")


@pytest.mark.parametrize("function", ["eps", "one_minus_eps", "zeta_from_eps"])
def test_wrong_end_empty_and_types(function):
    f = getattr(restitution.fast, function)
    with pytest.raises(ValueError, match="end must be naive or delayed-recovery, got 'both'"):
        f(0.5, end="both")
    with pytest.raises(ValueError, match="end must be naive or delayed-recovery, got 'Naive'"):
        f([0.5], end="Naive")
    with pytest.raises(ValueError, match="empty array"):
        f(np.zeros((0, 2)))
    with pytest.raises(TypeError, match="end must be a str"):
        f(0.5, end=1)
    with pytest.raises(TypeError):
        f("0.5")
    with pytest.raises(TypeError):
        f([1 + 2j])


_C_PROGRAM = r"""
#include <stdio.h>
#include "fast_table.h"
int main(void) {
  double x;
  while (scanf("%la", &x) == 1)
    printf("%a %a %a %a %a %a\n", restitution_eps_naive(x), restitution_eps_delayed_recovery(x),
           restitution_one_minus_eps_naive(x), restitution_one_minus_eps_delayed_recovery(x),
           restitution_zeta_from_eps_naive(x), restitution_zeta_from_eps_delayed_recovery(x));
  return 0;
}
"""


def test_bit_for_bit_with_the_c_header(tmp_path):
    """The library's table compiled from src/fast/fast_table.h as C gives the module's numbers exactly."""
    compiler = os.environ.get("CC") or shutil.which("cc") or shutil.which("gcc")
    if compiler is None:
        pytest.skip("no C compiler to build the header's check")
    source = tmp_path / "check.c"
    source.write_text(_C_PROGRAM)
    program = tmp_path / "check"
    subprocess.run([compiler, "-std=c99", "-O2", "-I", str(pathlib.Path(SOURCE_DIR) / "src" / "fast"),
                    str(source), "-o", str(program), "-lm"], check=True)
    xs = np.concatenate(([0.0], np.logspace(-6, 6, 300), np.linspace(0.001, 0.999, 200), [1.0]))
    lines = subprocess.run([str(program)], input="\n".join(float(x).hex() for x in xs), capture_output=True,
                           text=True, check=True).stdout.splitlines()
    assert len(lines) == len(xs)
    f = restitution.fast
    for x, line in zip(xs, lines):
        values = [float.fromhex(v) for v in line.split()]
        assert values[:4] == [f.eps(x, "naive"), f.eps(x), f.one_minus_eps(x, "naive"), f.one_minus_eps(x)], x
        if 0 < x <= 1:
            for c_zeta, end in zip(values[4:], ("naive", "delayed-recovery")):
                if c_zeta <= 1e6:
                    assert f.zeta_from_eps(x, end) == c_zeta, x
                else:  # the header goes on with the large-zeta law; the module keeps the checked range
                    with pytest.raises(ValueError, match="outside the checked range"):
                        f.zeta_from_eps(x, end)
