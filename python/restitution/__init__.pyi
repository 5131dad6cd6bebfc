# SPDX-License-Identifier: BSD-3-Clause
# Type stubs of the restitution package. Physical quantities in SI units (named in each docstring);
# zeta, tau, x and the EndResult/CollisionResult fields in natural units (x'(0) = 1).
from typing import Any, Callable, Dict, Generic, Literal, Optional, Sequence, Tuple, TypedDict, TypeVar, Union, overload

import numpy as np
import numpy.typing as npt

from . import fast as fast
from . import series as series
from ._oblique import ObliqueResult as ObliqueResult, oblique as oblique
from ._adhesion import AdhesiveCollision as AdhesiveCollision, adhesive_collision as adhesive_collision, sticking_speed as sticking_speed, adhesive_closed_forms as adhesive_closed_forms

__version__: str  # e.g. "0.3.0", the same as `restitution --version`

End = Literal["naive", "delayed-recovery", "delayed_recovery"]
Method = Literal["auto", "bdf", "adams", "taylor"]
Law = Literal["viscoelastic-hertz", "linear-dashpot", "tsuji-hertz", "hertz-constant-damping"]  # the family table's order
ArrayLike = Union[npt.ArrayLike, Sequence[float]]
FloatArray = npt.NDArray[np.float64]
# Scalars and arrays kept apart, so that the overloads give float for a scalar and an array for an array (a
# 0-d array, which the stubs count as an array, gives a float at run time).
Real = Union[float, np.floating[Any], np.integer[Any]]
Array = Union[npt.NDArray[Any], Sequence[float], Sequence[Sequence[float]]]
# progress= of array calls: a callable(done, total), or True for a tqdm bar.
Progress = Union[None, bool, Callable[[int, int], object]]

class NumericalFailure(ArithmeticError):
    """The solver could not deliver the requested accuracy (message names value and index)."""

class EndResult:
    @property
    def eps(self) -> float: ...
    @property
    def one_minus_eps(self) -> float: ...
    @property
    def tau(self) -> float: ...
    @property
    def x(self) -> float: ...
    @property
    def velocity(self) -> float: ...
    @property
    def dissipated_energy(self) -> float: ...

class MaxCompression:
    @property
    def tau(self) -> float: ...
    @property
    def x(self) -> float: ...

class SolverStats:
    @property
    def steps(self) -> int: ...
    @property
    def rhs_evaluations(self) -> int: ...
    @property
    def jacobian_evaluations(self) -> int: ...
    @property
    def root_evaluations(self) -> int: ...
    @property
    def error_test_failures(self) -> int: ...
    @property
    def convergence_failures(self) -> int: ...

_Naive = TypeVar("_Naive", bound=Optional[EndResult], covariant=True)
_Delayed = TypeVar("_Delayed", bound=Optional[EndResult], covariant=True)

# Generic in the stubs only, so that solve() can say which ends a result holds: CollisionResult[EndResult,
# EndResult] for end="both". A bare CollisionResult annotation means either end may be None.
class CollisionResult(Generic[_Naive, _Delayed]):
    @property
    def zeta(self) -> float: ...
    @property
    def law(self) -> str: ...
    @property
    def tolerance(self) -> float: ...
    @property
    def method(self) -> str: ...
    @property
    def max_compression(self) -> MaxCompression: ...
    @property
    def naive(self) -> _Naive: ...
    @property
    def delayed_recovery(self) -> _Delayed: ...
    @property
    def stats(self) -> SolverStats: ...
    @property
    def has_trajectory(self) -> bool: ...
    @property
    def tau(self) -> FloatArray: ...
    @property
    def x(self) -> FloatArray: ...
    @property
    def velocity(self) -> FloatArray: ...
    @property
    def acceleration(self) -> FloatArray: ...

class Material:
    def __init__(
        self,
        *,
        young_modulus: float,  # Pa
        poisson_ratio: float,
        radius: Optional[float] = None,  # m
        radii: Optional[Tuple[float, float]] = None,  # m
        density: Optional[float] = None,  # kg/m^3
        mass: Optional[float] = None,  # kg
        masses: Optional[Tuple[float, float]] = None,  # kg
        dissipative_constant: Optional[float] = None,  # A, s
        viscosities: Optional[Tuple[float, float]] = None,  # eta1, eta2, Pa s
    ) -> None: ...
    @property
    def young_modulus(self) -> float: ...
    @property
    def poisson_ratio(self) -> float: ...
    @property
    def radii(self) -> Tuple[float, float]: ...
    @property
    def density(self) -> Optional[float]: ...
    @property
    def masses(self) -> Optional[Tuple[float, float]]: ...
    @property
    def dissipative_constant(self) -> Optional[float]: ...
    @property
    def viscosities(self) -> Optional[Tuple[float, float]]: ...
    @property
    def effective_radius(self) -> float: ...  # m
    @property
    def effective_mass(self) -> float: ...  # kg
    @property
    def k(self) -> float: ...  # s^-2 m^-1/2
    @property
    def A(self) -> float: ...  # s
    @property
    def beta(self) -> float: ...  # s^(1/5) m^(-1/5)

class Calibration:
    @property
    def law(self) -> str: ...
    @property
    def zeta(self) -> float: ...
    @property
    def parameter(self) -> float: ...
    @property
    def beta(self) -> Optional[float]: ...  # s^(1/5) m^(-1/5); None unless law is viscoelastic-hertz
    @property
    def eps_at_zeta(self) -> float: ...
    @property
    def characteristic_velocity_m_s(self) -> Optional[float]: ...  # g*; None unless law is viscoelastic-hertz
    @property
    def dissipative_constant_s(self) -> Optional[float]: ...  # A
    @property
    def characteristic_velocity(self) -> Optional[float]: ...  # deprecated: characteristic_velocity_m_s
    @property
    def dissipative_constant(self) -> Optional[float]: ...  # deprecated: dissipative_constant_s
    @property
    def solves(self) -> int: ...

@overload
def zeta_of(zeta: Real, *, beta: None = ..., velocity: None = ..., material: None = ...) -> float: ...
@overload
def zeta_of(zeta: Array, *, beta: None = ..., velocity: None = ..., material: None = ...) -> FloatArray: ...
@overload
def zeta_of(zeta: None = ..., *, beta: Real, velocity: Real, material: None = ...) -> float: ...
@overload
def zeta_of(zeta: None = ..., *, beta: Array, velocity: Union[Real, Array], material: None = ...) -> FloatArray: ...
@overload
def zeta_of(zeta: None = ..., *, beta: Real, velocity: Array, material: None = ...) -> FloatArray: ...
@overload
def zeta_of(zeta: None = ..., *, beta: None = ..., velocity: Real, material: Material) -> float: ...
@overload
def zeta_of(zeta: None = ..., *, beta: None = ..., velocity: Array, material: Material) -> FloatArray: ...

# eps: a float for a scalar zeta (or scalar beta and velocity, or a material and a scalar velocity), an array
# of the broadcast shape for an array.
@overload
def eps(
    zeta: Real, end: End = ..., tolerance: float = ..., method: Method = ..., *, beta: None = ...,
    velocity: None = ..., material: None = ..., law: Law = ..., threads: Optional[int] = ..., progress: Progress = ...
) -> float: ...
@overload
def eps(
    zeta: Array, end: End = ..., tolerance: float = ..., method: Method = ..., *, beta: None = ...,
    velocity: None = ..., material: None = ..., law: Law = ..., threads: Optional[int] = ..., progress: Progress = ...
) -> FloatArray: ...
@overload
def eps(
    zeta: None = ..., end: End = ..., tolerance: float = ..., method: Method = ..., *, beta: Real,
    velocity: Real, material: None = ..., law: Law = ..., threads: Optional[int] = ..., progress: Progress = ...
) -> float: ...
@overload
def eps(
    zeta: None = ..., end: End = ..., tolerance: float = ..., method: Method = ..., *, beta: Array,
    velocity: Union[Real, Array], material: None = ..., law: Law = ..., threads: Optional[int] = ...,
    progress: Progress = ...
) -> FloatArray: ...
@overload
def eps(
    zeta: None = ..., end: End = ..., tolerance: float = ..., method: Method = ..., *, beta: Real,
    velocity: Array, material: None = ..., law: Law = ..., threads: Optional[int] = ..., progress: Progress = ...
) -> FloatArray: ...
@overload
def eps(
    zeta: None = ..., end: End = ..., tolerance: float = ..., method: Method = ..., *, beta: None = ...,
    velocity: Real, material: Material, law: Law = ..., threads: Optional[int] = ..., progress: Progress = ...
) -> float: ...
@overload
def eps(
    zeta: None = ..., end: End = ..., tolerance: float = ..., method: Method = ..., *, beta: None = ...,
    velocity: Array, material: Material, law: Law = ..., threads: Optional[int] = ..., progress: Progress = ...
) -> FloatArray: ...

# solve: the ends requested are the ends that are not None (end="both", the default: both).
@overload
def solve(
    zeta: Optional[Real] = ..., end: Literal["both"] = ..., tolerance: float = ..., method: Method = ...,
    trajectory: bool = ..., *, beta: Optional[Real] = ..., velocity: Optional[Real] = ...,
    material: Optional[Material] = ..., law: Law = ...
) -> CollisionResult[EndResult, EndResult]: ...
@overload
def solve(
    zeta: Optional[Real], end: Literal["naive"], tolerance: float = ..., method: Method = ..., trajectory: bool = ...,
    *, beta: Optional[Real] = ..., velocity: Optional[Real] = ..., material: Optional[Material] = ..., law: Law = ...
) -> CollisionResult[EndResult, None]: ...
@overload
def solve(
    zeta: Optional[Real] = ..., *, end: Literal["naive"], tolerance: float = ..., method: Method = ...,
    trajectory: bool = ..., beta: Optional[Real] = ..., velocity: Optional[Real] = ...,
    material: Optional[Material] = ..., law: Law = ...
) -> CollisionResult[EndResult, None]: ...
@overload
def solve(
    zeta: Optional[Real], end: Literal["delayed-recovery"], tolerance: float = ..., method: Method = ...,
    trajectory: bool = ..., *, beta: Optional[Real] = ..., velocity: Optional[Real] = ...,
    material: Optional[Material] = ..., law: Law = ...
) -> CollisionResult[None, EndResult]: ...
@overload
def solve(
    zeta: Optional[Real] = ..., *, end: Literal["delayed-recovery"], tolerance: float = ..., method: Method = ...,
    trajectory: bool = ..., beta: Optional[Real] = ..., velocity: Optional[Real] = ...,
    material: Optional[Material] = ..., law: Law = ...
) -> CollisionResult[None, EndResult]: ...
@overload
def solve(
    zeta: Optional[Real] = ..., end: str = ..., tolerance: float = ..., method: Method = ..., trajectory: bool = ...,
    *, beta: Optional[Real] = ..., velocity: Optional[Real] = ..., material: Optional[Material] = ..., law: Law = ...
) -> CollisionResult[Optional[EndResult], Optional[EndResult]]: ...
def calibrate(
    eps: float,
    velocity: float,  # m/s
    end: End = ...,
    material: Optional[Material] = ...,
    tolerance: float = ...,
    method: Method = ...,
    *,
    law: Law = ...,
) -> Calibration: ...

def fit_data(
    v: ArrayLike,  # m/s
    eps: ArrayLike,
    sigma: Optional[ArrayLike] = ...,
    *,
    laws: Optional[Union[str, Sequence[str]]] = ...,
    speed_independent_end: End = ...,
    material: Optional[Material] = ...,
    tolerance: float = ...,
    method: Method = ...,
) -> Dict[str, Any]: ...

class SundialsInfo(TypedDict):
    version: str  # e.g. "6.4.1"
    optimized: bool  # False: Debian's libsundials, CVODE solves 2-3x slower
    description: str

class BuildInfo(TypedDict):
    version: str  # restitution's, as __version__
    sundials: SundialsInfo

def build_info() -> BuildInfo: ...


def gas(
    *,
    radius: Optional[float] = ...,  # m
    density: Optional[float] = ...,  # kg/m^3
    mass: Optional[float] = ...,  # kg
    eps: Optional[float] = ...,
    velocity: Optional[float] = ...,  # m/s
    dissipative_constant: Optional[float] = ...,  # s
    young_modulus: Optional[float] = ...,  # Pa
    poisson_ratio: Optional[float] = ...,
    law: Law = ...,
    end: End = ...,
    packing_fraction: Optional[float] = ...,
    rms_speed: Optional[float] = ...,  # m/s per direction
    temperature: Optional[float] = ...,  # J
    duration: Optional[float] = ...,  # s
    haff_times: Optional[float] = ...,
    first_time: float = ...,  # s
    points_per_decade: int = ...,
    a2: Union[None, float, Literal["haff", "evolving"]] = ...,  # "evolving": the result's "a2" is an array
    collision_rate_factor: float = ...,
    tolerance: float = ...,
    thermostat: Optional[Literal["langevin", "white-noise"]] = ...,  # the driven gas
    bath_temperature: Optional[float] = ...,  # J (langevin)
    bath_time: Optional[float] = ...,  # s (langevin)
    power: Optional[float] = ...,  # W per sphere (white-noise)
) -> Dict[str, Any]: ...  # the keys of `restitution gas --json`, the curve as float64 arrays
from os import PathLike
from typing import Callable

def sweep_to_file(
    zetas: ArrayLike,
    path: Union[str, PathLike[str]],
    *,
    resume: bool = ...,
    end: Union[End, Literal["both"]] = ...,
    tolerance: float = ...,
    method: Method = ...,
    threads: Optional[int] = ...,
    law: Law = ...,
    stop: Optional[Callable[[], bool]] = ...,
) -> Dict[str, Any]: ...  # "status", "path", "partial_path", "points", "finished", "resumed", "damaged_lines", ...
