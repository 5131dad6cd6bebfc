// SPDX-License-Identifier: BSD-3-Clause
#include "dem/adhesive_lines_common.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "restitution/errors.hpp"

namespace restitution::dem {

double round_down_2(double x) {
  const double scale = std::pow(10.0, std::floor(std::log10(x)) - 1.0);
  return std::floor(x / scale) * scale;
}

double round_up_2(double x) {
  const double scale = std::pow(10.0, std::floor(std::log10(x)) - 1.0);
  return std::ceil(x / scale) * scale;
}

std::vector<std::string> integration_lines(double skin_m, double timestep_s) {
  return {fmt::format("neighbor {} bin", skin_m), "neigh_modify delay 0 every 1 check yes",
          "fix integrate all nve/sphere", fmt::format("timestep {}", timestep_s)};
}

AdhesiveSolves solve_listed_speeds(const AdhesiveContact& contact, const std::vector<double>& speeds,
                                   double tolerance) {
  AdhesiveSolves out;
  out.sticking = sticking_speed(contact, tolerance);
  out.speeds = speeds;
  if (out.speeds.empty()) {
    if (out.sticking.speed_m_per_s == 0.0) {
      throw InvalidInput(
          fmt::format("these spheres never stick (elastic {}): give the speeds with --impact-velocity",
                      contact.model == AdhesiveModel::sjkr ? "sjkr" : "DMT"));
    }
    for (const double k : {0.97, 1.03, 1.05, 1.5, 3.0, 10.0, 100.0}) {
      out.speeds.push_back(k * out.sticking.speed_m_per_s);
    }
  }
  for (const double v : out.speeds) {
    out.collisions.push_back(solve_adhesive(contact, v, tolerance));
    const auto& c = out.collisions.back();
    if (c.outcome == AdhesiveOutcome::bounced &&
        (out.shortest_contact_s == 0.0 || c.contact_time_s < out.shortest_contact_s)) {
      out.shortest_contact_s = c.contact_time_s;
    }
    out.deepest_m = std::max(out.deepest_m, c.max_compression_m);
  }
  if (out.shortest_contact_s == 0.0) {  // every speed sticks: resolve the approach to the first turn
    for (const auto& c : out.collisions)
      out.shortest_contact_s = std::max(out.shortest_contact_s, c.contact_time_s);
  }
  return out;
}

}  // namespace restitution::dem
