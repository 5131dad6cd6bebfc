# SPDX-License-Identifier: BSD-3-Clause
# Type stubs of restitution.adhesive_collision, restitution.sticking_speed and their result (SI units).
from typing import Any, Dict, Literal, Optional, Union

import numpy as np

from . import Material, SolverStats

_Real = Union[float, np.floating[Any], np.integer[Any]]
Adhesion = Literal["jkr-lammps", "jkr", "dmt", "sjkr"]
Outcome = Literal["bounced", "stuck"]

class AdhesiveCollision:
    @property
    def adhesion(self) -> Adhesion: ...
    @property
    def velocity_m_per_s(self) -> float: ...
    @property
    def outcome(self) -> Outcome: ...
    @property
    def eps(self) -> float: ...  # 0 when stuck
    @property
    def one_minus_eps(self) -> float: ...
    @property
    def contact_time_s(self) -> float: ...
    @property
    def max_compression_m(self) -> float: ...
    @property
    def hysteresis_work_j(self) -> float: ...
    @property
    def viscous_work_j(self) -> float: ...
    @property
    def kinetic_to_adhesion_energy(self) -> float: ...
    @property
    def stats(self) -> SolverStats: ...

def adhesive_collision(
    velocity: _Real,  # m/s
    *,
    material: Material,
    adhesion: Adhesion = ...,
    surface_energy: Optional[_Real] = ...,  # J/m^2, per surface (jkr-lammps, jkr, dmt)
    cohesion_energy_density: Optional[_Real] = ...,  # J/m^3, LIGGGHTS's k_c (sjkr)
    dissipative_constant: Optional[_Real] = ...,  # A, s
    tolerance: _Real = ...,
) -> AdhesiveCollision: ...
def sticking_speed(
    *,
    material: Material,
    adhesion: Adhesion = ...,
    surface_energy: Optional[_Real] = ...,  # J/m^2, per surface (jkr-lammps, jkr, dmt)
    cohesion_energy_density: Optional[_Real] = ...,  # J/m^3, LIGGGHTS's k_c (sjkr)
    dissipative_constant: Optional[_Real] = ...,  # A, s
    tolerance: _Real = ...,
) -> float: ...  # m/s
def adhesive_closed_forms(
    *,
    material: Material,
    adhesion: Adhesion = ...,
    surface_energy: Optional[_Real] = ...,  # J/m^2, per surface (jkr-lammps, jkr, dmt)
    cohesion_energy_density: Optional[_Real] = ...,  # J/m^3, LIGGGHTS's k_c (sjkr)
) -> Dict[str, float]: ...
