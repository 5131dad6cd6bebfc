# SPDX-License-Identifier: BSD-3-Clause
# Type stubs of restitution.oblique and its result: floats for scalar angle and spin, float64 arrays otherwise.
from typing import Any, Generic, Literal, Optional, Sequence, Tuple, TypeVar, Union, overload

import numpy as np
import numpy.typing as npt

from . import Material

_Real = Union[float, np.floating[Any], np.integer[Any]]
_Array = Union[npt.NDArray[Any], Sequence[float], Sequence[Sequence[float]]]
_Value = TypeVar("_Value", float, npt.NDArray[np.float64], covariant=True)
Tangential = Literal["linear_nohistory", "linear_history", "mindlin", "liggghts_history", "mindlin_rescale",
                     "mindlin/force", "mindlin_rescale/force"]
TorqueArm = Literal["lammps", "radius", "radius-minus-half-overlap"]

class ObliqueResult(Generic[_Value]):
    tangential_model: Tangential
    maw_chi: float
    rigid_wall: bool
    dissipative_constant_s: float  # given or calibrated
    failure: Any  # why an impact was not solved ("" where it was); an object array for several
    angle_deg: _Value  # deg
    initial_spin_rad_s: _Value
    normal_restitution: _Value
    tangential_restitution: _Value
    rebound_angle: _Value  # rad
    rebound_angle_deg: _Value  # deg
    impact_angle: _Value  # rad
    spin_rad_s: _Value
    spin2_rad_s: _Value
    slip_velocity: _Value  # m/s
    tangential_velocity: _Value  # m/s
    normal_velocity: _Value  # m/s
    impulse_ratio: _Value
    line_of_centres_turn: _Value  # rad
    contact_time_s: _Value
    stick_time_s: _Value
    slip_time_s: _Value
    psi_in: _Value
    psi_out: _Value
    # The names before the JSON's, until 0.5.0 (a DeprecationWarning).
    @property
    def initial_spin(self) -> _Value: ...
    @property
    def spin(self) -> _Value: ...
    @property
    def spin2(self) -> _Value: ...
    @property
    def contact_time(self) -> _Value: ...
    @property
    def stick_time(self) -> _Value: ...
    @property
    def slip_time(self) -> _Value: ...
    @property
    def dissipative_constant(self) -> float: ...
    # One impact: the switch times (s) as an array and the modes as a tuple; several: object arrays of them.
    switch_times: Any
    modes: Any

@overload
def oblique(
    *,
    material: Material,
    friction: Optional[float],
    angle: _Real,  # deg
    spin: _Real = ...,  # rad/s
    impact_velocity: float = ...,  # m/s
    tangential: Tangential = ...,
    tangential_stiffness: Optional[float] = ...,  # N/m, N/m^2 for mindlin
    tangential_damping: float = ...,
    wall: bool = ...,
    fixed_normal: bool = ...,
    end: Literal["naive", "delayed-recovery", "delayed_recovery"] = ...,
    torque_arm: TorqueArm = ...,
    tolerance: float = ...,
    eps: Optional[float] = ...,
    velocity: Optional[float] = ...,  # m/s
    wall_young_modulus: Optional[float] = ...,  # Pa
    wall_poisson_ratio: Optional[float] = ...,
    law: Literal["viscoelastic-hertz", "tsuji-hertz", "hertz-constant-damping"] = ...,
    speed: Optional[float] = ...,  # deprecated: impact_velocity
) -> ObliqueResult[float]: ...
@overload
def oblique(
    *,
    material: Material,
    friction: Optional[float],
    angle: Union[_Real, _Array],
    spin: Union[_Real, _Array] = ...,
    impact_velocity: float = ...,
    tangential: Tangential = ...,
    tangential_stiffness: Optional[float] = ...,
    tangential_damping: float = ...,
    wall: bool = ...,
    fixed_normal: bool = ...,
    end: Literal["naive", "delayed-recovery", "delayed_recovery"] = ...,
    torque_arm: TorqueArm = ...,
    tolerance: float = ...,
    eps: Optional[float] = ...,
    velocity: Optional[float] = ...,  # m/s
    wall_young_modulus: Optional[float] = ...,  # Pa
    wall_poisson_ratio: Optional[float] = ...,
    law: Literal["viscoelastic-hertz", "tsuji-hertz", "hertz-constant-damping"] = ...,
    speed: Optional[float] = ...,  # deprecated: impact_velocity
) -> ObliqueResult[npt.NDArray[np.float64]]: ...
