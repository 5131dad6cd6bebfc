// Which requests a law can honour, whatever the engine: engines call this before they integrate, so that
// no engine needs another's headers to refuse the same requests.
#include <fmt/core.h>

#include <cmath>

#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"

namespace restitution {

void check_solve_request(const ContactLaw& law, const SolveOptions& options) {
  check_solve_options(options);
  if (law.kind() == LawKind::linear_dashpot && options.ends.contains(CollisionEnd::naive) &&
      law.parameter() >= 1.0) {
    throw InvalidInput(fmt::format(
        "the naive end does not exist for damping-ratio r={} >= 1: the overdamped dash-pot never returns to "
        "x = 0 (the 2008 paper assigns eps = 0, Eq. 10); ask for the delayed-recovery end",
        law.parameter()));
  }
  if (options.ends.contains(CollisionEnd::naive) && !law.naive_end_may_exist()) {
    // The scale-invariant members other than the dash-pot (Tsuji): ζ >= 2 sqrt(b+1) (docs/contact_laws.md).
    throw InvalidInput(fmt::format(
        "the naive end does not exist for law {} at zeta={} >= {:.17g}: the overlap approaches 0 only as "
        "tau -> infinity (eps = 0 in the sense of the overdamped dash-pot); ask for the delayed-recovery end",
        law_name(law.kind()), law.zeta(), 2.0 * std::sqrt(law.damping_exponent() + 1.0)));
  }
  if (law.kind() == LawKind::linear_dashpot && options.ends.contains(CollisionEnd::naive)) {
    // Near critical damping the naive end's two modes cancel to ω = sqrt(1 - r²) and double rounding is
    // amplified accordingly. Measured against the closed form: CVODE (BDF) misses T = 1e-9 by 1.01x at r =
    // 0.9999 (floor 1.5e-9 there), Taylor misses T = 1e-12 by 4x at r = 0.999 (floor 2.2e-12).
    const double omega_squared = (1.0 - law.parameter()) * (1.0 + law.parameter());
    const double smallest = options.method == Method::taylor
                                ? min_tolerance(Method::taylor) / std::sqrt(omega_squared)
                                : 3e-13 / omega_squared;
    if (options.tolerance < smallest) {
      throw InvalidInput(fmt::format(
          "the naive end of the dash-pot at damping-ratio {} is delivered only to tolerance >= {:.2g} by "
          "method {} (rounding grows near critical damping), got {:g}",
          law.parameter(), smallest, method_name(options.method), options.tolerance));
    }
  }
}

}  // namespace restitution
