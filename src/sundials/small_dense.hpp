// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Dense linear algebra for the 3×3 Newton systems of CVODE's BDF corrector. SUNDIALS' dense matrix operations
// and its LU (SUNLinSol_Dense) cost more in dispatch and general loops than the arithmetic on nine numbers,
// also in the optimized CVODE build: with them instead of these a naive-end sweep (200 log-spaced ζ in
// [1e-3, 1e3], T = 1e-10) takes 3.0 % more instructions and ~2 % more CPU (docs/performance.md, issue 34).
// The matrix here keeps SUNDIALS' dense layout and ID (SM_ELEMENT_D and CVODE's Jacobian code work on it
// unchanged) with plain loops in its operations table; the linear solver is an LU with partial pivoting
// compiled with our flags. Private to the library.
#include "sundials/handles.hpp"

namespace restitution::sundials {

// A square SUNDIALS dense matrix of size n whose zero/copy/scale-add/matvec operations are plain loops (fixed
// and unrolled for n = 3); its clones share them.
Matrix make_small_dense_matrix(sunindextype n, const Context& context);

// A direct linear solver for square dense matrices of the template vector's length: setup factors the matrix
// in place (LU with partial pivoting, as SUNLinSol_Dense; a zero pivot gives the recoverable
// SUNLS_LUFACT_FAIL), solve substitutes. Throws InvalidInput when the matrix is not dense, not square or does
// not match the vector.
LinearSolver make_small_dense_solver(const Vector& template_vector, const Matrix& matrix,
                                     const Context& context);

}  // namespace restitution::sundials
