# Type stubs of restitution.fast: zeta in natural units, eps dimensionless.
from typing import Literal, Union, overload

import numpy as np
import numpy.typing as npt

End = Literal["naive", "delayed-recovery"]
FloatArray = npt.NDArray[np.float64]

@overload
def eps(zeta: float, end: End = ...) -> float: ...
@overload
def eps(zeta: npt.ArrayLike, end: End = ...) -> Union[float, FloatArray]: ...
@overload
def one_minus_eps(zeta: float, end: End = ...) -> float: ...
@overload
def one_minus_eps(zeta: npt.ArrayLike, end: End = ...) -> Union[float, FloatArray]: ...
@overload
def zeta_from_eps(eps: float, end: End = ...) -> float: ...
@overload
def zeta_from_eps(eps: npt.ArrayLike, end: End = ...) -> Union[float, FloatArray]: ...
