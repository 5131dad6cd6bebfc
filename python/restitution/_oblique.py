# SPDX-License-Identifier: BSD-3-Clause
"""restitution.oblique: oblique impacts with a LAMMPS tangential model (docs/oblique.md), the arguments of
`restitution oblique` as keywords; array angles and spins broadcast and give arrays."""

import textwrap as _textwrap
import warnings as _warnings

import numpy as _np

from . import _restitution as _core
from . import _end, _optional_real, _real_array, _text, Material
from ._renamed import add_old_names

# The outputs in the order the repr shows them: attribute, unit (as the repr writes it), what it is.
_FIELDS = (
    ("angle_deg", "deg", "impact angle from the normal, as given"),
    ("initial_spin_rad_s", "rad/s", "spin of the (first) sphere before contact, as given"),
    ("normal_restitution", "", "eps = -v_n'/v_n"),
    ("tangential_restitution", "", "e_t = -s'/s at the contact point (-1: s unchanged; NaN where s = 0)"),
    ("rebound_angle", "rad", "atan2(u', eps v_n): the centre's velocity after contact, from the normal"),
    ("rebound_angle_deg", "deg", "the rebound angle in degrees"),
    ("impact_angle", "rad", "atan2(u, v_n) before contact"),
    ("spin_rad_s", "rad/s", "spin of the (first) sphere after contact"),
    ("spin2_rad_s", "rad/s", "spin of the second sphere after contact (0 on a wall)"),
    ("slip_velocity", "m/s", "s' of the contact point after contact"),
    ("tangential_velocity", "m/s", "u' of the first centre relative to the second after contact"),
    ("normal_velocity", "m/s", "separation speed eps v_n"),
    ("impulse_ratio", "", "J_t/J_n, tangential over normal impulse (-mu for a slide throughout)"),
    ("line_of_centres_turn", "rad", "how far a pair's line of centres turned during the contact"),
    ("contact_time_s", "s", "duration of the contact"),
    ("stick_time_s", "s", "time below the Coulomb cap"),
    ("slip_time_s", "s", "time at the cap"),
    ("psi_in", "", "Maw, Barber & Fawcett's psi_1 = 2(1 - nu)/(mu(2 - nu)) s/v_n (NaN without friction)"),
    ("psi_out", "", "psi_2 of the outgoing slip over the same v_n"),
)


class ObliqueResult:
    """The outcome of oblique impacts (restitution.oblique): floats for one impact, float64 arrays of the
    broadcast shape of angle and spin for several.

    Attributes (SI units; angles in rad unless named _deg; named as the JSON of `restitution oblique --json`
    where it has them): angle_deg, initial_spin_rad_s, normal_restitution, tangential_restitution,
    rebound_angle [rad], rebound_angle_deg, impact_angle [rad], spin_rad_s, spin2_rad_s, slip_velocity,
    tangential_velocity, normal_velocity [m/s], impulse_ratio, line_of_centres_turn [rad], contact_time_s,
    stick_time_s, slip_time_s, psi_in, psi_out; dissipative_constant_s; switch_times [s]
    (per impact the times of the mode switches, the first 0) and modes (per impact "stick"/"slip" from each of
    them) as arrays, or for several impacts object arrays of them; tangential_model and maw_chi (chi of Maw's
    diagram: the gross-slip line is psi_2 = psi_1 - 2(1 + eps) chi). The names without the unit suffix
    (initial_spin, spin, spin2, contact_time, stick_time, slip_time, dissipative_constant) still work until
    0.5.0, with a DeprecationWarning.
    """

    def __init__(self, **values):
        self.__dict__.update(values)

    def __eq__(self, other):
        if not isinstance(other, ObliqueResult) or self.__dict__.keys() != other.__dict__.keys():
            return NotImplemented
        return all(_same(self.__dict__[k], other.__dict__[k]) for k in self.__dict__)

    __hash__ = None  # mutable arrays inside

    def __repr__(self):
        parts = [f"tangential_model={self.tangential_model!r}"]
        for name, unit, _ in _FIELDS:
            value = getattr(self, name)
            text = _np.array2string(value, precision=6) if isinstance(value, _np.ndarray) else f"{value:.6g}"
            parts.append(f"{name}={text}" + (f" {unit}" if unit else ""))
        if isinstance(self.angle_deg, float):
            parts.append("modes=" + ", ".join(f"{m} from {t:.4g} s" for m, t in zip(self.modes, self.switch_times)))
        return "ObliqueResult(" + ", ".join(parts) + ")"


# The names before the JSON's (issue 44, item 13), kept until 0.5.0.
add_old_names(ObliqueResult, (("initial_spin", "initial_spin_rad_s"), ("spin", "spin_rad_s"), ("spin2", "spin2_rad_s"),
                              ("contact_time", "contact_time_s"), ("stick_time", "stick_time_s"),
                              ("slip_time", "slip_time_s"), ("dissipative_constant", "dissipative_constant_s")))


def _same(a, b):
    if isinstance(a, _np.ndarray) and a.dtype == object:
        return a.shape == b.shape and all(_same(x, y) for x, y in zip(a.ravel(), b.ravel()))
    if isinstance(a, (_np.ndarray, float)):
        return bool(_np.array_equal(a, b, equal_nan=True))
    return a == b


def oblique(*, material, friction, angle, spin=0.0, impact_velocity=1.0, tangential="mindlin",
            tangential_stiffness=None, tangential_damping=0.0, wall=False, fixed_normal=False,
            end="delayed-recovery", torque_arm="lammps", tolerance=_core.default_tolerance, eps=None,
            velocity=None, wall_young_modulus=None, wall_poisson_ratio=None, law="viscoelastic-hertz", speed=None):
    """Oblique impacts of two spheres of one material, or of a sphere on a wall, with a tangential model
    as Debian's LAMMPS writes it in `pair granular` (docs/oblique.md), as `restitution oblique` computes them.

    Parameters
    ----------
    material : Material
        Young's modulus, Poisson's ratio, radius (or radii), density or masses, and its dissipation (A, 0 for
        an elastic contact, or the viscosities), unless eps and velocity are given: one of the two is required.
    eps, velocity : float, optional
        Instead of the material's dissipation: eps measured head-on at velocity [m/s] on this contact (sphere
        and sphere, or sphere and wall); A is calibrated from them.
    law : {"viscoelastic-hertz", "tsuji-hertz", "hertz-constant-damping"}
        The normal law, with the material's Hertz stiffness; the last two are damped by eps and velocity (or
        elastic with the material's A = 0). Not with tangential="liggghts_history".
    friction : float
        Coulomb's mu >= 0.
    angle : float or array_like
        Impact angle(s) from the normal in degrees, in [0, 90).
    spin : float or array_like
        Spin of the (first) sphere before contact [rad/s], positive adding to the slip; broadcast with angle.
    impact_velocity : float
        Impact speed [m/s]: v cos(angle) normal, v sin(angle) tangential (`restitution oblique
        --impact-velocity`). The old name speed still works, with a DeprecationWarning, until 0.5.0.
    tangential : {TANGENTIAL_MODELS}
    tangential_stiffness : float, optional
        k_t [N/m] of linear_history (required there when friction > 0), [N/m^2] of the mindlin models
        (default LAMMPS's NULL, 8 G*).
    tangential_damping : float
        LAMMPS's tangential damping factor, times the normal damping coefficient.
    wall : bool
        A sphere on a flat wall instead of two spheres: rigid, as `restitution dem --wall`, unless
        wall_young_modulus [Pa] and wall_poisson_ratio give its material (both or neither).
    wall_young_modulus, wall_poisson_ratio : float, optional
        The wall's Young's modulus [Pa] and Poisson ratio (both or neither; default: a rigid wall).
    fixed_normal : bool
        Two spheres: keep the impact's normal instead of letting the line of centres turn as LAMMPS's pair does.
    end : {"delayed-recovery", "naive"}
    torque_arm : {"lammps", "radius", "radius-minus-half-overlap"}
    tolerance : float
        The accuracy contract, in [1e-10, 1e-2): eps and e_t within it, the rebound angle within it in rad, the
        spins within it times max(|spin|, v/R). An impact near the stick/slip boundary, where that cannot be
        shown, gives a RuntimeWarning that says why (docs/oblique.md, "Accuracy and cost").

    Returns
    -------
    ObliqueResult
        Floats for scalar angle and spin, float64 arrays of their broadcast shape otherwise: e_t, eps, the
        rebound angle in rad and deg, the spins in rad/s, the impulse ratio, contact, stick and slip times in s,
        the switch times and modes, Maw's psi, named as the JSON keys of `restitution oblique --json`. An
        impact whose solve failed has NaN outputs, its reason in failure (a RuntimeWarning says it); the
        others are kept.

    Raises
    ------
    ValueError
        A missing or bad argument, named (friction, angle, spin, tangential_stiffness, ...).

    Examples
    --------
    >>> import restitution
    >>> steel = restitution.Material(young_modulus=2e11, poisson_ratio=0.3, radius=1e-3, density=7800.0,
    ...                              dissipative_constant=0.0)  # elastic
    >>> r = restitution.oblique(material=steel, friction=0.3, angle=80.0, wall=True, tangential="mindlin")
    >>> r.modes, round(r.impulse_ratio, 12)            # grazing: slides throughout, J_t/J_n = -mu
    (('slip',), -0.3)
    >>> round(r.rebound_angle_deg, 4), round(r.spin_rad_s, 2)  # deg, rad/s
    (78.845, -260.47)
    >>> restitution.oblique(material=steel, friction=0.3, angle=[10.0, 80.0], wall=True,
    ...                     tangential="mindlin").tangential_restitution.round(4)
    array([-0.9463, -0.6297])
    """
    if not isinstance(material, Material):
        raise TypeError(f"material must be a restitution.Material, got {type(material).__name__}")
    if speed is not None:
        _warnings.warn("oblique(speed=...) is deprecated and will be removed in 0.5.0; use "
                       "impact_velocity=...", DeprecationWarning, stacklevel=2)
        impact_velocity = speed
    angles, spins = _np.broadcast_arrays(_real_array("angle", angle), _real_array("spin", spin))
    for name, flag in (("wall", wall), ("fixed_normal", fixed_normal)):
        if not isinstance(flag, bool):
            raise TypeError(f"{name} must be a bool, got {type(flag).__name__}")
    numbers = {name: _optional_real(name, value) for name, value in (
        ("friction", friction), ("impact_velocity", impact_velocity), ("tangential_damping", tangential_damping),
        ("tolerance", tolerance))}
    for name in ("impact_velocity", "tangential_damping", "tolerance"):
        if numbers[name] is None:
            raise TypeError(f"{name} must be a real number")
    # By the names of the study's table (_core.oblique_parameters), as the command's options and a scene's keys.
    columns = _core.oblique_impacts(material, angles.ravel().tolist(), spins.ravel().tolist(), {
        "friction": numbers["friction"], "tangential": _text("tangential", tangential),
        "tangential_stiffness": _optional_real("tangential_stiffness", tangential_stiffness),
        "tangential_damping": numbers["tangential_damping"], "impact_velocity": numbers["impact_velocity"],
        "wall": wall, "fixed_normal": fixed_normal, "end": _end(end), "torque_arm": _text("torque_arm", torque_arm),
        "tolerance": numbers["tolerance"], "eps": _optional_real("eps", eps),
        "velocity": _optional_real("velocity", velocity),
        "wall_young_modulus": _optional_real("wall_young_modulus", wall_young_modulus),
        "wall_poisson_ratio": _optional_real("wall_poisson_ratio", wall_poisson_ratio), "law": _text("law", law)})
    for angle_deg, spin_rad_s, why in zip(angles.ravel(), spins.ravel(), columns["failure"]):
        if why:  # never silently: this impact was not solved, its outputs are NaN
            _warnings.warn(f"oblique impact at {angle_deg:g} deg, spin {spin_rad_s:g} rad/s not solved: {why}",
                           RuntimeWarning, stacklevel=2)
    for angle_deg, spin_rad_s, why in zip(angles.ravel(), spins.ravel(), columns["ill_conditioned"]):
        if why:  # never silently: the outputs of this impact are not shown to be within the tolerance
            _warnings.warn(f"oblique impact at {angle_deg:g} deg, spin {spin_rad_s:g} rad/s: {why}", RuntimeWarning,
                           stacklevel=2)
    shape = angles.shape
    values = {"tangential_model": columns["tangential_model"], "maw_chi": columns["maw_chi"],
              "rigid_wall": columns["rigid_wall"], "dissipative_constant_s": columns["dissipative_constant_s"]}
    columns["rebound_angle_deg"] = _np.degrees(columns["rebound_angle"])
    for name, _, _ in _FIELDS:
        values[name] = float(columns[name][0]) if shape == () else columns[name].reshape(shape)
    values["failure"] = columns["failure"][0] if shape == () else _np.array(columns["failure"], dtype=object).reshape(shape)
    if shape == ():
        values["switch_times"] = columns["switch_times"][0]
        values["modes"] = columns["modes"][0]
    else:
        for name in ("switch_times", "modes"):
            cells = _np.empty(len(columns[name]), dtype=object)
            cells[:] = columns[name]
            values[name] = cells.reshape(shape)
    return ObliqueResult(**values)


def _set_of(names, column):
    """The names as a numpydoc set's items that start at `column`, wrapped there within 116 columns."""
    quoted = ", ".join(f'"{name}"' for name in names)
    return _textwrap.fill(quoted, width=116, initial_indent=" " * column, subsequent_indent=" " * column,
                          break_on_hyphens=False, break_long_words=False)[column:]


# The models are the library's table (src/oblique/tangential_models.cpp), not a copy typed here.
oblique.__doc__ = oblique.__doc__.replace("{TANGENTIAL_MODELS}", "{" + _set_of(_core.oblique_tangential_names, 18) + "}")
