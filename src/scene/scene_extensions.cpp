#include "scene/scene_extensions.hpp"

#include <fmt/core.h>

namespace restitution::scene::detail {

void add_approximations(const Sweep& sweep, const std::vector<double>& /*zeta*/, SweepExtras& extras) {
  if (!sweep.compare_series) return;
  extras.notes.emplace_back(
      "series comparison: not available in this build (the series module with the published tables has not "
      "been merged)");
}

void add_power_law_fits(const Sweep& sweep, const std::vector<double>& /*zeta*/,
                        const std::vector<const CollisionResult*>& /*results*/, SweepExtras& extras) {
  if (!sweep.fit) return;
  extras.notes.emplace_back(
      "power-law fit: not available in this build (the asymptotics module has not been merged)");
}

std::string study_note(const ExternalStudy& study) {
  return fmt::format("{} study '{}': not available in this build (its module has not been merged)",
                     study.kind, study.name);
}

}  // namespace restitution::scene::detail
