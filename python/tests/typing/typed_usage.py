# SPDX-License-Identifier: BSD-3-Clause
"""The package as a typed program uses it: mypy (python/tests/test_typing.py) must accept every line, so the stubs
give a float for a scalar, an array for an array, and non-Optional ends for the ends solve() was asked for."""

import numpy as np
import numpy.typing as npt

import restitution
import restitution.fast
import restitution.series

speeds: npt.NDArray[np.float64] = np.logspace(-2, 1, 5)  # m/s
steel = restitution.Material(young_modulus=2.0e11, poisson_ratio=0.3, radius=0.01, density=7800.0,
                             dissipative_constant=2e-6)

y: float = restitution.eps(1.0)
x: np.ndarray = restitution.eps(np.array([0.1, 1.0]))
from_list: npt.NDArray[np.float64] = restitution.eps([0.1, 1.0], end="naive", progress=True)
counted: np.ndarray = restitution.eps(speeds, progress=lambda done, total: print(done, total))
one_speed: float = restitution.eps(material=steel, velocity=1.0)
many_speeds: np.ndarray = restitution.eps(material=steel, velocity=speeds)
beta_speeds: np.ndarray = restitution.eps(beta=0.1, velocity=speeds)
beta_speed: float = restitution.eps(beta=0.1, velocity=2.0)
numpy_scalar: float = restitution.eps(np.float64(0.5))
zeta: float = restitution.zeta_of(beta=0.1, velocity=1.0)
zetas: np.ndarray = restitution.zeta_of(material=steel, velocity=speeds)

both = restitution.solve(1.0)
both_eps: float = both.naive.eps + both.delayed_recovery.eps  # both ends, no Optional
naive_only: float = restitution.solve(1.0, "naive").naive.eps
delayed_only: float = restitution.solve(1.0, end="delayed-recovery").delayed_recovery.eps
by_material: float = restitution.solve(material=steel, velocity=1.0).delayed_recovery.one_minus_eps
any_result: restitution.CollisionResult = restitution.solve(1.0, end="naive")  # a bare annotation still fits
trajectory: np.ndarray = restitution.solve(1.0, trajectory=True).x

calibration = restitution.calibrate(0.8, 1.0, material=steel)
beta: float = calibration.zeta
sundials_optimized: bool = restitution.build_info()["sundials"]["optimized"]

fast_eps: float = restitution.fast.eps(0.3)
fast_array: np.ndarray = restitution.fast.eps(speeds)
series_array: np.ndarray = restitution.series.eval("naive", speeds)
cooling: dict = restitution.gas(radius=0.005, density=920.0, eps=0.8, velocity=2.0, packing_fraction=0.1,
                                rms_speed=1.0, haff_times=10, a2="haff")

grazing: float = restitution.oblique(material=steel, friction=0.3, angle=80.0, wall=True,
                                     tangential_stiffness=2.2e6).tangential_restitution
spins_after: npt.NDArray[np.float64] = restitution.oblique(material=steel, friction=0.3, angle=[10.0, 80.0],
                                                           tangential="mindlin").spin_rad_s
