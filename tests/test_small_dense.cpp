// SPDX-License-Identifier: BSD-3-Clause
// The dense 3×3 (and general n×n) matrix and LU solver that CVODE's BDF corrector uses: against SUNDIALS' own
// SUNLinSol_Dense on the same matrices, against systems built from a known solution, on a zero leading pivot
// and singular matrices, and the matrix operations against plain reference loops.
#include <gtest/gtest.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

#include "restitution/errors.hpp"
#include "sundials/small_dense.hpp"

namespace restitution::sundials {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// Column-major n×n entries: element (i, j) at [i + j n].
using Entries = std::vector<double>;
using Values = std::vector<double>;

std::size_t size_of(const Entries& a) {
  return static_cast<std::size_t>(std::lround(std::sqrt(a.size())));
}

double max_norm(const Values& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

double max_difference(const Values& a, const Values& b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

// b = a x, accumulated in long double so that b is the exact product to within its own rounding.
Values product(const Entries& a, const Values& x) {
  const std::size_t n = x.size();
  Values b(n);
  for (std::size_t i = 0; i < n; ++i) {
    long double sum = 0.0L;
    for (std::size_t j = 0; j < n; ++j) sum += static_cast<long double>(a[i + j * n]) * x[j];
    b[i] = static_cast<double>(sum);
  }
  return b;
}

// Infinity-norm of a column-major matrix (largest row sum).
double matrix_norm(const Entries& a) {
  const std::size_t n = size_of(a);
  double m = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    double row = 0.0;
    for (std::size_t j = 0; j < n; ++j) row += std::abs(a[i + j * n]);
    m = std::max(m, row);
  }
  return m;
}

void fill(SUNMatrix m, const Entries& a) {
  std::copy(a.begin(), a.end(), SM_DATA_D(m));
}

Entries entries(SUNMatrix m) {
  const sunindextype n = SM_COLUMNS_D(m);
  return {SM_DATA_D(m), SM_DATA_D(m) + n * n};
}

Values values(N_Vector v) {
  return {NV_DATA_S(v), NV_DATA_S(v) + NV_LENGTH_S(v)};
}

struct Solution {
  int setup_flag = 0;
  sunindextype last_flag = 0;
  Values x;
};

class SmallDense : public ::testing::Test {
 protected:
  // Factor a and solve a x = b, with our solver (small) or SUNDIALS' SUNLinSol_Dense.
  Solution solve(const Entries& a, const Values& b, bool small) {
    const auto n = static_cast<sunindextype>(b.size());
    Vector x = make_serial_vector(n, context_);
    Vector rhs = make_serial_vector(n, context_);
    std::copy(b.begin(), b.end(), NV_DATA_S(rhs.get()));
    Matrix m = small ? make_small_dense_matrix(n, context_) : make_dense_matrix(n, n, context_);
    fill(m.get(), a);
    LinearSolver s = small ? make_small_dense_solver(x, m, context_)
                           : LinearSolver(SUNLinSol_Dense(x.get(), m.get(), context_.get()));
    EXPECT_EQ(SUNLinSolInitialize(s.get()), SUNLS_SUCCESS);
    Solution out;
    out.setup_flag = SUNLinSolSetup(s.get(), m.get());
    out.last_flag = SUNLinSolLastFlag(s.get());
    if (out.setup_flag == SUNLS_SUCCESS) {
      EXPECT_EQ(SUNLinSolSolve(s.get(), m.get(), x.get(), rhs.get(), 0.0), SUNLS_SUCCESS);
      out.x = values(x.get());
    }
    return out;
  }

  // κ∞(a) = ‖a‖∞ ‖a⁻¹‖∞, the inverse from SUNDIALS' solver column by column.
  double condition(const Entries& a) {
    const std::size_t n = size_of(a);
    Values row_sums(n, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
      Values unit(n, 0.0);
      unit[j] = 1.0;
      const Values column = solve(a, unit, false).x;
      for (std::size_t i = 0; i < n; ++i) row_sums[i] += std::abs(column[i]);
    }
    return matrix_norm(a) * max_norm(row_sums);
  }

  // Ours agrees with SUNDIALS to rounding and both recover the known x to within what κ allows.
  void expect_solves(const Entries& a, const Values& x) {
    const Values b = product(a, x);
    const Solution ours = solve(a, b, true);
    const Solution theirs = solve(a, b, false);
    ASSERT_EQ(ours.setup_flag, SUNLS_SUCCESS);
    ASSERT_EQ(theirs.setup_flag, SUNLS_SUCCESS);
    EXPECT_EQ(ours.last_flag, 0);
    EXPECT_LE(max_difference(ours.x, theirs.x), 1e-14 * max_norm(theirs.x));
    const double kappa = condition(a);
    const auto n = static_cast<double>(x.size());
    EXPECT_LE(max_difference(ours.x, x), 50.0 * n * kEpsilon * kappa * max_norm(x)) << "kappa " << kappa;
  }

  Entries random_entries(std::size_t n) {
    Entries a(n * n);
    for (double& e : a) e = uniform_(generator_);
    return a;
  }
  Values random_values(std::size_t n) {
    Values v(n);
    for (double& e : v) e = uniform_(generator_);
    return v;
  }

  Context context_;
  std::mt19937_64 generator_{20261123};
  std::uniform_real_distribution<double> uniform_{-1.0, 1.0};
};

TEST_F(SmallDense, RandomSystemsAgreeWithSundialsAndTheKnownSolution) {
  for (const std::size_t n : {3U, 5U}) {
    for (int trial = 0; trial < 200; ++trial) {
      SCOPED_TRACE(testing::Message() << "n " << n << " trial " << trial);
      expect_solves(random_entries(n), random_values(n));
    }
  }
}

TEST_F(SmallDense, IllConditionedSystemsAgreeWithSundialsAndTheKnownSolution) {
  // Nearly singular (κ∞ ≈ 2e11).
  expect_solves({1.0, 4.0, 7.0, 2.0, 5.0, 8.0, 3.0, 6.0, 9.0 + 1e-9}, {1.0, -2.0, 0.5});
  // CVODE's Newton matrix I - γJ for a stiff contact (stiffness 1e10, damping 1e4, step 1e-3): entries
  // over 13 decades as in the BDF phases (κ∞ ≈ 1e10).
  const double gamma = 1e-3;
  const Entries jacobian = {0.0, -1e10, 3e3, 1.0, -1e4, 2e-2, 0.0, 0.0, 0.0};
  Entries newton(9);
  for (std::size_t k = 0; k < 9; ++k) newton[k] = (k % 4 == 0 ? 1.0 : 0.0) - gamma * jacobian[k];
  expect_solves(newton, {1e-6, -3.0, 0.25});
  // The 5×5 Hilbert matrix (κ ≈ 5e5) with rows scaled over 16 decades (κ∞ ≈ 1e19): the general path, and
  // partial pivoting that must follow the scaling.
  Entries hilbert(25);
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t j = 0; j < 5; ++j)
      hilbert[i + j * 5] = std::pow(1e4, static_cast<double>(i)) / static_cast<double>(i + j + 1);
  expect_solves(hilbert, {1.0, 2.0, -1.0, 0.5, 3.0});
}

TEST_F(SmallDense, ZeroLeadingPivotIsSwappedAway) {
  expect_solves({0.0, 3.0, 1.0, 1.0, 0.0, 1.0, 2.0, 1.0, 0.0}, {2.0, -1.0, 4.0});
  // A permutation matrix: every step needs a swap, the solution is exact.
  const Entries permutation = {0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0};
  const Values x = {1.5, -2.5, 3.5};
  const Solution ours = solve(permutation, product(permutation, x), true);
  EXPECT_EQ(ours.x, x);
}

TEST_F(SmallDense, SingularMatricesGiveTheRecoverableLuFailureLikeSundials) {
  const std::vector<Entries> singular = {
      {1.0, 2.0, 1.0, 2.0, 4.0, 1.0, 3.0, 6.0, 1.0},  // rank 2: the third pivot is zero
      {0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 7.0},  // zero first column
      Entries(25, 1.0),                               // rank 1, general path
  };
  for (const Entries& a : singular) {
    const Values b(size_of(a), 1.0);
    const Solution ours = solve(a, b, true);
    const Solution theirs = solve(a, b, false);
    EXPECT_EQ(ours.setup_flag, SUNLS_LUFACT_FAIL);
    EXPECT_GT(SUNLS_LUFACT_FAIL, 0);  // CVODE retries a positive (recoverable) failure
    EXPECT_EQ(ours.setup_flag, theirs.setup_flag);
    EXPECT_EQ(ours.last_flag, theirs.last_flag);  // the column of the zero pivot, counted from 1
    EXPECT_GT(ours.last_flag, 0);
  }
}

TEST_F(SmallDense, MatrixOperationsAgreeWithPlainLoops) {
  for (const std::size_t n : {3U, 5U}) {
    SCOPED_TRACE(testing::Message() << "n " << n);
    const auto size = static_cast<sunindextype>(n);
    const Entries a = random_entries(n);
    const Entries b = random_entries(n);
    const double c = -0.37;
    Matrix m = make_small_dense_matrix(size, context_);
    Matrix other = make_small_dense_matrix(size, context_);
    fill(m.get(), a);
    fill(other.get(), b);

    Entries expected(n * n);
    for (std::size_t k = 0; k < n * n; ++k) expected[k] = c * a[k] + b[k];
    ASSERT_EQ(SUNMatScaleAdd(c, m.get(), other.get()), SUNMAT_SUCCESS);
    EXPECT_EQ(entries(m.get()), expected);

    fill(m.get(), a);
    for (std::size_t k = 0; k < n * n; ++k) expected[k] = c * a[k] + (k % (n + 1) == 0 ? 1.0 : 0.0);
    ASSERT_EQ(SUNMatScaleAddI(c, m.get()), SUNMAT_SUCCESS);
    EXPECT_EQ(entries(m.get()), expected);

    fill(m.get(), a);
    ASSERT_EQ(SUNMatCopy(m.get(), other.get()), SUNMAT_SUCCESS);
    EXPECT_EQ(entries(other.get()), a);

    const Values x = random_values(n);
    Vector xv = make_serial_vector(size, context_);
    Vector yv = make_serial_vector(size, context_);
    std::copy(x.begin(), x.end(), NV_DATA_S(xv.get()));
    ASSERT_EQ(SUNMatMatvec(m.get(), xv.get(), yv.get()), SUNMAT_SUCCESS);
    Values y(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) y[i] += a[i + j * n] * x[j];
    EXPECT_EQ(values(yv.get()), y);
    EXPECT_EQ(SUNMatMatvec(m.get(), xv.get(), xv.get()), SUNMAT_ILL_INPUT);  // y would overwrite x

    ASSERT_EQ(SUNMatZero(m.get()), SUNMAT_SUCCESS);
    EXPECT_EQ(entries(m.get()), Entries(n * n, 0.0));
  }
  // Matrices of different sizes are refused, as SUNDIALS' own operations refuse them.
  Matrix small = make_small_dense_matrix(3, context_);
  Matrix large = make_small_dense_matrix(5, context_);
  EXPECT_EQ(SUNMatCopy(small.get(), large.get()), SUNMAT_ILL_INPUT);
  EXPECT_EQ(SUNMatScaleAdd(1.0, small.get(), large.get()), SUNMAT_ILL_INPUT);
}

TEST_F(SmallDense, ClonesKeepTheReplacedOperations) {
  for (const sunindextype n : {3, 5}) {
    Matrix plain = make_dense_matrix(n, n, context_);
    Matrix m = make_small_dense_matrix(n, context_);
    EXPECT_EQ(SUNMatGetID(m.get()), SUNMATRIX_DENSE);
    EXPECT_NE(m->ops->scaleaddi, plain->ops->scaleaddi);
    Matrix clone(SUNMatClone(m.get()));
    ASSERT_NE(clone, nullptr);
    Matrix clone_of_clone(SUNMatClone(clone.get()));
    ASSERT_NE(clone_of_clone, nullptr);
    for (const Matrix* c : {&clone, &clone_of_clone}) {
      const SUNMatrix_Ops ops = (*c)->ops;
      EXPECT_EQ(SUNDenseMatrix_Rows(c->get()), n);
      EXPECT_EQ(SUNDenseMatrix_Columns(c->get()), n);
      EXPECT_EQ(ops->clone, m->ops->clone);
      EXPECT_EQ(ops->zero, m->ops->zero);
      EXPECT_EQ(ops->copy, m->ops->copy);
      EXPECT_EQ(ops->scaleadd, m->ops->scaleadd);
      EXPECT_EQ(ops->scaleaddi, m->ops->scaleaddi);
      EXPECT_EQ(ops->matvec, m->ops->matvec);
    }
  }
}

TEST_F(SmallDense, SolverDescribesItselfAsADirectCustomSolver) {
  Vector x = make_serial_vector(3, context_);
  Matrix m = make_small_dense_matrix(3, context_);
  LinearSolver s = make_small_dense_solver(x, m, context_);
  EXPECT_EQ(SUNLinSolGetType(s.get()), SUNLINEARSOLVER_DIRECT);
  EXPECT_EQ(SUNLinSolGetID(s.get()), SUNLINEARSOLVER_CUSTOM);
  long int real_words = -1;
  long int integer_words = -1;
  EXPECT_EQ(SUNLinSolSpace(s.get(), &real_words, &integer_words), SUNLS_SUCCESS);
  EXPECT_EQ(real_words, 0);
  EXPECT_EQ(integer_words, 5);
  // A matrix of another size is refused at setup instead of being read out of bounds.
  Matrix large = make_small_dense_matrix(5, context_);
  EXPECT_EQ(SUNLinSolSetup(s.get(), large.get()), SUNLS_ILL_INPUT);
  EXPECT_EQ(SUNLinSolLastFlag(s.get()), SUNLS_ILL_INPUT);
}

TEST_F(SmallDense, MismatchedMatrixAndVectorAreRefused) {
  Vector x = make_serial_vector(3, context_);
  Matrix m = make_small_dense_matrix(5, context_);
  EXPECT_THROW((void)make_small_dense_solver(x, m, context_), InvalidInput);
}

}  // namespace
}  // namespace restitution::sundials
