// SPDX-License-Identifier: BSD-3-Clause
// Numerical failures of the CVODE engine become NumericalFailure messages that name ζ, the end(s), the
// tolerance, the method and CVODE's flag; each cause is forced here on purpose.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"

namespace restitution {
namespace {

std::string failure_message(const ContactLaw& law, const SolveOptions& options) {
  CollisionSolver solver;
  try {
    solver.solve(law, options);
  } catch (const NumericalFailure& e) {
    return e.what();
  }
  return "no failure";
}

void expect_names(const std::string& message, const std::vector<std::string>& parts) {
  for (const std::string& part : parts)
    EXPECT_NE(message.find(part), std::string::npos) << part << " in\n" << message;
}

TEST(NumericalFailure, TooMuchWorkNamesZetaEndToleranceAndFlag) {
  SolveOptions options;
  options.tolerance = 1e-9;
  options.max_steps_per_phase = 3;
  options.ends = EndSet{CollisionEnd::delayed_recovery};
  for (const Method method : {Method::bdf, Method::adams}) {
    options.method = method;
    const std::string message = failure_message(ContactLaw::hertz_natural(2.5), options);
    // CV_TOO_MUCH_WORK is flag -1.
    expect_names(message, {"too much work", "flag -1", "zeta=2.5", "the delayed-recovery end",
                           "tolerance 1e-09", std::string("method ") + method_name(method)});
  }
}

TEST(NumericalFailure, NoEndBeforeTheTimeLimit) {
  // Without stiffness nor damping the spheres never stop approaching: no maximal compression and no end
  // before the time limit. The factories would refuse nothing here: built unchecked.
  const ContactLaw free_flight = ContactLaw::unchecked(LawKind::viscoelastic_hertz, 0.0, 0.0);
  SolveOptions options;
  options.tolerance = 1e-6;
  expect_names(failure_message(free_flight, options),
               {"no end of the collision before tau=", "zeta=0", "both ends", "tolerance 1e-06"});
}

TEST(NumericalFailure, NonFiniteRightHandSideIsAFailureNotANumber) {
  // A law whose force is not a number (a broken law built by hand): CVODE's error test or corrector
  // fails repeatedly; what comes back must be an error naming the flag, never a NaN ε.
  const ContactLaw broken =
      ContactLaw::unchecked(LawKind::viscoelastic_hertz, 1.0, std::numeric_limits<double>::quiet_NaN());
  SolveOptions options;
  options.tolerance = 1e-8;
  for (const Method method : {Method::bdf, Method::adams}) {
    options.method = method;
    CollisionSolver solver;
    try {
      const CollisionResult r = solver.solve(broken, options);
      ADD_FAILURE() << "solved a NaN law: eps "
                    << (r[CollisionEnd::naive] ? r[CollisionEnd::naive]->eps : -1.0);
    } catch (const NumericalFailure& e) {
      expect_names(e.what(), {"zeta=1", "tolerance 1e-08", std::string("method ") + method_name(method)});
      EXPECT_TRUE(std::string(e.what()).find("flag -") != std::string::npos ||
                  std::string(e.what()).find("not finite") != std::string::npos)
          << e.what();
    }
  }
}

TEST(NumericalFailure, RepeatedConvergenceFailuresNameCvodesFlag) {
  // ζ = 1e300 is far beyond what double-precision BDF can follow: the Newton corrector fails repeatedly at
  // the first step (CV_CONV_FAILURE, flag -4).
  SolveOptions options;
  options.method = Method::bdf;
  expect_names(failure_message(ContactLaw::hertz_natural(1e300), options),
               {"CVODE failed", "flag -4", "zeta=1e+300", "both ends", "tolerance 1e-10", "method bdf",
                "try a larger tolerance"});
}

TEST(NumericalFailure, TheSolverIsUsableAfterAFailure) {
  CollisionSolver solver;
  SolveOptions starved;
  starved.max_steps_per_phase = 2;
  EXPECT_THROW(solver.solve(ContactLaw::hertz_natural(1.0), starved), NumericalFailure);
  const SolveOptions normal;
  CollisionSolver fresh;
  EXPECT_EQ(solver.solve(ContactLaw::hertz_natural(1.0), normal)[CollisionEnd::naive]->eps,
            fresh.solve(ContactLaw::hertz_natural(1.0), normal)[CollisionEnd::naive]->eps);
}

TEST(NumericalFailure, MaxStepsMustBePositive) {
  SolveOptions options;
  options.max_steps_per_phase = 0;
  CollisionSolver solver;
  EXPECT_THROW(solver.solve(ContactLaw::hertz_natural(1.0), options), InvalidInput);
}

}  // namespace
}  // namespace restitution
