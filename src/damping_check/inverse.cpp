// SPDX-License-Identifier: BSD-3-Clause
#include "damping_check/inverse.hpp"

#include <fmt/core.h>
#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <cstdint>

#include "restitution/errors.hpp"

namespace restitution::damping_check {
namespace {

// The recipe's requests are searched in [kLowest, 1 - kLowest]: the ends of (0, 1) where its formulas still
// hold (the calibrations and fits are singular at 0 and 1).
constexpr double kLowest = 1e-6;

}  // namespace

InverseResult invert_recipe(const InverseRequest& request, CollisionSolver& solver) {
  const double target = request.target_eps;
  if (!std::isfinite(target) || target <= 0.0 || target >= 1.0)
    throw InvalidInput(fmt::format("--target-eps must be in (0, 1), got {}", target));
  CheckRequest check;
  check.recipe = request.recipe;
  check.clamps = {request.clamp};
  check.reference_velocity_m_s = request.target_velocity_m_s;  // set up where the target is
  check.speeds_m_s = {request.target_velocity_m_s};
  check.tolerance = request.tolerance;
  // ε at the target speed for a request; an end that does not exist (an overdamped member without the
  // clamp) is ε -> 0 in the limit.
  const auto given = [&](double requested) {
    check.eps_requested = requested;
    return check_recipe(check, solver).points.front().actual_eps.value_or(0.0);
  };
  // Every recipe's ζ falls as the request rises and ε falls as ζ rises: the map is increasing.
  const double lowest = given(kLowest);
  const double highest = given(1.0 - kLowest);
  if (!(target >= lowest && target <= highest)) {
    throw InvalidInput(fmt::format(
        "--target-eps {} is out of reach of recipe {} with the clamp {}: its eps at {} m/s spans [{:.6g}, "
        "{:.6g}]",
        target, recipe_name(request.recipe), clamp_name(request.clamp), request.target_velocity_m_s, lowest,
        highest));
  }
  // Each ε is accurate to `tolerance`; a bracket of 1e-14 leaves the root's error to the solves.
  std::uintmax_t iterations = 200;
  const auto [a, b] = boost::math::tools::toms748_solve(
      [&](double requested) { return given(requested) - target; }, kLowest, 1.0 - kLowest, lowest - target,
      highest - target, [](double x, double y) { return std::abs(x - y) <= 1e-14; }, iterations);
  InverseResult result;
  result.eps_to_request = 0.5 * (a + b);
  check.eps_requested = result.eps_to_request;
  check.speeds_m_s = request.speeds_m_s;
  result.check = check_recipe(check, solver);
  return result;
}

std::vector<InverseResult> invert_recipe_for(InverseRequest request, const std::vector<Clamp>& clamps,
                                             CollisionSolver& solver) {
  std::vector<InverseResult> results;
  for (const Clamp clamp : clamps) {
    request.clamp = clamp;
    results.push_back(invert_recipe(request, solver));
  }
  return results;
}

}  // namespace restitution::damping_check
