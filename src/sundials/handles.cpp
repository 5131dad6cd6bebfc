// SPDX-License-Identifier: BSD-3-Clause
#include "sundials/handles.hpp"

#include <fmt/core.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "restitution/errors.hpp"

namespace restitution::sundials {

void check_flag(int flag, const char* call) {
  if (flag < 0) throw NumericalFailure(fmt::format("SUNDIALS call {} failed with flag {}", call, flag));
}

void check_created(const void* object, const char* call) {
  if (object == nullptr) throw NumericalFailure(fmt::format("SUNDIALS call {} returned no object", call));
}

Context::Context() {
  check_flag(SUNContext_Create(nullptr, &context_), "SUNContext_Create");
}

Context::~Context() {
  SUNContext_Free(&context_);
}

Vector make_serial_vector(sunindextype length, const Context& context) {
  Vector v(N_VNew_Serial(length, context.get()));
  check_created(v.get(), "N_VNew_Serial");
  return v;
}

Matrix make_dense_matrix(sunindextype rows, sunindextype columns, const Context& context) {
  Matrix m(SUNDenseMatrix(rows, columns, context.get()));
  check_created(m.get(), "SUNDenseMatrix");
  return m;
}

CvodeMemory::CvodeMemory(int linear_multistep_method, const Context& context)
    : memory_(CVodeCreate(linear_multistep_method, context.get())) {
  check_created(memory_, "CVodeCreate");
  check_flag(CVodeSetErrHandlerFn(memory_, &CvodeMemory::record_error, this), "CVodeSetErrHandlerFn");
}

CvodeMemory::~CvodeMemory() {
  CVodeFree(&memory_);
}

void CvodeMemory::record_error(int code, const char* module, const char* function,
                               char* message,  // NOLINT(readability-non-const-parameter): CVErrHandlerFn
                               void* self) noexcept {
  try {
    static_cast<CvodeMemory*>(self)->last_error_ =
        fmt::format("{} in {}: {} (flag {})", module != nullptr ? module : "",
                    function != nullptr ? function : "", message != nullptr ? message : "", code);
  } catch (...) {  // NOLINT(bugprone-empty-catch): an error text must never throw through CVODE
  }
}

SolverStats cvode_phase_stats(void* cvode_memory) {
  SolverStats stats;
  long value = 0;
  CVodeGetNumSteps(cvode_memory, &value);
  stats.steps = value;
  CVodeGetNumRhsEvals(cvode_memory, &value);
  stats.rhs_evaluations = value;
  CVodeGetNumGEvals(cvode_memory, &value);
  stats.root_evaluations = value;
  CVodeGetNumErrTestFails(cvode_memory, &value);
  stats.error_test_failures = value;
  CVodeGetNumNonlinSolvConvFails(cvode_memory, &value);
  stats.convergence_failures = value;
  return stats;
}

}  // namespace restitution::sundials
