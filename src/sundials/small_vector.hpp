// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A serial N_Vector for the 3-component states of this project. SUNDIALS' serial vector spends more time
// dispatching (special cases of LinearSum, separate local/global reductions) than computing on three
// numbers; CVODE's step is O(q^2) vector operations, so they dominate a solve (also with the optimized
// CVODE build: with SUNDIALS' serial vector a delayed-end sweep takes 36 % more instructions and ~12 % more
// CPU, a naive-end sweep 39 % more instructions, docs/performance.md, issue 34). This vector keeps the
// serial layout (the dense linear solver and N_VGetArrayPointer work on it unchanged) and replaces the
// operations CVODE calls per step by plain loops, with the fused operations enabled. Private to the
// library.
#include "sundials/handles.hpp"

namespace restitution::sundials {

// A serial vector of the given length whose hot operations are the plain loops; its clones share them.
Vector make_small_vector(sunindextype length, const Context& context);

}  // namespace restitution::sundials
