# SPDX-License-Identifier: BSD-3-Clause
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


_STEEL = dict(young_modulus=2e11, poisson_ratio=0.3, radius=0.01, density=7800.0)


def test_material_names_a_missing_field():
    with pytest.raises(TypeError, match=r"^Material needs young_modulus") as error:
        restitution.Material()
    assert "incompatible" not in str(error.value)
    with pytest.raises(TypeError, match=r"^Material needs poisson_ratio"):
        restitution.Material(young_modulus=2e11, radius=0.01, density=7800.0)
    with pytest.raises(TypeError, match=r"^Material needs poisson_ratio"):
        restitution.Material(**{**_STEEL, "poisson_ratio": None})


def test_material_names_an_unknown_field():
    with pytest.raises(TypeError, match=r"^Material has no field 'foo'; the fields are young_modulus, ") as error:
        restitution.Material(**_STEEL, foo=1)
    assert "incompatible" not in str(error.value)
    with pytest.raises(TypeError, match=r"^Material has no field 'raduis'"):
        restitution.Material(young_modulus=2e11, poisson_ratio=0.3, raduis=0.01, density=7800.0)


def test_material_names_a_mistyped_field_and_positional_arguments():
    with pytest.raises(TypeError, match=r"^Material: radius must be a real number, got str"):
        restitution.Material(**{**_STEEL, "radius": "big"})
    with pytest.raises(TypeError, match=r"^Material: radii must be a pair of real numbers, got float"):
        restitution.Material(**{**_STEEL, "radius": None, "radii": 0.01})
    with pytest.raises(TypeError, match=r"^Material takes keyword arguments only, got 2 positional"):
        restitution.Material(2e11, 0.3, radius=0.01, density=7800.0)


def test_material_keywords_still_build_the_same_material():
    steel = restitution.Material(**_STEEL, dissipative_constant=1e-6)
    assert steel.radii == (0.01, 0.01) and steel.density == 7800.0 and steel.masses is None
    pair = restitution.Material(young_modulus=2e11, poisson_ratio=0.3, radii=(0.01, 0.01), masses=(0.1, 0.1),
                                viscosities=(1e3, 1e3))
    assert pair.masses == (0.1, 0.1) and pair.viscosities == (1e3, 1e3)
