// SPDX-License-Identifier: BSD-3-Clause
#include "sundials/fixed_point.hpp"

#include <memory>

namespace restitution::sundials {
namespace {

// What SUNNonlinSol_FixedPoint keeps for m = 0: the previous iterate, G(y) and their difference, the
// callbacks CVODE sets, and the counters it reads after each solve.
struct Content {
  Vector previous;
  Vector image;
  Vector change;
  SUNNonlinSolSysFn system = nullptr;
  SUNNonlinSolConvTestFn converged = nullptr;
  void* test_data = nullptr;
  int max_iterations = 3;  // SUNNonlinSol_FixedPoint's default; CVODE sets its own
  int iteration = 0;
  long iterations = 0;            // of the last solve
  long convergence_failures = 0;  // of the last solve
};

Content& content(SUNNonlinearSolver solver) {
  return *static_cast<Content*>(solver->content);
}

// The solver is called through SUNDIALS' C function table: nothing here throws.
SUNNonlinearSolver_Type type(SUNNonlinearSolver /*solver*/) noexcept {
  return SUNNONLINEARSOLVER_FIXEDPOINT;
}

int initialize(SUNNonlinearSolver solver) noexcept {
  Content& c = content(solver);
  if (c.system == nullptr || c.converged == nullptr) return SUN_NLS_MEM_NULL;
  c.iterations = 0;
  c.convergence_failures = 0;
  return SUN_NLS_SUCCESS;
}

// As SUNNonlinSolSolve_FixedPoint with m = 0: y_prev = y; y = G(y); test y - y_prev. The loops run to the
// vectors' run-time length: unrolled for 3 and 4 components they took 3 % fewer instructions per solve but
// 4 % more CPU (interleaved medians, issue 34; docs/performance.md).
int solve(SUNNonlinearSolver solver, N_Vector /*y0*/, N_Vector correction, N_Vector weights, double tolerance,
          sunbooleantype /*call_setup*/, void* memory) noexcept {
  Content& c = content(solver);
  const sunindextype size = NV_LENGTH_S(correction);
  double* y = NV_DATA_S(correction);
  double* previous = NV_DATA_S(c.previous.get());
  const double* image = NV_DATA_S(c.image.get());
  double* change = NV_DATA_S(c.change.get());
  c.iterations = 0;
  c.convergence_failures = 0;
  for (c.iteration = 0; c.iteration < c.max_iterations; ++c.iteration) {
    for (sunindextype i = 0; i < size; ++i) previous[i] = y[i];
    const int status = c.system(correction, c.image.get(), memory);
    if (status != 0) return status;
    for (sunindextype i = 0; i < size; ++i) y[i] = image[i];
    ++c.iterations;
    for (sunindextype i = 0; i < size; ++i) change[i] = y[i] - previous[i];  // N_VLinearSum(1, y, -1, prev)
    const int test = c.converged(solver, correction, c.change.get(), tolerance, weights, c.test_data);
    if (test == SUN_NLS_SUCCESS) return SUN_NLS_SUCCESS;
    if (test != SUN_NLS_CONTINUE) {
      ++c.convergence_failures;
      return test;
    }
  }
  ++c.convergence_failures;
  return SUN_NLS_CONV_RECVR;
}

int release(SUNNonlinearSolver solver) noexcept {
  if (solver == nullptr) return SUN_NLS_SUCCESS;
  delete static_cast<Content*>(solver->content);  // NOLINT(cppcoreguidelines-owning-memory): C object
  solver->content = nullptr;
  SUNNonlinSolFreeEmpty(solver);
  return SUN_NLS_SUCCESS;
}

int set_system(SUNNonlinearSolver solver, SUNNonlinSolSysFn function) noexcept {
  if (function == nullptr) return SUN_NLS_ILL_INPUT;
  content(solver).system = function;
  return SUN_NLS_SUCCESS;
}

int set_test(SUNNonlinearSolver solver, SUNNonlinSolConvTestFn function, void* data) noexcept {
  if (function == nullptr) return SUN_NLS_ILL_INPUT;
  content(solver).converged = function;
  content(solver).test_data = data;
  return SUN_NLS_SUCCESS;
}

int set_max_iterations(SUNNonlinearSolver solver, int count) noexcept {
  if (count < 1) return SUN_NLS_ILL_INPUT;
  content(solver).max_iterations = count;
  return SUN_NLS_SUCCESS;
}

int iterations(SUNNonlinearSolver solver, long* count) noexcept {
  *count = content(solver).iterations;
  return SUN_NLS_SUCCESS;
}

int current_iteration(SUNNonlinearSolver solver, int* iteration) noexcept {
  *iteration = content(solver).iteration;
  return SUN_NLS_SUCCESS;
}

int convergence_failures(SUNNonlinearSolver solver, long* count) noexcept {
  *count = content(solver).convergence_failures;
  return SUN_NLS_SUCCESS;
}

Vector clone(const Vector& template_vector) {
  Vector v(N_VClone(template_vector.get()));
  check_created(v.get(), "N_VClone");
  return v;
}

}  // namespace

NonlinearSolver make_small_fixed_point_solver(const Vector& template_vector, const Context& context) {
  auto state = std::make_unique<Content>();
  state->previous = clone(template_vector);
  state->image = clone(template_vector);
  state->change = clone(template_vector);
  SUNNonlinearSolver empty = SUNNonlinSolNewEmpty(context.get());
  check_created(empty, "SUNNonlinSolNewEmpty");
  empty->content = state.release();
  empty->ops->free = release;  // from here the handle frees the content
  NonlinearSolver solver(empty);
  solver->ops->gettype = type;
  solver->ops->initialize = initialize;
  solver->ops->solve = solve;
  solver->ops->setsysfn = set_system;
  solver->ops->setctestfn = set_test;
  solver->ops->setmaxiters = set_max_iterations;
  solver->ops->getnumiters = iterations;
  solver->ops->getcuriter = current_iteration;
  solver->ops->getnumconvfails = convergence_failures;
  return solver;
}

}  // namespace restitution::sundials
