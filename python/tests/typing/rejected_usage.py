# SPDX-License-Identifier: BSD-3-Clause
"""Lines mypy must reject (python/tests/test_typing.py counts one error per line marked `# rejected`): the
stubs are precise, not merely permissive."""

import numpy as np

import restitution

scalar_from_array: float = restitution.eps(np.array([0.1, 1.0]))  # rejected
array_from_scalar: np.ndarray = restitution.eps(1.0)  # rejected
naive_missing: float = restitution.solve(1.0, end="delayed-recovery").naive.eps  # rejected
delayed_missing: float = restitution.solve(1.0, "naive").delayed_recovery.eps  # rejected
fast_scalar_from_array: float = restitution.fast.eps([0.1, 0.2])  # rejected
wrong_end: float = restitution.eps(1.0, end="middle")  # rejected
steel = restitution.Material(young_modulus=2e11, poisson_ratio=0.3, radius=1e-3, density=7800.0)
oblique_array_as_float: float = restitution.oblique(material=steel, friction=0.3, angle=[10.0, 20.0]).spin_rad_s  # rejected
oblique_unknown_model = restitution.oblique(material=steel, friction=0.3, angle=10.0, tangential="hertz")  # rejected
