# SPDX-License-Identifier: BSD-3-Clause
"""The library's certified fast table of eps(zeta) (docs/fast.md), natural units (zeta = beta v^(1/5)).

Piecewise polynomials in ln zeta, fitted to the quad-precision reference engine: |eps - eps_exact| <=
1e-13 * min(eps, 1 - eps) for 0 <= zeta <= 1e6 (delayed-recovery end) and 1e5 (naive end; above it the
large-zeta asymptotic law). The collision duration and the maximal compression likewise (their accuracy:
docs/fast.md). Like every front end, this module refuses zeta > 1e6 (and eps below eps(1e6) in the inverse)
with ValueError; inside that domain it returns the same bits as the C++ functions restitution::fast::eps,
one_minus_eps and zeta_from_eps and the exported C header (which go on beyond it with the large-zeta laws).
No ODE solve (the library's cost per value: docs/fast.md).

Examples
--------
>>> import numpy, restitution
>>> round(restitution.fast.eps(0.1), 12)                           # float in, float out
0.892858875507
>>> restitution.fast.eps(numpy.logspace(-3, 3, 7), end="naive").shape  # array in, same shape out
(7,)
>>> round(restitution.fast.zeta_from_eps(0.8), 10)                 # the inverse
0.2011366613

Errors: ValueError naming the value and, for arrays, the index (NaN, zeta < 0 or > 1e6, eps outside (0, 1] or
below eps(1e6), an unknown end, an empty array); TypeError for non-real arguments. Array loops run with the GIL released.
"""

import restitution as _package  # its argument checks, looked up at call time (this module loads first)

from ._restitution import fast as _core

__all__ = ["eps", "one_minus_eps", "zeta_from_eps", "collision_duration", "max_compression"]


def _call(name, argument, value, end):
    end = _package._end(end)
    if type(value) in (float, int):
        return getattr(_core, name)(float(value), end)
    array = _package._real_array(argument, value)
    if array.ndim == 0:
        return getattr(_core, name)(float(array), end)
    return getattr(_core, name + "_array")(array, end)


def eps(zeta, end="delayed-recovery"):
    """Coefficient of restitution eps (dimensionless) at 0 <= zeta <= 1e6 (natural units).

    end: "delayed-recovery" (the force vanishes; the physical end) or "naive" (the overlap vanishes).
    Returns a float for scalar input, else a float64 array of the same shape.
    Accuracy |eps - eps_exact| <= 1e-13 * min(eps, 1 - eps) for zeta <= 1e6 (naive: 1e5).
    Raises ValueError for NaN, zeta < 0 or zeta > 1e6 (naming the index in an array) or an unknown end.
    """
    return _call("eps", "zeta", zeta, end)


def one_minus_eps(zeta, end="delayed-recovery"):
    """1 - eps (dimensionless) at 0 <= zeta <= 1e6 (natural units), to its own relative accuracy: use it where eps
    is close to 1 (small zeta), where 1 - eps(zeta) would lose digits. Arguments, shapes, errors as eps().
    """
    return _call("one_minus_eps", "zeta", zeta, end)


def zeta_from_eps(eps, end="delayed-recovery"):
    """The inverse: zeta (natural units) with eps(zeta) = eps, for eps in (0, 1] (dimensionless; 1 gives 0).

    The relative accuracy of eps(result) is 1e-13 of min(eps, 1 - eps) within the certified range.
    Returns a float for scalar input, else a float64 array of the same shape.
    Raises ValueError for NaN, eps outside (0, 1] or below eps(zeta = 1e6) (naming the index in an array)
    or an unknown end.
    """
    return _call("zeta_from_eps", "eps", eps, end)


def collision_duration(zeta, end="delayed-recovery"):
    """Collision duration tau_c (natural units) at 0 <= zeta <= 1e6 (natural units): the table, above it the
    large-zeta law (relative accuracy in docs/fast.md).
    Arguments, shapes, errors as eps().
    """
    return _call("collision_duration", "zeta", zeta, end)


def max_compression(zeta):
    """(tau_max, x_max): time and size of the maximal compression (natural units) at 0 <= zeta <= 1e6
    (natural units), floats for scalar input, else two float64 arrays of the input's shape. Errors as eps().
    """
    if type(zeta) in (float, int):
        return _core.max_compression(float(zeta))
    array = _package._real_array("zeta", zeta)
    if array.ndim == 0:
        return _core.max_compression(float(array))
    return _core.max_compression_array(array)
