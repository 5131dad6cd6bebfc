# SPDX-License-Identifier: BSD-3-Clause
"""Shapes in, shapes out: floats stay floats, arrays keep their shape, beta and velocity broadcast."""

import numpy as np
import pytest

import restitution


def test_scalars_return_floats():
    for zeta in (0.5, 1, np.float64(0.5), np.array(0.5)):
        assert isinstance(restitution.eps(zeta), float)
    assert isinstance(restitution.eps(beta=0.5, velocity=1.0), float)


@pytest.mark.parametrize("shape", [(1,), (4,), (2, 3), (2, 1, 3)])
def test_arrays_keep_their_shape(shape):
    zetas = np.linspace(0.0, 2.0, int(np.prod(shape))).reshape(shape)
    eps = restitution.eps(zetas, method="taylor")
    assert eps.shape == shape and eps.dtype == np.float64
    flat = [restitution.eps(float(z), method="taylor") for z in zetas.ravel()]
    np.testing.assert_array_equal(eps.ravel(), flat)


def test_lists_tuples_and_non_contiguous_arrays():
    zetas = np.linspace(0.1, 1.0, 10)
    expected = restitution.eps(zetas)
    np.testing.assert_array_equal(restitution.eps(list(zetas)), expected)
    np.testing.assert_array_equal(restitution.eps(tuple(zetas)), expected)
    np.testing.assert_array_equal(restitution.eps(zetas[::2]), expected[::2])
    np.testing.assert_array_equal(restitution.eps(zetas.astype(np.float32)),
                                  restitution.eps(zetas.astype(np.float32).astype(np.float64)))


def test_beta_and_velocity_broadcast():
    beta = np.array([[0.1], [0.2]])
    velocity = np.array([0.5, 1.0, 2.0])
    eps = restitution.eps(beta=beta, velocity=velocity)
    assert eps.shape == (2, 3)
    np.testing.assert_array_equal(eps, restitution.eps(restitution.zeta_of(beta=beta, velocity=velocity)))
    np.testing.assert_allclose(restitution.zeta_of(beta=beta, velocity=velocity), beta * velocity ** 0.2, rtol=1e-15)
    assert restitution.eps(beta=0.1, velocity=velocity).shape == (3,)
    assert restitution.zeta_of(beta=beta, velocity=1.0).shape == (2, 1)


def test_incompatible_shapes_raise_value_error():
    with pytest.raises(ValueError):
        restitution.eps(beta=[0.1, 0.2], velocity=[1.0, 2.0, 3.0])
