"""Issue 25 item 11: Python refuses bad arguments in its own words, naming the argument."""

import pytest

import restitution


def test_none_for_end_and_method_names_the_argument():
    with pytest.raises(TypeError, match="end must be a str, got NoneType"):
        restitution.eps(1.0, end=None)
    with pytest.raises(TypeError, match="method must be a str, got NoneType"):
        restitution.eps(1.0, method=None)


def test_zeta_of_validates():
    for bad in (-1.0, float("inf"), 2e6, float("nan")):
        with pytest.raises(ValueError, match="zeta"):
            restitution.zeta_of(bad)
    with pytest.raises(ValueError, match=r"zeta at index 1"):
        restitution.zeta_of([0.5, -1.0])


def test_trajectory_must_be_a_bool():
    with pytest.raises(TypeError, match="trajectory must be True or False"):
        restitution.solve(1.0, trajectory="yes")


def test_numbers_does_not_leak():
    assert not hasattr(restitution, "numbers")
