# SPDX-License-Identifier: BSD-3-Clause
"""Coefficient of restitution of viscoelastic spheres.

eps(zeta) solves the collision x'' + zeta sqrt(x) x' + x^(3/2) = 0, x(0) = 0, x'(0) = 1 (natural units,
zeta = beta v^(1/5)) to a certified accuracy |eps - eps_exact| <= tolerance * min(eps, 1 - eps).

Examples
--------
>>> import numpy, restitution
>>> round(restitution.eps(0.1), 10)                                  # float in, float out
0.8928588755
>>> restitution.eps(numpy.logspace(-3, 3, 7), end="naive").shape      # array in, same shape out
(7,)
>>> steel = restitution.Material(young_modulus=2.0e11, poisson_ratio=0.3, radius=0.01, density=7800.0,
...                              dissipative_constant=2e-6)          # Pa, m, kg/m^3, s
>>> restitution.eps(material=steel, velocity=[0.1, 1.0]).round(6)     # velocities in m/s
array([0.893312, 0.838058])

Errors: ValueError for bad input (the message names the argument, the value and, for arrays, the index);
TypeError for arguments of the wrong type or combination; restitution.NumericalFailure (an ArithmeticError)
when the solver cannot deliver the accuracy. Array calls run on all cores without the GIL and stop with
KeyboardInterrupt on Ctrl-C. restitution.fast gives the same eps from the certified table, ~20 ns a value.
"""

import numbers as _numbers
import os as _os
import warnings as _warnings

import numpy as _np

from . import _restitution as _core
from . import fast, series
from ._restitution import CollisionResult, EndResult, Calibration, Material, MaxCompression
from ._restitution import NumericalFailure, SolverStats
from ._restitution import __version__  # the file VERSION at the root of the checkout
from ._renamed import add_old_names as _add_old_names

__all__ = ["__version__", "eps", "solve", "calibrate", "fit_data", "zeta_of", "build_info", "Material",
           "NumericalFailure", "CollisionResult", "EndResult", "MaxCompression", "SolverStats", "Calibration", "series",
           "fast"]

# The names before the JSON's (issue 44, item 13), kept until 0.5.0.
_add_old_names(Calibration, (("characteristic_velocity", "characteristic_velocity_m_s"),
                             ("dissipative_constant", "dissipative_constant_s")))

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


def _end(end):
    """end as the library spells it: the attribute and JSON spelling "delayed_recovery" is the same end."""
    return _text("end", end).replace("_", "-")


def _scalar(value):
    """A 0-d numpy array of real numbers as the number it holds (numpy's reductions return them); else value."""
    if isinstance(value, _np.ndarray) and value.ndim == 0 and value.dtype.kind in "iuf":
        return value.item()
    return value


def zeta_of(zeta=None, *, beta=None, velocity=None, material=None):
    """The damping parameter zeta (natural units) from exactly one of the three ways to give it.

    Parameters
    ----------
    zeta : float or array_like, optional
        zeta itself, 0 <= zeta <= 1e6.
    beta : float or array_like, optional
        beta [s^(1/5) m^(-1/5)], with velocity: zeta = beta v^(1/5) (arrays broadcast).
    velocity : float or array_like, optional
        Impact speed [m/s], with beta or material.
    material : Material, optional
        With its dissipation, and velocity: beta = material.beta.

    Returns
    -------
    float or numpy.ndarray
        A float for scalar input, else a float64 array of the broadcast shape.

    Raises
    ------
    ValueError
        zeta outside the checked range 0 <= zeta <= 1e6 (or NaN), as eps() does.
    TypeError
        Not exactly one of zeta, beta and material.

    Examples
    --------
    >>> import restitution
    >>> restitution.zeta_of(beta=0.1, velocity=1.0)
    0.1
    >>> restitution.zeta_of(beta=0.1, velocity=[1.0, 32.0]).round(12)
    array([0.1, 0.2])
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
        material=None, law="viscoelastic-hertz", threads=None, progress=None):
    """Coefficient of restitution eps at one end of the collision.

    Parameters
    ----------
    zeta : float or array_like, optional
        In the checked range 0 <= zeta <= 1e6 (natural units; above it ValueError, as on the command line).
        Or instead beta with velocity, or material with velocity.
    end : {"delayed-recovery", "naive"}
        "delayed-recovery" (the force vanishes; the physical end) or "naive" (the overlap vanishes).
    tolerance : float
        |eps - eps_exact| <= tolerance * min(eps, 1 - eps), in [1e-11, 1e-2] for the CVODE methods,
        [1e-13, 1e-2] for taylor.
    method : {"auto", "bdf", "adams", "taylor"}
        "auto" (CVODE, BDF or Adams per regime), "bdf", "adams" or "taylor" (Taylor series; fastest; the naive
        end for zeta <= 100 only).
    beta : float or array_like, optional
        beta [s^(1/5) m^(-1/5)], with velocity; arrays broadcast.
    velocity : float or array_like, optional
        Impact speed [m/s], with beta or material.
    material : Material, optional
        Spheres with their dissipation, with velocity.
    law : str
        The contact law (docs/contact_laws.md): "viscoelastic-hertz" (default), "tsuji-hertz",
        "hertz-constant-damping" or "linear-dashpot"; zeta is that law's natural-form parameter in
        x'' + zeta x^b x' + x^a = 0 (the dash-pot: zeta = 2 r); beta and material are Hertz only.
    threads : int, optional
        Worker threads for an array, in [1, 1024]; None (default): all cores, as the command line's sweep
        --threads. A scalar is solved on the calling thread.
    progress : callable or bool, optional
        For arrays: a callable(done, total) called a few times a second from the calling thread (with the
        GIL) and once at the end, or True for a tqdm progress bar (when tqdm is installed; Debian:
        python3-tqdm). An exception the callable raises stops the array call. Scalars make no calls.

    Returns
    -------
    float or numpy.ndarray
        A float for scalar input, else a float64 array of the same (broadcast) shape, computed on all cores
        (or `threads`) with the GIL released (Ctrl-C -> KeyboardInterrupt). The same digits as solve()
        gives for the same end, zeta, tolerance and method.

    Raises
    ------
    ValueError
        A bad value or an empty array; the message names the index.
    TypeError
        A wrong type or combination of arguments.
    NumericalFailure
        Accuracy not reached; the message names the index.

    Examples
    --------
    >>> import restitution
    >>> round(restitution.eps(1.0), 10)
    0.3939306032
    >>> restitution.eps(1.0) == restitution.solve(1.0).delayed_recovery.eps
    True
    >>> [f"{e:.6g}" for e in restitution.eps([0.01, 1.0, 100.0], end="naive")]
    ['0.988545', '0.331165', '5.15838e-10']
    >>> calls = []
    >>> restitution.eps([0.1, 0.2, 0.3], progress=lambda done, total: calls.append((done, total))).shape
    (3,)
    >>> calls[-1]
    (3, 3)
    """
    if (type(zeta) is float and beta is None and material is None and velocity is None and type(end) is str
            and type(method) is str and type(tolerance) is float and law == "viscoelastic-hertz"
            and threads is None and progress is None):
        return _core.eps_scalar(zeta, _end(end), tolerance, method, law)  # fast path; pybind11 checks the types
    workers = _threads(threads)
    law = _law(law, zeta, beta, material)
    _check_progress(progress)
    z = zeta_of(zeta, beta=beta, velocity=velocity, material=material)
    if isinstance(z, float):
        return _core.eps_scalar(z, _end(end), _tolerance(tolerance), _text("method", method), law)
    end, tolerance, method = _end(end), _tolerance(tolerance), _text("method", method)
    callback, bar = _progress_callback(progress, z.size)
    try:
        return _core.eps_array(z, end, tolerance, method, law, workers, callback)
    finally:
        if bar is not None:
            bar.close()


def _check_progress(progress):
    if not (progress is None or isinstance(progress, bool) or callable(progress)):
        raise TypeError(f"progress must be None, True, False or a callable(done, total), got {type(progress).__name__}")


def _progress_callback(progress, total):
    """(callable(done, total) or None, the tqdm bar to close or None) for eps_array's progress."""
    if progress is None or progress is False:
        return None, None
    if progress is not True:
        return progress, None
    try:
        from tqdm import tqdm
    except ImportError:
        _warnings.warn("progress=True shows a tqdm bar, but tqdm is not installed (pip install tqdm, or Debian's "
                       "python3-tqdm); computing without one", stacklevel=3)
        return None, None
    bar = tqdm(total=total, unit="solve")
    return (lambda done, _total: bar.update(done - bar.n)), bar


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
    tolerance = _scalar(tolerance)
    if isinstance(tolerance, bool) or not isinstance(tolerance, _numbers.Real):
        raise TypeError(f"tolerance must be a real number, got {type(tolerance).__name__}")
    return float(tolerance)


def solve(zeta=None, end="both", tolerance=_TOLERANCE, method="auto", trajectory=False, *, beta=None,
          velocity=None, material=None, law="viscoelastic-hertz"):
    """One collision in full.

    Parameters
    ----------
    zeta : float, optional
        As for eps(), scalar only; or beta with velocity, or material with velocity.
    end : {"both", "naive", "delayed-recovery"}
        The ends to compute. With "both" (the default) each end is solved as eps() solves it (two
        integrations), so that solve(z).naive.eps == eps(z, end="naive") and
        solve(z).delayed_recovery.eps == eps(z) to the last digit.
    tolerance, method, law
        As for eps().
    trajectory : bool
        Record (tau, x, x', x'') at every internal step and event.
    beta, velocity, material
        As for eps(), scalars only.

    Returns
    -------
    CollisionResult
        In natural units: .naive and .delayed_recovery (EndResult: eps, one_minus_eps, tau, x, velocity,
        dissipated_energy; None for an end not asked for), .max_compression (tau, x), .stats (steps,
        rhs_evaluations, ...; with end="both" the sum of both integrations), .method (the one used; with
        end="both" that of the naive end's integration, which runs through the whole collision), .zeta,
        .law (.zeta is the damping ratio r for the dash-pot), .tolerance; with trajectory=True the numpy
        arrays .tau, .x, .velocity (x') and .acceleration (x'').

    Raises
    ------
    ValueError, TypeError, NumericalFailure
        As eps() does.

    Examples
    --------
    >>> import restitution
    >>> r = restitution.solve(1.0)
    >>> round(r.naive.eps, 10), round(r.delayed_recovery.eps, 10)
    (0.3311648105, 0.3939306032)
    >>> round(r.max_compression.x, 8)
    0.7674808
    >>> restitution.solve(1.0, end="naive").delayed_recovery is None
    True
    """
    law = _law(law, zeta, beta, material)
    if not isinstance(trajectory, bool):
        raise TypeError(f"trajectory must be True or False, got {type(trajectory).__name__}")
    z = zeta_of(zeta, beta=beta, velocity=velocity, material=material)
    if not isinstance(z, float):
        raise TypeError("solve() takes one collision: zeta (or beta, velocity) must be scalars; use eps() for arrays")
    return _core.solve(z, _end(end), _tolerance(tolerance), _text("method", method), bool(trajectory), law)


def calibrate(eps, velocity, end="delayed-recovery", material=None, tolerance=_TOLERANCE, method="auto", *,
              law="viscoelastic-hertz"):
    """The damping that gives a measured eps in (0, 1) at the impact speed velocity [m/s].

    Parameters
    ----------
    eps : float
        The measured coefficient of restitution, in (0, 1).
    velocity : float
        The impact speed [m/s].
    end : {"delayed-recovery", "naive"}
        As for eps().
    material : Material, optional
        Its elastic data (its dissipation is not needed) give the dissipative constant A [s].
    tolerance, method, law
        As for eps().

    Returns
    -------
    Calibration
        .zeta (natural units), .beta [s^(1/5) m^(-1/5)], .characteristic_velocity_m_s (the 1999 paper's g*
        [m/s]), .dissipative_constant_s (A [s] for the material's elastic data, else None), .eps_at_zeta,
        .solves, named as the JSON keys of `restitution calibrate --json` (the names without _m_s and _s
        still work until 0.5.0, with a DeprecationWarning). For another law than viscoelastic Hertz .zeta (and
        .parameter, the dash-pot's r) is the result and .beta, .characteristic_velocity_m_s are None (no
        material).

    Raises
    ------
    ValueError
        eps outside (0, 1) or below eps(zeta = 1e6) (the checked range).

    Examples
    --------
    >>> import restitution
    >>> c = restitution.calibrate(0.8, 1.0)            # eps = 0.8 at 1 m/s
    >>> round(c.beta, 8), round(c.eps_at_zeta, 8)
    (0.20113666, 0.8)
    """
    law = _law(law, material=material)
    if material is not None and not isinstance(material, Material):
        raise TypeError(f"material must be a restitution.Material, got {type(material).__name__}")
    eps, velocity = _scalar(eps), _scalar(velocity)
    for name, value in (("eps", eps), ("velocity", velocity)):
        if isinstance(value, bool) or not isinstance(value, _numbers.Real):
            raise TypeError(f"{name} must be a real number, got {type(value).__name__}")
    return _core.calibrate(float(eps), float(velocity), _end(end), _tolerance(tolerance),
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
    [s^(1/5) m^(-1/5)]), Tsuji ("zeta") and the linear dash-pot ("damping-ratio") at speed_independent_end.

    Parameters
    ----------
    v : array_like
        Impact speeds [m/s], one per measurement.
    eps : array_like
        Measured coefficients of restitution, in (0, 1).
    sigma : array_like, optional
        Their standard deviations; without them the scatter is estimated from the residuals.
    laws : str or sequence of str, optional
        Restricts the candidates (names as restitution's law names).
    speed_independent_end : {"delayed-recovery", "naive"}
        The end of the speed-independent candidates.
    material : Material, optional
        Its elastic data give the Hertz fits' dissipative constant A [s].
    tolerance, method
        As for eps().

    Returns
    -------
    dict
        The keys of `restitution fit-data --json` (docs/fit.md): "fits" (one dict per law: "value", "ci68",
        "ci95" as [low, high] from the profile of chi2, a bound at the edge of the checked range being None,
        "chi2_per_dof", "aic", "converged", "residual_tests", ...), "best" (index of the lowest AIC),
        "sigma_estimated" (True without sigma: the intervals use t quantiles). With a Material, the Hertz
        fits carry "dissipative_constant_s" (A [s]) with its intervals.

    Raises
    ------
    ValueError
        Bad data (eps outside (0, 1), v <= 0, sigma outside [1e-100, 1e100], NaN, too few points, an array of
        more than one dimension) or a law that is not a candidate.

    Examples
    --------
    >>> import restitution
    >>> fit = restitution.fit_data([0.5, 1.0, 2.0, 4.0], [0.90, 0.88, 0.86, 0.83])
    >>> best = fit["fits"][fit["best"]]
    >>> best["law"], best["end"], round(best["value"], 3)
    ('viscoelastic-hertz', 'naive', 0.116)
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


def build_info():
    """Which build of restitution and of SUNDIALS this module runs.

    A CVODE solve costs 2-3x more on Debian's unoptimized SUNDIALS than on the optimized build the project
    makes (scripts/sundials in a checkout, the CVODE source bundled in the sdist for pip); the numbers are the
    same. Configure says which one it links, in one line; this tells which one a module runs.

    Returns
    -------
    dict
        {"version": restitution's version, "sundials": {"version": str, "optimized": bool,
        "description": str}}, as `restitution --version` and the command line's JSON outputs say it.

    Examples
    --------
    >>> import restitution
    >>> info = restitution.build_info()
    >>> info["version"] == restitution.__version__, sorted(info["sundials"])
    (True, ['description', 'optimized', 'version'])
    """
    return _core.build_info()


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
    return _core.sweep_to_file(z.tolist(), _os.fspath(path), bool(resume), _end(end), _tolerance(tolerance),
                               _text("method", method), _threads(threads), _law(law), stop)


__all__.append("sweep_to_file")


def _optional_real(name, value):
    value = _scalar(value)
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, _numbers.Real):
        raise TypeError(f"{name} must be a real number or None, got {type(value).__name__}")
    return float(value)


def gas(*, radius=None, density=None, mass=None, eps=None, velocity=None, dissipative_constant=None,
        young_modulus=None, poisson_ratio=None, law="viscoelastic-hertz", end="delayed-recovery",
        packing_fraction=None, rms_speed=None, temperature=None, duration=None, haff_times=None, first_time=0.0,
        points_per_decade=20, a2=None, collision_rate_factor=1.0, tolerance=_TOLERANCE, thermostat=None,
        bath_temperature=None, bath_time=None, power=None):
    """The freely cooling granular gas of these spheres in its homogeneous cooling state (docs/gas.md), as
    `restitution gas` computes it: T(t) from the kinetic theory with the law's exact eps(v), beside Haff's law.

    Parameters
    ----------
    radius : float
        Sphere radius R [m]; with density [kg/m^3] or mass [kg] (exactly one).
    density, mass : float, optional
    eps, velocity : float, optional
        The law calibrated so that eps holds at the impact speed velocity [m/s]; or instead
    dissipative_constant : float, optional
        A [s] of viscoelastic Hertz, with the material's young_modulus [Pa] and poisson_ratio.
    young_modulus, poisson_ratio : float, optional
    law : str
        Any member of the contact-law family (restitution's law names).
    end : {"delayed-recovery", "naive"}
    packing_fraction : float
        phi in (0, 0.5), such that Haff's tau0 lies in [1e-300, 1e300] s (else a ValueError names the packing
        fractions that work for the other arguments).
    rms_speed, temperature : float
        Exactly one: the initial rms speed per direction [m/s] (T0 = m v^2), or T0 = m<v^2>/3 [J].
    duration, haff_times : float
        Exactly one: the span of time [s], or in Haff times tau0.
    first_time : float
        First time of the log-spaced grid [s]; 0: six decades below the end.
    points_per_decade : int
        Points of the time grid per decade, in [1, 1000].
    a2 : float, "haff" or "evolving", optional
        The first Sonine coefficient, held constant; "haff": van Noije & Ernst's of the Haff eps; "evolving":
        a2(t) from the Sonine moment equations, starting Maxwellian (the result's "a2" is then an array of the
        curve); None: Maxwellian.
    collision_rate_factor : float
        A factor on Enskog's collision rate.
    tolerance : float
        Accuracy of each eps solve of a law without a fast table, and of the calibration: in [1e-11, 1e-2] for
        every law.
    thermostat : {"langevin", "white-noise"}, optional
        The driven gas (docs/gas.md, "The driven gas"): a Langevin bath (LAMMPS's fix langevin) of
        bath_temperature T_b [J, energy units like temperature] and drag time bath_time tau_b [s], or white
        noise putting in power [W] per sphere. The curve is then the relaxation from T0 to the steady state.
    bath_temperature, bath_time, power : float, optional

    Returns
    -------
    dict
        The keys of `restitution gas --json`: "law" (a dict: "kind", "end", "zeta_at_reference",
        "reference_speed_m_s"), "mass_kg", "diameter_m", "packing_fraction", "contact_correlation" (g2),
        "number_density_m3", "initial_temperature_j", "tau0_s", "haff_eps", "a2", "collision_rate_factor",
        "duration_s", and the curve as numpy arrays: "time_s", "temperature_j", "haff_temperature_j",
        "local_exponent", "cooling_rate_hz", "collision_frequency_hz", "collisions_per_particle",
        "effective_eps" (and "a2" with a2="evolving"). With a thermostat also "thermostat" (a dict: "kind" and
        "bath_temperature_j", "bath_time_s" or "power_w"), "steady_temperature_j", "steady_a2",
        "relaxation_time_s", "driving_exponent" (d ln T_s / d ln T_b or P), "constant_eps_driving_exponent",
        "steady_effective_eps", "steady_collision_frequency_hz" and "steady_power_w".

    Raises
    ------
    ValueError
        A missing, extra or bad argument, named (packing_fraction outside (0, 0.5), both duration and
        haff_times, ...).

    Examples
    --------
    >>> import restitution
    >>> g = restitution.gas(radius=0.005, density=920.0, eps=0.8, velocity=2.0, packing_fraction=0.1,
    ...                     rms_speed=1.0, haff_times=1000)
    >>> round(g["tau0_s"], 6), round(g["haff_eps"], 4), g["time_s"].shape
    (0.091387, 0.7924, (121,))
    >>> round(g["local_exponent"][-1], 2)   # Haff's law: -2; viscoelastic spheres tend to -5/3
    -1.69
    """
    return _core.gas(_gas_arguments(locals()))


def _gas_arguments(given):
    """restitution.gas's arguments checked by type, read through the gas study's table (_core.gas_parameters:
    name, kind, unit and whether a scene takes it from the material; the signature, the docstring and the .pyi
    list the same names, a test compares them)."""
    arguments = {}
    for name, kind, *_ in _core.gas_parameters:
        value = given[name]
        if kind == "optional number" or (kind == "number" and name != "tolerance"):
            arguments[name] = _optional_real(name, value)
        elif kind == "number":
            arguments[name] = _tolerance(value)
        elif kind == "whole number":
            if isinstance(value, bool) or not isinstance(value, _numbers.Integral):
                raise TypeError(f"{name} must be an int, got {type(value).__name__}")
            arguments[name] = int(value)
        elif kind == "number or word":
            arguments[name] = value if value is None or isinstance(value, str) else _optional_real(name, value)
        elif value is not None or kind == "word":
            arguments[name] = _end(value) if name == "end" else _text(name, value)
    required = [name for name, kind, *_ in _core.gas_parameters if kind == "number" and name != "tolerance"]
    if any(arguments[name] is None for name in required):
        raise TypeError(f"{' and '.join(required)} must be real numbers")
    return arguments


__all__.append("gas")

from ._oblique import ObliqueResult, oblique  # noqa: E402 (it uses the helpers above)

__all__ += ["oblique", "ObliqueResult"]

from ._adhesion import AdhesiveCollision, adhesive_closed_forms, adhesive_collision, sticking_speed  # noqa: E402 (it uses the helpers above)

__all__ += ["adhesive_collision", "sticking_speed", "adhesive_closed_forms", "AdhesiveCollision"]
