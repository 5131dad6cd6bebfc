// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// CVODE's fixed-point corrector (Adams) for the small vectors of src/sundials/small_vector.hpp: the iteration
// of SUNNonlinSol_FixedPoint without acceleration (m = 0) and without damping, step for step the same
// arithmetic, with its copies and difference as plain loops instead of three dispatched vector calls per
// iteration. Private to the library.
#include "sundials/handles.hpp"

namespace restitution::sundials {

// A fixed-point solver for vectors like `template_vector` (serial layout, as make_small_vector's).
NonlinearSolver make_small_fixed_point_solver(const Vector& template_vector, const Context& context);

}  // namespace restitution::sundials
