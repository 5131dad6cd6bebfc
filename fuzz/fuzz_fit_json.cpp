// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the fit JSON that `calibrate --from-fit` and `dem --from-fit` read
// (fit/fit_report_reader.hpp). Any text must give a carry-over that keeps the invariants the reader promises,
// or InvalidInput naming the file; what the carry-over then gives at a few speeds must keep them too.
// Anything else is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>

#include "fit/fit_report_reader.hpp"
#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace {

using restitution::FitInterval;

// low <= value <= high where a number, and NaN exactly where the flag says "edge".
bool holds(const FitInterval& i, double value) {
  if (i.low_at_edge != std::isnan(i.low) || i.high_at_edge != std::isnan(i.high)) return false;
  return (i.low_at_edge || i.low <= value) && (i.high_at_edge || value <= i.high);
}

bool contains(const FitInterval& outer, const FitInterval& inner) {
  return (outer.low_at_edge || (!inner.low_at_edge && outer.low <= inner.low)) &&
         (outer.high_at_edge || (!inner.high_at_edge && inner.high <= outer.high));
}

void check_carry_over(const restitution::FitCarryOver& fit) {
  const double g = restitution::characteristic_velocity_m_s(fit.beta);
  if (!(std::isfinite(fit.beta) && fit.beta > 0.0 && std::isfinite(g) && g > 0.0)) std::abort();
  if (!holds(fit.ci68, fit.beta) || !holds(fit.ci95, fit.beta) || !contains(fit.ci95, fit.ci68)) std::abort();
  if ((!fit.ci95.low_at_edge && fit.ci95.low < 0.0) || fit.points == 0) std::abort();
  if (fit.chosen >= fit.fits.size()) std::abort();
  if (fit.rejection.better_fit && *fit.rejection.better_fit >= fit.fits.size()) std::abort();
  for (const double v : {1e-3, 1.0, 1e3}) {
    try {
      const restitution::FittedEps e =
          restitution::fitted_eps_at_speed(fit.beta, fit.ci68, fit.ci95, fit.end, v);
      if (!(e.eps >= 0.0 && e.eps <= 1.0) || !holds(e.ci68, e.eps) || !holds(e.ci95, e.eps)) std::abort();
    } catch (const restitution::InvalidInput& e) {
      // Only the domain check may refuse: β's ζ at this speed beyond the checked range.
      if (std::string(e.what()).find("outside the checked range") == std::string::npos) std::abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace restitution;
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const std::optional<CollisionEnd> end :
       {std::optional<CollisionEnd>(), std::optional<CollisionEnd>(CollisionEnd::naive),
        std::optional<CollisionEnd>(CollisionEnd::delayed_recovery)}) {
    try {
      const FitCarryOver fit = parse_fit_report(text, "f.json", end);
      if (end && fit.end != *end) std::abort();
      check_carry_over(fit);
    } catch (const InvalidInput& e) {
      if (std::string(e.what()).rfind("f.json: ", 0) != 0) std::abort();
    }
  }
  return 0;
}
