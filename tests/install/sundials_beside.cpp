// SPDX-License-Identifier: BSD-3-Clause
// A consumer that links the system's SUNDIALS beside the installed restitution and calls CVODE itself
// (tests/install_consumer.sh). Its own CVode* calls must bind to the system library, which dladdr names;
// restitution's solves use the copy the library carries, whose symbols the installed archive keeps local.
// Prints "cvode_library PATH", "own_solve RELATIVE_ERROR" and "eps_delayed_recovery EPS" at zeta = 1.
#include <cvode/cvode.h>
#include <dlfcn.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <cmath>
#include <cstdio>
#include <restitution/restitution.hpp>

namespace {

// y' = -y from y(0) = 1 to t = 1 with the consumer's own CVODE (Adams, functional iteration).
int decay(realtype, N_Vector y, N_Vector ydot, void*) {
  NV_Ith_S(ydot, 0) = -NV_Ith_S(y, 0);
  return 0;
}

double own_cvode_solve() {
  SUNContext context = nullptr;
  if (SUNContext_Create(nullptr, &context) != 0) return NAN;
  N_Vector y = N_VNew_Serial(1, context);
  NV_Ith_S(y, 0) = 1.0;
  void* memory = CVodeCreate(CV_ADAMS, context);
  double at_one = NAN;
  if (memory != nullptr && CVodeInit(memory, decay, 0.0, y) == CV_SUCCESS &&
      CVodeSStolerances(memory, 1e-10, 1e-12) == CV_SUCCESS) {
    SUNNonlinearSolver fixed_point = SUNNonlinSol_FixedPoint(y, 0, context);
    realtype t = 0.0;
    if (CVodeSetNonlinearSolver(memory, fixed_point) == CV_SUCCESS &&
        CVode(memory, 1.0, y, &t, CV_NORMAL) == CV_SUCCESS) {
      at_one = NV_Ith_S(y, 0);
    }
    SUNNonlinSolFree(fixed_point);
  }
  CVodeFree(&memory);
  N_VDestroy(y);
  SUNContext_Free(&context);
  return at_one;
}

}  // namespace

int main() {
  Dl_info where{};
  if (dladdr(reinterpret_cast<void*>(&CVodeCreate), &where) == 0 || where.dli_fname == nullptr) {
    std::puts("cvode_library unknown");
    return 1;
  }
  std::printf("cvode_library %s\n", where.dli_fname);
  std::printf("own_solve %.3g\n", std::fabs(own_cvode_solve() / std::exp(-1.0) - 1.0));
  restitution::CollisionSolver solver;
  const auto result = solver.solve(restitution::ContactLaw::hertz_natural(1.0), {});
  std::printf("eps_delayed_recovery %.17g\n", result[restitution::CollisionEnd::delayed_recovery]->eps);
  return 0;
}
