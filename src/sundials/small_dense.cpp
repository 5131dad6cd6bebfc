// SPDX-License-Identifier: BSD-3-Clause
#include "sundials/small_dense.hpp"

#include <fmt/core.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "restitution/errors.hpp"

namespace restitution::sundials {
namespace {

// Every operation below is called through a SUNDIALS C function table: no exception may leave it, and none
// can (arithmetic on doubles, no allocation).

bool is_square_dense(SUNMatrix a, sunindextype n) noexcept {
  return a != nullptr && SUNMatGetID(a) == SUNMATRIX_DENSE && SM_ROWS_D(a) == n && SM_COLUMNS_D(a) == n;
}

// The operations of square dense matrices with Size columns (0: any size, read from the matrix). Storage is
// column-major: element (i, j) is data[i + j n].
template <sunindextype Size>
struct MatrixLoops {
  // A size known at compile time (the 3-component state) lets the compiler unroll every loop.
  static sunindextype size(SUNMatrix a) { return Size > 0 ? Size : SM_COLUMNS_D(a); }
  static sunindextype elements(SUNMatrix a) { return size(a) * size(a); }
  static double* data(SUNMatrix a) { return SM_DATA_D(a); }

  static int zero(SUNMatrix a) noexcept {
    std::fill_n(data(a), elements(a), 0.0);
    return SUNMAT_SUCCESS;
  }

  // b = a.
  static int copy(SUNMatrix a, SUNMatrix b) noexcept {
    if (!is_square_dense(b, size(a))) return SUNMAT_ILL_INPUT;
    std::copy_n(data(a), elements(a), data(b));
    return SUNMAT_SUCCESS;
  }

  // a = c a + b.
  static int scale_add(double c, SUNMatrix a, SUNMatrix b) noexcept {
    if (!is_square_dense(b, size(a))) return SUNMAT_ILL_INPUT;
    double* ad = data(a);
    const double* bd = data(b);
    for (sunindextype k = 0; k < elements(a); ++k) ad[k] = c * ad[k] + bd[k];
    return SUNMAT_SUCCESS;
  }

  // a = c a + I (CVODE's Newton matrix I - γJ from the saved Jacobian).
  static int scale_add_identity(double c, SUNMatrix a) noexcept {
    double* ad = data(a);
    const sunindextype n = size(a);
    for (sunindextype k = 0; k < n * n; ++k) ad[k] *= c;
    for (sunindextype i = 0; i < n; ++i) ad[i + i * n] += 1.0;
    return SUNMAT_SUCCESS;
  }

  // y = a x, for distinct vectors of the matrix's size with an array (serial layout).
  static int matvec(SUNMatrix a, N_Vector x, N_Vector y) noexcept {
    const sunindextype n = size(a);
    const double* xd = N_VGetArrayPointer(x);
    double* yd = N_VGetArrayPointer(y);
    if (xd == nullptr || yd == nullptr || xd == yd || N_VGetLength(x) != n || N_VGetLength(y) != n)
      return SUNMAT_ILL_INPUT;
    const double* ad = data(a);
    for (sunindextype i = 0; i < n; ++i) {
      double sum = 0.0;
      for (sunindextype j = 0; j < n; ++j) sum += ad[i + j * n] * xd[j];
      yd[i] = sum;
    }
    return SUNMAT_SUCCESS;
  }

  // SUNMatClone_Dense builds a matrix with SUNDIALS' own table; CVODE clones the Jacobian (its saved copy),
  // so the clone gets this table too.
  static SUNMatrix clone(SUNMatrix a) noexcept {
    SUNMatrix b = SUNDenseMatrix(SM_ROWS_D(a), SM_COLUMNS_D(a), a->sunctx);
    if (b != nullptr && SUNMatCopyOps(a, b) != SUNMAT_SUCCESS) {
      SUNMatDestroy(b);
      return nullptr;
    }
    return b;
  }

  static void install(SUNMatrix_Ops ops) {
    ops->clone = clone;
    ops->zero = zero;
    ops->copy = copy;
    ops->scaleadd = scale_add;
    ops->scaleaddi = scale_add_identity;
    ops->matvec = matvec;
  }
};

// What the solver keeps between setup and solve.
struct Factorisation {
  std::vector<sunindextype> pivots;  // at step k of the elimination, row k was swapped with row pivots[k]
  sunindextype last_flag = 0;        // 0, k + 1 for a zero pivot in column k, or a negative SUNLS_ flag
};

Factorisation& factorisation(SUNLinearSolver s) {
  return *static_cast<Factorisation*>(s->content);
}

// LU with partial pivoting of square dense matrices with Size columns (0: any size, from the pivots).
template <sunindextype Size>
struct LuLoops {
  static sunindextype size(const Factorisation& f) {
    return Size > 0 ? Size : static_cast<sunindextype>(f.pivots.size());
  }

  // In place: a = P L U with unit-diagonal L stored below the diagonal and U on and above it. The
  // elimination order is that of SUNDIALS' denseGETRF (largest pivot, first one on ties; multipliers from
  // the reciprocal pivot), so results agree with SUNLinSol_Dense. Returns 0, or k + 1 when column k has
  // only zeros on and below the diagonal.
  static sunindextype factor(double* a, sunindextype n, sunindextype* pivots) {
    for (sunindextype k = 0; k < n; ++k) {
      double* column_k = a + k * n;
      sunindextype pivot = k;
      for (sunindextype i = k + 1; i < n; ++i)
        if (std::abs(column_k[i]) > std::abs(column_k[pivot])) pivot = i;
      pivots[k] = pivot;
      if (column_k[pivot] == 0.0) return k + 1;
      if (pivot != k)
        for (sunindextype j = 0; j < n; ++j) std::swap(a[pivot + j * n], a[k + j * n]);
      const double reciprocal = 1.0 / column_k[k];
      for (sunindextype i = k + 1; i < n; ++i) column_k[i] *= reciprocal;
      for (sunindextype j = k + 1; j < n; ++j) {
        double* column_j = a + j * n;
        const double a_kj = column_j[k];
        for (sunindextype i = k + 1; i < n; ++i) column_j[i] -= a_kj * column_k[i];
      }
    }
    return 0;
  }

  // b = (P L U)^-1 b: the row swaps, then forward (L) and back (U) substitution.
  static void substitute(const double* lu, sunindextype n, const sunindextype* pivots, double* b) {
    for (sunindextype k = 0; k < n; ++k)
      if (pivots[k] != k) std::swap(b[k], b[pivots[k]]);
    for (sunindextype k = 0; k < n; ++k)
      for (sunindextype i = k + 1; i < n; ++i) b[i] -= lu[i + k * n] * b[k];
    for (sunindextype k = n - 1; k >= 0; --k) {
      b[k] /= lu[k + k * n];
      for (sunindextype i = 0; i < k; ++i) b[i] -= lu[i + k * n] * b[k];
    }
  }

  static int setup(SUNLinearSolver s, SUNMatrix a) noexcept {
    Factorisation& f = factorisation(s);
    if (!is_square_dense(a, size(f))) {
      f.last_flag = SUNLS_ILL_INPUT;
      return SUNLS_ILL_INPUT;
    }
    f.last_flag = factor(SM_DATA_D(a), size(f), f.pivots.data());
    // Recoverable, as SUNLinSol_Dense: CVODE retries with a fresh Jacobian or a smaller step.
    return f.last_flag > 0 ? SUNLS_LUFACT_FAIL : SUNLS_SUCCESS;
  }

  // x = a^-1 b with a factored by setup (the tolerance is for iterative solvers).
  static int solve(SUNLinearSolver s, SUNMatrix a, N_Vector x, N_Vector b, double /*tolerance*/) noexcept {
    Factorisation& f = factorisation(s);
    const sunindextype n = size(f);
    double* xd = N_VGetArrayPointer(x);
    const double* bd = N_VGetArrayPointer(b);
    if (!is_square_dense(a, n) || N_VGetLength(x) != n || N_VGetLength(b) != n) {
      f.last_flag = SUNLS_ILL_INPUT;
      return SUNLS_ILL_INPUT;
    }
    if (xd == nullptr || bd == nullptr) {
      f.last_flag = SUNLS_MEM_FAIL;
      return SUNLS_MEM_FAIL;
    }
    if (xd != bd) std::copy_n(bd, n, xd);
    substitute(SM_DATA_D(a), n, f.pivots.data(), xd);
    f.last_flag = SUNLS_SUCCESS;
    return SUNLS_SUCCESS;
  }

  static void install(SUNLinearSolver_Ops ops);
};

SUNLinearSolver_Type solver_type(SUNLinearSolver /*s*/) noexcept {
  return SUNLINEARSOLVER_DIRECT;
}

SUNLinearSolver_ID solver_id(SUNLinearSolver /*s*/) noexcept {
  return SUNLINEARSOLVER_CUSTOM;
}

int initialize_solver(SUNLinearSolver s) noexcept {
  factorisation(s).last_flag = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}

sunindextype solver_last_flag(SUNLinearSolver s) noexcept {
  return factorisation(s).last_flag;
}

// The pivots (integers) and the two size fields, counted as SUNLinSol_Dense counts its own.
int solver_space(SUNLinearSolver s, long int* real_words, long int* integer_words) noexcept {
  *real_words = 0;
  *integer_words = 2 + static_cast<long int>(factorisation(s).pivots.size());
  return SUNLS_SUCCESS;
}

int free_solver(SUNLinearSolver s) noexcept {
  if (s == nullptr) return SUNLS_SUCCESS;
  delete static_cast<Factorisation*>(s->content);
  s->content = nullptr;
  SUNLinSolFreeEmpty(s);
  return SUNLS_SUCCESS;
}

template <sunindextype Size>
void LuLoops<Size>::install(SUNLinearSolver_Ops ops) {
  ops->gettype = solver_type;
  ops->getid = solver_id;
  ops->initialize = initialize_solver;
  ops->setup = setup;
  ops->solve = solve;
  ops->lastflag = solver_last_flag;
  ops->space = solver_space;
  ops->free = free_solver;
}

// The 3-component state gets the loops of fixed length, any other size the general ones.
template <template <sunindextype> class Loops, class Ops>
void install_for_size(sunindextype n, Ops ops) {
  if (n == 3) {
    Loops<3>::install(ops);
  } else {
    Loops<0>::install(ops);
  }
}

}  // namespace

Matrix make_small_dense_matrix(sunindextype n, const Context& context) {
  Matrix m = make_dense_matrix(n, n, context);
  install_for_size<MatrixLoops>(n, m->ops);
  return m;
}

LinearSolver make_small_dense_solver(const Vector& template_vector, const Matrix& matrix,
                                     const Context& context) {
  const sunindextype n = N_VGetLength(template_vector.get());
  if (!is_square_dense(matrix.get(), n))
    throw InvalidInput(fmt::format(
        "the small dense linear solver needs a square dense matrix of the vector's length {}", n));
  auto content = std::make_unique<Factorisation>();
  content->pivots.assign(static_cast<std::size_t>(n), 0);
  LinearSolver s(SUNLinSolNewEmpty(context.get()));
  check_created(s.get(), "SUNLinSolNewEmpty");
  install_for_size<LuLoops>(n, s->ops);
  s->content = content.release();
  return s;
}

}  // namespace restitution::sundials
