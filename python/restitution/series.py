# SPDX-License-Identifier: BSD-3-Clause
"""Analytic series and closed-form approximations of eps(zeta), natural units (zeta = beta v^(1/5)).

coefficients(kind, count): recomputed coefficients (kinds: coefficient_kinds).
eval(kind, zeta, terms=None, coefficients="computed"): eps of a series or approximation (kinds:
evaluation_kinds), zeta a float or array-like.
Sources: Schwager & Poeschel, Phys. Rev. E 78, 051304 (2008); Ramirez et al., Phys. Rev. E 60, 4465
(1999); Mueller & Poeschel, Phys. Rev. E 84, 021302 (2011).
"""

import numpy as _np

from ._restitution import series as _core

coefficient_kinds = _core.coefficient_kinds
evaluation_kinds = _core.evaluation_kinds

__all__ = ["coefficients", "eval", "coefficient_kinds", "evaluation_kinds"]


def coefficients(kind, count):
    """count recomputed coefficients of a series (computed in __float128, rounded to double).

    kind "naive": array c_1..c_N of eps = 1 + sum_k c_k zeta^k (N <= 60);
    "delayed-recovery": array h_0..h_N of eps = sum_k h_k zeta^(k/2) (N <= 120);
    "max-compression": tuple (a_1..a_N, b_0..b_N) with tau_max = tau_max0 + sum a_k zeta^k and
    x_max = sum b_k zeta^k (N <= 60). Raises ValueError naming kind or count.
    """
    if not isinstance(kind, str):
        raise TypeError(f"kind must be a str, got {type(kind).__name__}")
    if isinstance(count, bool) or not isinstance(count, (int, _np.integer)):
        raise TypeError(f"count must be an int, got {type(count).__name__}")
    return _core.coefficients(kind, int(count))


def eval(kind, zeta, terms=None, coefficients="computed"):  # noqa: A001 (the name the issue asks for)
    """eps of a series or closed-form approximation at zeta >= 0 (float or array-like; same shape out).

    kind: "naive-series", "delayed-recovery-series" (terms = c_1..c_N or h_0..h_N, default 40 and 60; the
    old spellings "naive", "delayed-recovery" are aliases; "NAME:published" / "NAME:computed-N" name the
    coefficients as series validate does), "pade-1999", "pade-1999-corrected", "simple-theory-1999",
    "pade-2011-1-4", "pade-2011-3-6" (no terms): the names scene files use (evaluation_kinds).
    coefficients: "computed" (recomputed here) or "published" (2008 paper, Tables III and V).
    The series diverge beyond their radius of convergence; see docs/series.md.
    Raises ValueError naming kind, zeta (and its index), terms or coefficients.
    """
    if not isinstance(kind, str):
        raise TypeError(f"kind must be a str, got {type(kind).__name__}")
    if coefficients not in ("computed", "published"):
        raise ValueError(f"coefficients must be computed or published, got {coefficients!r}")
    if terms is not None and (isinstance(terms, bool) or not isinstance(terms, (int, _np.integer))):
        raise TypeError(f"terms must be an int or None, got {type(terms).__name__}")
    from . import _real_array  # the package's one argument check

    array = _real_array("zeta", zeta)
    values = _core.eval(kind, array.reshape(array.shape or (1,)), None if terms is None else int(terms),
                        coefficients == "published")
    return float(values[0]) if array.ndim == 0 else values
