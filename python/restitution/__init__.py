# SPDX-License-Identifier: BSD-3-Clause
"""Coefficient of restitution of viscoelastic spheres.

eps(zeta) solves the collision x'' + zeta sqrt(x) x' + x^(3/2) = 0, x(0) = 0, x'(0) = 1 (natural units,
zeta = beta v^(1/5)) to a certified accuracy |eps - eps_exact| <= tolerance * min(eps, 1 - eps).

    >>> import restitution
    >>> restitution.eps(0.1)                                    # float in, float out
    >>> restitution.eps(numpy.logspace(-3, 3, 7), end="naive")  # array in, array of the same shape out
    >>> restitution.eps(material=steel, velocity=[0.1, 1.0])    # velocities in m/s

Errors: ValueError for bad input (the message names the argument, the value and, for arrays, the index);
TypeError for arguments of the wrong type or combination; restitution.NumericalFailure (an ArithmeticError)
when the solver cannot deliver the accuracy. Array calls run on all cores without the GIL and stop with
KeyboardInterrupt on Ctrl-C. restitution.fast gives the same eps from the certified table, ~20 ns a value.
"""

import numbers as _numbers

import numpy as _np

from . import _restitution as _core
from . import fast, series
from ._restitution import CollisionResult, EndResult, Calibration, Material, MaxCompression
from ._restitution import NumericalFailure, SolverStats
from ._restitution import __version__  # the file VERSION at the root of the checkout

__all__ = ["__version__", "eps", "solve", "calibrate", "fit_data", "zeta_of", "Material", "NumericalFailure", "CollisionResult",
           "EndResult", "MaxCompression", "SolverStats", "Calibration", "series", "fast"]

_SCALARS = (float, int)
_TOLERANCE = _core.default_tolerance  # SolveOptions' default, the command line's too
_SPEED_INDEPENDENT_END = _core.default_speed_independent_end  # fit_data's, as fit-data's on the command line


def _real_array(name, value):
    """value as a float64 array; TypeError naming the argument for anything but real numbers (a bool too)."""
    if isinstance(value, (str, bytes, bool, _np.bool_)) or value is None:
        raise TypeError(f"{name} must be a real number or an array-like of real numbers, got {type(value).__name__}")
    try:
        array = _np.asarray(value)
    except ValueError as error:  # ragged nested sequences
        raise TypeError(f"{name} must be a real number or a rectangular array-like: {error}") from None
    if array.dtype.kind not in "iuf":  # not "b": True is no speed, and would be read as 1
        raise TypeError(f"{name} must hold real numbers, got an array of dtype {array.dtype}")
    return _np.asarray(array, dtype=_np.float64, order="C")  # keeps 0-d arrays 0-d


def _text(name, value):
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a str, got {type(value).__name__}")
    return value


def zeta_of(zeta=None, *, beta=None, velocity=None, material=None):
    """The damping parameter zeta (natural units) from exactly one of the three ways to give it.

    zeta: float or array-like, >= 0.
    beta [s^(1/5) m^(-1/5)] with velocity [m/s]: zeta = beta v^(1/5), arrays broadcast.
    material (restitution.Material, with its dissipation) with velocity [m/s]: beta = material.beta.
    Raises ValueError for a zeta outside the checked range 0 <= zeta <= 1e6 (or NaN), as eps() does.
    Returns a float for scalar input, else a float64 array of the broadcast shape.
    """
    given = [zeta is not None, beta is not None, material is not None]
    if sum(given) != 1:
        raise TypeError("give exactly one of zeta, beta (with velocity) and material (with velocity)")
    if zeta is not None:
        if velocity is not None:
            raise TypeError("velocity goes with beta or material, not with zeta")
        if type(zeta) in _SCALARS:
            return _checked_zeta(float(zeta))
        array = _real_array("zeta", zeta)
        return _checked_zeta(float(array)) if array.ndim == 0 else _checked_zetas(array)
    if velocity is None:
        raise TypeError("beta and material need velocity [m/s]")
    if material is not None:
        if not isinstance(material, Material):
            raise TypeError(f"material must be a restitution.Material, got {type(material).__name__}")
        beta = material.beta
    if type(beta) in _SCALARS and type(velocity) in _SCALARS:
        return _core.zeta_from(float(beta), float(velocity))
    b, v = _np.broadcast_arrays(_real_array("beta", beta), _real_array("velocity", velocity))
    zetas = _core.zetas_from(_np.asarray(b, order="C"), _np.asarray(v, order="C"))
    return _checked_zeta(float(zetas)) if zetas.ndim == 0 else _checked_zetas(zetas)


_LARGEST_ZETA = _core.largest_checked_zeta


def _checked_zeta(zeta):
    """zeta in the checked range 0 <= zeta <= 1e6, else ValueError in the library's words."""
    _core.require_checked_zeta(zeta)
    return zeta


def _checked_zetas(zetas):
    bad = _np.flatnonzero(~((zetas >= 0.0) & (zetas <= _LARGEST_ZETA)))
    if bad.size:
        index = _np.unravel_index(bad[0], zetas.shape)
        try:
            _core.require_checked_zeta(float(zetas[index]))
        except ValueError as error:
            where = index if len(index) > 1 else index[0]
            raise ValueError(f"{error} (zeta at index {where})") from None
    return zetas


def _law(law, zeta=None, beta=None, material=None):
    """The law's name, checked; beta and material describe viscoelastic Hertz only."""
    _text("law", law)
    if law not in _core.law_names:
        raise ValueError(f"law must be one of {', '.join(_core.law_names)}, got '{law}'")
    if (beta is not None or material is not None) and not _core.has_dissipative_constant(law):
        described = " or ".join(f"law='{name}'" for name in _core.law_names if _core.has_dissipative_constant(name))
        raise TypeError(f"beta and material describe {described}; law='{law}' takes zeta")
    return law


def eps(zeta=None, end="delayed-recovery", tolerance=_TOLERANCE, method="auto", *, beta=None, velocity=None,
        material=None, law="viscoelastic-hertz", threads=None):
    """Coefficient of restitution eps at one end of the collision.

    zeta: float or array-like in the checked range 0 <= zeta <= 1e6 (natural units; above it ValueError, as
        on the command line), or instead beta [s^(1/5) m^(-1/5)] with velocity [m/s]
        (arrays broadcast), or a Material with velocity [m/s].
    end: "delayed-recovery" (the force vanishes; the physical end) or "naive" (the overlap vanishes).
    tolerance: |eps - eps_exact| <= tolerance * min(eps, 1 - eps), in [1e-11, 1e-2] for the CVODE methods,
        [1e-13, 1e-2] for taylor.
    method: "auto" (CVODE, BDF or Adams per regime), "bdf", "adams" or "taylor" (Taylor series; fastest;
        the naive end for zeta <= 100 only).
    law: the contact law (docs/contact_laws.md): "viscoelastic-hertz" (default), "tsuji-hertz",
        "hertz-constant-damping" or "linear-dashpot"; zeta is that law's natural-form parameter in
        x'' + zeta x^b x' + x^a = 0 (the dash-pot: zeta = 2 r); beta and material are Hertz only.
    threads: worker threads for an array, an int in [1, 1024]; None (default): all cores. As the command
        line's sweep --threads. A scalar is solved on the calling thread.
    Returns a float for scalar input, else a float64 array of the same (broadcast) shape, computed on all
    cores (or `threads`) with the GIL released (Ctrl-C -> KeyboardInterrupt).
    Raises ValueError (bad value, empty array; the message names the index), TypeError (wrong type),
    NumericalFailure (accuracy not reached; names the index).
    """
    if (type(zeta) is float and beta is None and material is None and velocity is None and type(end) is str
            and type(method) is str and type(tolerance) is float and law == "viscoelastic-hertz"
            and threads is None):
        return _core.eps_scalar(zeta, end, tolerance, method, law)  # fast path; pybind11 checks the types
    workers = _threads(threads)
    law = _law(law, zeta, beta, material)
    z = zeta_of(zeta, beta=beta, velocity=velocity, material=material)
    if isinstance(z, float):
        return _core.eps_scalar(z, _text("end", end), _tolerance(tolerance), _text("method", method), law)
    return _core.eps_array(z, _text("end", end), _tolerance(tolerance), _text("method", method), law, workers)


_MAX_THREADS = _core.max_threads  # the library's bound, as the command line's --threads


def _threads(threads):
    """The worker count for the library's sweep: 0 (all cores) for None."""
    if threads is None:
        return 0
    if isinstance(threads, bool) or not isinstance(threads, _numbers.Integral):
        raise TypeError(f"threads must be an int, got {type(threads).__name__}")
    if not 1 <= threads <= _MAX_THREADS:
        raise ValueError(f"threads must lie in [1, {_MAX_THREADS}] (default: all cores), got {threads}")
    return int(threads)


def _tolerance(tolerance):
    if isinstance(tolerance, bool) or not isinstance(tolerance, _numbers.Real):
        raise TypeError(f"tolerance must be a real number, got {type(tolerance).__name__}")
    return float(tolerance)


def solve(zeta=None, end="both", tolerance=_TOLERANCE, method="auto", trajectory=False, *, beta=None,
          velocity=None, material=None, law="viscoelastic-hertz"):
    """One collision in full: a CollisionResult with, in natural units,

    .naive / .delayed_recovery: EndResult (eps, one_minus_eps, tau, x, velocity, dissipated_energy) or
        None for the end not asked for; .max_compression (tau, x); .stats (steps, rhs_evaluations, ...);
    .method (the one used), .zeta, .tolerance; with trajectory=True the numpy arrays .tau, .x, .velocity
        (x') and .acceleration (x'') at every internal step and event.
    zeta, beta/velocity or material/velocity as for eps() but scalar only; end "both" (default), "naive"
    or "delayed-recovery"; law as for eps() (.law names it; .zeta is the damping ratio r for the dash-pot).
    Raises ValueError, TypeError, NumericalFailure as eps() does.
    """
    law = _law(law, zeta, beta, material)
    if not isinstance(trajectory, bool):
        raise TypeError(f"trajectory must be True or False, got {type(trajectory).__name__}")
    z = zeta_of(zeta, beta=beta, velocity=velocity, material=material)
    if not isinstance(z, float):
        raise TypeError("solve() takes one collision: zeta (or beta, velocity) must be scalars; use eps() for arrays")
    return _core.solve(z, _text("end", end), _tolerance(tolerance), _text("method", method), bool(trajectory), law)


def calibrate(eps, velocity, end="delayed-recovery", material=None, tolerance=_TOLERANCE, method="auto", *,
              law="viscoelastic-hertz"):
    """The damping that gives a measured eps in (0, 1) at the impact speed velocity [m/s].

    Returns a Calibration: .zeta (natural units), .beta [s^(1/5) m^(-1/5)], .characteristic_velocity
    (the 1999 paper's g* [m/s]), .dissipative_constant (A [s] for the material's elastic data, else None),
    .eps_at_zeta, .solves. end as for eps(). Raises ValueError for eps outside (0, 1) or below eps(zeta = 1e6) (the checked range).
    law as for eps(): for another law than viscoelastic Hertz .zeta (and .parameter, the dash-pot's r) is
    the result and .beta, .characteristic_velocity are 0 (no material).
    """
    law = _law(law, material=material)
    if material is not None and not isinstance(material, Material):
        raise TypeError(f"material must be a restitution.Material, got {type(material).__name__}")
    for name, value in (("eps", eps), ("velocity", velocity)):
        if isinstance(value, bool) or not isinstance(value, _numbers.Real):
            raise TypeError(f"{name} must be a real number, got {type(value).__name__}")
    return _core.calibrate(float(eps), float(velocity), _text("end", end), _tolerance(tolerance),
                           _text("method", method), material, law)


def _measurements(name, value):
    """One value per measurement: a 2-D table is refused, not flattened into points it does not hold."""
    array = _real_array(name, value)
    if array.ndim > 1:
        raise ValueError(f"{name} must be one-dimensional (one value per measurement), got an array of shape "
                         f"{array.shape}")
    return array.ravel().tolist()


def fit_data(v, eps, sigma=None, *, laws=None, speed_independent_end=_SPEED_INDEPENDENT_END, material=None,
             tolerance=_TOLERANCE, method="auto"):
    """Fit measured eps at impact speeds v [m/s] (optional standard deviations sigma) with every candidate law.

    Candidates: viscoelastic Hertz at the delayed-recovery and naive ends (parameter "beta"
    [s^(1/5) m^(-1/5)]), Tsuji ("zeta") and the linear dash-pot ("damping-ratio") at speed_independent_end;
    laws (names as restitution's law names) restricts them. Returns a dict with the keys of
    `restitution fit-data --json` (docs/fit.md): "fits" (one dict per law: "value", "ci68", "ci95" as
    [low, high] from the profile of chi2, a bound at the edge of the checked range being None, "chi2_per_dof",
    "aic", "converged", "residual_tests", ...), "best" (index of the lowest AIC), "sigma_estimated" (True
    without sigma: the scatter is estimated from the residuals and the intervals use t quantiles). With a
    Material, the Hertz fits carry "dissipative_constant_s" (A [s]) with its intervals. Raises ValueError for
    bad data (eps outside (0, 1), v <= 0, sigma outside [1e-100, 1e100], NaN, too few points, an array of more
    than one dimension) and for a law that is not a candidate.
    """
    if material is not None and not isinstance(material, Material):
        raise TypeError(f"material must be a restitution.Material, got {type(material).__name__}")
    v = _measurements("v", v)
    eps = _measurements("eps", eps)
    sigma = None if sigma is None else _measurements("sigma", sigma)
    if laws is not None:
        laws = [_text("laws", law) for law in ([laws] if isinstance(laws, str) else laws)]
    return _core.fit_data(v, eps, sigma, laws, _text("speed_independent_end", speed_independent_end), material,
                          _tolerance(tolerance), _text("method", method))


import os as _os  # noqa: E402 (sweep_to_file's section, kept together)


def sweep_to_file(zetas, path, *, resume=False, end="both", tolerance=_TOLERANCE, method="auto", threads=None,
                  law="viscoelastic-hertz", stop=None):
    """Solve at every zeta of a 1-d array and write the table into the CSV file `path`, as `restitution sweep`
    writes it (the same bytes for the same grid and options), keeping every finished row in path.partial.

    Ctrl-C (KeyboardInterrupt) or stop (a callable polled every ~20 ms, stopping the sweep when it returns
    True) ends the sweep after the points in progress and keeps path.partial; the same call with resume=True
    continues from it and writes the same bytes as an uninterrupted sweep. end "naive", "delayed-recovery" or
    "both"; law, tolerance, method and threads as for eps(). Returns a dict: "status" ("complete",
    "already_complete": resume=True found path complete and computed nothing, or "stopped"), "path",
    "partial_path", "points", "finished", "resumed" (rows kept from path.partial), "damaged_lines",
    "first_damaged_line" (1-based, 0: none) and "failed" (points whose rows say why they failed). Raises
    ValueError for a bad zeta or option, for path.partial without resume=True, and for a path.partial written
    by another sweep (naming the file); OSError when a file cannot be written.
    """
    z = _real_array("zetas", zetas)
    if z.ndim != 1:
        raise ValueError(f"zetas must be a 1-d array, got {z.ndim} dimensions")
    if stop is not None and not callable(stop):
        raise TypeError(f"stop must be callable or None, got {type(stop).__name__}")
    return _core.sweep_to_file(z.tolist(), _os.fspath(path), bool(resume), _text("end", end), _tolerance(tolerance),
                               _text("method", method), _threads(threads), _law(law), stop)


__all__.append("sweep_to_file")
