// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// RAII ownership of the SUNDIALS C objects this project uses. Private to the library.
// Each handle owns exactly one object and frees it with the matching SUNDIALS destructor.
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nonlinearsolver.h>

#include <memory>
#include <string>

#include "restitution/solve_types.hpp"

namespace restitution::sundials {

// Throws NumericalFailure naming the SUNDIALS call when flag < 0.
void check_flag(int flag, const char* call);
// Throws NumericalFailure when a constructor returned null.
void check_created(const void* object, const char* call);

class Context {
 public:
  Context();
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  [[nodiscard]] SUNContext get() const { return context_; }

 private:
  SUNContext context_ = nullptr;
};

struct VectorDeleter {
  void operator()(N_Vector v) const { N_VDestroy(v); }
};
using Vector = std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter>;
Vector make_serial_vector(sunindextype length, const Context& context);

struct MatrixDeleter {
  void operator()(SUNMatrix m) const { SUNMatDestroy(m); }
};
using Matrix = std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixDeleter>;
Matrix make_dense_matrix(sunindextype rows, sunindextype columns, const Context& context);

struct LinearSolverDeleter {
  void operator()(SUNLinearSolver s) const { SUNLinSolFree(s); }
};
using LinearSolver = std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, LinearSolverDeleter>;

struct NonlinearSolverDeleter {
  void operator()(SUNNonlinearSolver s) const { SUNNonlinSolFree(s); }
};
using NonlinearSolver = std::unique_ptr<std::remove_pointer_t<SUNNonlinearSolver>, NonlinearSolverDeleter>;

// CVODE integrator memory. Owns the memory block and collects CVODE's error messages instead of
// letting CVODE print them (library code never prints).
class CvodeMemory {
 public:
  CvodeMemory(int linear_multistep_method, const Context& context);
  ~CvodeMemory();
  CvodeMemory(const CvodeMemory&) = delete;
  CvodeMemory& operator=(const CvodeMemory&) = delete;
  [[nodiscard]] void* get() const { return memory_; }
  // The last message CVODE reported (empty if none).
  [[nodiscard]] const std::string& last_error() const { return last_error_; }
  void clear_error() { last_error_.clear(); }

 private:
  static void record_error(int code, const char* module, const char* function, char* message,
                           void* self) noexcept;
  void* memory_ = nullptr;
  std::string last_error_;
};

// CVODE's counters since its last (re)initialisation: steps, right-hand sides, root functions, error-test and
// nonlinear convergence failures (the linear solver's are the caller's to add).
[[nodiscard]] SolverStats cvode_phase_stats(void* cvode_memory);

}  // namespace restitution::sundials
