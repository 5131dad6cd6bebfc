// SPDX-License-Identifier: BSD-3-Clause
// Which requests a law can honour, whatever the engine: engines call this before they integrate, so that
// no engine needs another's headers to refuse the same requests. The options alone are the solver's to check
// (check_solve_options, src/solver/solve_options.cpp), before it hands the request to an engine.
#include <fmt/core.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

#include "engine/solve_request.hpp"
#include "restitution/errors.hpp"

namespace restitution {
namespace {

// The one conditioning check (docs/accuracy.md, "Conditioning"): rounding inside a double solve perturbs the
// result like a relative change of ζ by rounding_gain · DBL_EPSILON, which ε amplifies by κ = |d ln ε / d ln
// ζ| (a ~1e6 near critical damping); and the answer must be one the engine resolves.
void check_conditioning(const ContactLaw& law, const SolveOptions& options, const EngineRounding& engine) {
  const ContactLaw::Conditioning c = law.input_conditioning(options.ends);
  const double smallest_eps = std::max(engine.smallest_eps, DBL_MIN);
  if (c.log_eps < std::log(smallest_eps)) {
    throw InvalidInput(fmt::format(
        "the naive end of law {} at {}={} has eps = 10^{:.1f} (closed form), below the smallest eps method "
        "{} "
        "resolves ({:.3g}: {}); ask for a {} further from critical damping or the delayed-recovery end",
        law_name(law.kind()), law.parameter_name(), law.parameter(), c.log_eps / M_LN10, engine.method,
        smallest_eps, engine.smallest_eps > DBL_MIN ? engine.smallest_why : "the smallest normal double",
        law.parameter_name()));
  }
  const double deliverable = engine.rounding_gain * c.condition * DBL_EPSILON;
  if (options.tolerance < deliverable) {
    throw InvalidInput(fmt::format(
        "the naive end of law {} at {}={} is ill-conditioned (d ln eps / d ln zeta = {:.3g}, growing near "
        "critical damping): rounding lets method {} deliver only tolerance >= {:.2g}, got {:g}; ask for that "
        "tolerance or the delayed-recovery end",
        law_name(law.kind()), law.parameter_name(), law.parameter(), c.condition, engine.method, deliverable,
        options.tolerance));
  }
}

}  // namespace

void check_solve_request(const ContactLaw& law, const SolveOptions& options, const EngineRounding& engine) {
  require_served_zeta(law.zeta());
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
        law_name(law.kind()), law.zeta(), law.critical_zeta()));
  }
  check_conditioning(law, options, engine);
}

}  // namespace restitution
