# SPDX-License-Identifier: BSD-3-Clause
# Type stubs of restitution.series (natural units, zeta = beta v^(1/5)).
from typing import Any, Literal, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]
# Scalars and arrays kept apart, so that a scalar gives a float and an array an array.
Real = Union[float, np.floating[Any], np.integer[Any]]
Array = Union[npt.NDArray[Any], Sequence[float], Sequence[Sequence[float]]]

coefficient_kinds: Tuple[str, ...]
evaluation_kinds: Tuple[str, ...]

@overload
def coefficients(kind: Literal["naive", "delayed-recovery"], count: int) -> FloatArray: ...
@overload
def coefficients(kind: Literal["max-compression"], count: int) -> Tuple[FloatArray, FloatArray]: ...
@overload
def eval(kind: str, zeta: Real, terms: Optional[int] = ...,
         coefficients: Literal["computed", "published"] = ...) -> float: ...
@overload
def eval(kind: str, zeta: Array, terms: Optional[int] = ...,
         coefficients: Literal["computed", "published"] = ...) -> FloatArray: ...
