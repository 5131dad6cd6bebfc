# SPDX-License-Identifier: BSD-3-Clause
"""restitution.adhesive_collision and restitution.sticking_speed: adhesive collisions of two spheres of a Material
(docs/adhesion.md), as `restitution eps --adhesion MODEL --surface-energy GAMMA --velocity V` (sjkr:
`--cohesion-energy-density K`) computes them."""

from . import _restitution as _core
from . import _optional_real, _text, _tolerance, _TOLERANCE, Material
from ._restitution import AdhesiveCollision

_MODELS = tuple(_core.adhesive_model_names)


def _arguments(material, adhesion, surface_energy, cohesion_energy_density, dissipative_constant):
    if not isinstance(material, Material):
        raise TypeError(f"material must be a restitution.Material, got {type(material).__name__}")
    if _text("adhesion", adhesion) not in _MODELS:
        raise ValueError(f"adhesion must be one of {', '.join(_MODELS)}, got '{adhesion}'")
    gamma = _optional_real("surface_energy", surface_energy)
    k_c = _optional_real("cohesion_energy_density", cohesion_energy_density)
    if adhesion == "sjkr" and k_c is None:
        raise TypeError("adhesion='sjkr' needs cohesion_energy_density (LIGGGHTS's k_c, J/m^3)")
    if adhesion != "sjkr" and gamma is None:
        raise TypeError("surface_energy (gamma per surface, J/m^2) is required")
    return dict(material=material, adhesion=adhesion, surface_energy=gamma, cohesion_energy_density=k_c,
                dissipative_constant=_optional_real("dissipative_constant", dissipative_constant))


def adhesive_collision(velocity, *, material, adhesion="jkr", surface_energy=None, cohesion_energy_density=None,
                       dissipative_constant=None, tolerance=_TOLERANCE):
    """One adhesive collision of two spheres of the material at the impact speed (docs/adhesion.md).

    Parameters
    ----------
    velocity : float
        Impact speed v > 0 [m/s].
    material : Material
        The spheres (young_modulus Y [Pa]: E* = Y/(2(1 - nu^2)) is built from it, radius, density or mass).
    adhesion : {"jkr", "jkr-lammps", "dmt", "sjkr"}
        jkr: textbook JKR, viscoelastic dissipation A dδ/dt dF_el/dδ, broken where dδ/da = 0; jkr-lammps: JKR as
        LAMMPS 20220106 codes it (damping viscoelastic, dropped at the force-controlled pull-off); dmt: LAMMPS's DMT;
        sjkr: LIGGGHTS 3.8.0's cohesion sjkr on Hertz (docs/adhesion.md §10).
    surface_energy : float
        gamma of one surface [J/m^2] (work of adhesion w = 2 gamma, pull-off force 3 pi gamma R_eff); required for
        jkr, jkr-lammps and dmt, refused for sjkr.
    cohesion_energy_density : float
        sjkr only (and required there): LIGGGHTS's cohesionEnergyDensity k_c [J/m^3], the force -k_c times the area
        of the spheres' intersection circle while they overlap (`eps --adhesion sjkr --cohesion-energy-density`).
    dissipative_constant : float, optional
        A [s]; jkr-lammps and dmt use LAMMPS's damp = 2 A E*/m_eff, sjkr LIGGGHTS's gamman = 2 A E*/m_eff. None:
        the Material's dissipation when it has one, else elastic (A = 0).
    tolerance : float
        Relative accuracy, in [1e-12, 1e-2].

    Returns
    -------
    AdhesiveCollision
        adhesion, velocity_m_per_s, outcome ("bounced" or "stuck"), eps (0 when stuck), one_minus_eps,
        contact_time_s, max_compression_m, hysteresis_work_j, viscous_work_j, kinetic_to_adhesion_energy, stats:
        the fields of `restitution eps --adhesion ... --json`.

    Examples
    --------
    >>> import restitution
    >>> ice = restitution.Material(young_modulus=7e9, poisson_ratio=0.25, radius=1.5e-6, density=920.0)
    >>> r = restitution.adhesive_collision(2.0, material=ice, adhesion="jkr", surface_energy=0.19)
    >>> r.outcome, round(r.eps, 6)
    ('bounced', 0.831978)
    """
    speed = _optional_real("velocity", velocity)
    if speed is None:
        raise TypeError("velocity (the impact speed, m/s) is required")
    return _core.adhesive_collision(velocity=speed, tolerance=_tolerance(tolerance),
                                    **_arguments(material, adhesion, surface_energy, cohesion_energy_density,
                                                 dissipative_constant))


def sticking_speed(*, material, adhesion="jkr", surface_energy=None, cohesion_energy_density=None,
                   dissipative_constant=None, tolerance=_TOLERANCE):
    """The impact speed v_s [m/s] below which two spheres of the material stick (0.0: they never do, as undamped
    DMT and sjkr), to the relative tolerance; the arguments as restitution.adhesive_collision's.

    Examples
    --------
    >>> import restitution
    >>> ice = restitution.Material(young_modulus=7e9, poisson_ratio=0.25, radius=1.5e-6, density=920.0)
    >>> round(restitution.sticking_speed(material=ice, surface_energy=0.19), 6)
    1.109618
    """
    return _core.sticking_speed(tolerance=_tolerance(tolerance),
                                **_arguments(material, adhesion, surface_energy, cohesion_energy_density,
                                             dissipative_constant))


def adhesive_closed_forms(*, material, adhesion="jkr", surface_energy=None, cohesion_energy_density=None):
    """The elastic model's closed forms (docs/adhesion.md §2-3) as a dict: "break_overlap_m" (negative for JKR, 0 for
    DMT and sjkr), "elastic_hysteresis_work_j" W (the undamped v_s is sqrt(2W/m*)), "pull_off_force_n" F_c = 3 pi
    gamma R_eff (not for sjkr) and "effective_modulus_pa" E*; the arguments as restitution.adhesive_collision's."""
    arguments = _arguments(material, adhesion, surface_energy, cohesion_energy_density, None)
    del arguments["dissipative_constant"]
    return _core.adhesive_closed_forms(**arguments)
