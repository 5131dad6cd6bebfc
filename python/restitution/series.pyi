# SPDX-License-Identifier: BSD-3-Clause
# Type stubs of restitution.series (natural units, zeta = beta v^(1/5)).
from typing import Literal, Optional, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]

coefficient_kinds: Tuple[str, ...]
evaluation_kinds: Tuple[str, ...]

@overload
def coefficients(kind: Literal["naive", "delayed-recovery"], count: int) -> FloatArray: ...
@overload
def coefficients(kind: Literal["max-compression"], count: int) -> Tuple[FloatArray, FloatArray]: ...
@overload
def eval(kind: str, zeta: float, terms: Optional[int] = ...,
         coefficients: Literal["computed", "published"] = ...) -> float: ...
@overload
def eval(kind: str, zeta: npt.ArrayLike, terms: Optional[int] = ...,
         coefficients: Literal["computed", "published"] = ...) -> Union[float, FloatArray]: ...
