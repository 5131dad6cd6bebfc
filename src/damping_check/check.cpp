// SPDX-License-Identifier: BSD-3-Clause
#include "damping_check/check.hpp"

#include <fmt/core.h>

#include <cmath>
#include <string>

#include "restitution/errors.hpp"
#include "restitution/sweep.hpp"

namespace restitution::damping_check {

const char* clamp_name(Clamp clamp) {
  return clamp == Clamp::on ? "on" : "off";
}

CollisionEnd end_for(Clamp clamp) {
  return clamp == Clamp::on ? CollisionEnd::delayed_recovery : CollisionEnd::naive;
}

std::vector<Clamp> clamps_from_name(const std::string& name) {
  if (name == "on") return {Clamp::on};
  if (name == "off") return {Clamp::off};
  if (name == kBothEnds) return {Clamp::on, Clamp::off};
  throw InvalidInput(fmt::format("clamp must be on, off or both, got '{}'", name));
}

std::vector<double> speed_grid(double v_min_m_s, double v_max_m_s, int points) {
  if (!std::isfinite(v_min_m_s) || v_min_m_s <= 0.0) {
    throw InvalidInput(
        fmt::format("the smallest impact speed must be finite and > 0 m/s, got {}", v_min_m_s));
  }
  if (!std::isfinite(v_max_m_s) || v_max_m_s < v_min_m_s) {
    throw InvalidInput(
        fmt::format("the largest impact speed must be finite and >= the smallest ({} m/s), got {}", v_min_m_s,
                    v_max_m_s));
  }
  if (points < 1 || points > kMaxSpeedPoints)
    throw InvalidInput(
        fmt::format("the number of impact speeds must be in [1, {}], got {}", kMaxSpeedPoints, points));
  // The sweep's grid: log-spaced with both ends exactly the speeds given.
  return zeta_values({.zeta_min = v_min_m_s,
                      .zeta_max = points == 1 ? v_min_m_s : v_max_m_s,
                      .points = static_cast<std::size_t>(points),
                      .logarithmic = true,
                      .variable = "velocity"});
}

std::vector<double> map_eps_grid() {
  std::vector<double> grid;
  for (int i = 1; i <= 19; ++i) grid.push_back(0.05 * i);
  grid.push_back(0.99);
  return grid;
}

CheckResult check_recipe(const CheckRequest& request, CollisionSolver& solver) {
  if (request.clamps.empty()) throw InvalidInput("no clamp to check: give on, off or both");
  const auto positive = [](double v, const char* what) {
    if (!std::isfinite(v) || v <= 0.0)
      throw InvalidInput(fmt::format("{} must be finite and > 0, got {}", what, v));
  };
  positive(request.reference_velocity_m_s, "reference velocity (m/s)");
  for (double v : request.speeds_m_s) positive(v, "impact speed (m/s)");
  SolveOptions options;
  options.tolerance = request.tolerance;
  check_solve_options(options);

  CheckResult result;
  result.setting = recipe_setting(request.recipe, request.eps_requested, request.tolerance, solver);
  std::vector<std::optional<double>> speeds;
  if (result.setting.speed_independent()) {
    speeds.emplace_back();
  } else {
    if (request.speeds_m_s.empty())
      throw InvalidInput("no impact speed to check this speed-dependent recipe at");
    speeds.assign(request.speeds_m_s.begin(), request.speeds_m_s.end());
  }
  // The ε of the member with damping ζ at the end `clamp` gives; empty where that end does not exist.
  const auto eps_for = [&](double zeta, Clamp clamp) -> std::optional<double> {
    require_checked_zeta(zeta);
    const ContactLaw law = ContactLaw::natural(result.setting.law, zeta);
    if (clamp == Clamp::off && !law.naive_end_may_exist()) return std::nullopt;
    options.ends = EndSet{end_for(clamp)};
    return end_of(solver.solve(law, options), end_for(clamp)).eps;
  };
  for (Clamp clamp : request.clamps) {
    // At the reference speed ζ is zeta_reference, the recipe's own setting (also when speed-independent).
    const std::optional<double> at_calibration = eps_for(result.setting.zeta_reference, clamp);
    for (const auto& v : speeds) {
      CheckPoint p;
      p.clamp = clamp;
      p.velocity_m_s = v;
      p.zeta = v ? result.setting.zeta_at(*v, request.reference_velocity_m_s) : result.setting.zeta_reference;
      p.actual_eps = eps_for(p.zeta, clamp);
      p.eps_at_calibration = at_calibration;
      result.points.push_back(p);
    }
  }
  return result;
}

std::vector<CheckResult> check_recipe_at(CheckRequest request, const std::vector<double>& eps_requested,
                                         CollisionSolver& solver) {
  std::vector<CheckResult> results;
  results.reserve(eps_requested.size());
  for (const double eps : eps_requested) {
    request.eps_requested = eps;
    results.push_back(check_recipe(request, solver));
  }
  return results;
}

}  // namespace restitution::damping_check
