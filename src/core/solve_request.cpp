// Which requests a law can honour, whatever the engine: engines call this before they integrate, so that
// no engine needs another's headers to refuse the same requests.
#include <fmt/core.h>

#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"

namespace restitution {

void check_solve_request(const ContactLaw& law, const SolveOptions& options) {
  check_solve_options(options);
  if (law.kind == LawKind::linear_dashpot && options.ends.naive && law.parameter >= 1.0) {
    throw InvalidInput(fmt::format(
        "the naive end does not exist for damping-ratio r={} >= 1: the overdamped dash-pot never returns to "
        "x = 0 (the 2008 paper assigns eps = 0, Eq. 10); ask for the delayed-recovery end",
        law.parameter));
  }
}

}  // namespace restitution
