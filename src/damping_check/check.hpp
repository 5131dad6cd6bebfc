// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The ε a damping recipe really produces: the recipe's law member and ζ (recipes.hpp) solved with the
// collision solver, per clamp (on: the force is clamped at zero, the collision ends where it vanishes, the
// delayed-recovery end; off: it ends where the overlap vanishes, the naive end) and per impact speed.
#include <optional>
#include <vector>

#include "damping_check/recipes.hpp"
#include "restitution/collision_solver.hpp"

namespace restitution::damping_check {

// The DEM codes' words for the two ends (`--clamp on|off`): each clamp is one CollisionEnd (end_for), named
// as the codes' documentation names it; "both" is the ends' kBothEnds.
enum class Clamp { on, off };
const char* clamp_name(Clamp clamp);  // "on" | "off"
CollisionEnd end_for(Clamp clamp);    // on: delayed_recovery, off: naive
// "on" | "off" | "both" -> the clamps to check; throws InvalidInput naming the value otherwise.
std::vector<Clamp> clamps_from_name(const std::string& name);

struct CheckRequest {
  Recipe recipe = Recipe::lammps_tsuji;
  double eps_requested = 0.5;
  std::vector<Clamp> clamps{Clamp::on, Clamp::off};
  double reference_velocity_m_s = 1.0;          // v_ref of the speed-dependent recipes
  std::vector<double> speeds_m_s{1.0};          // ignored by speed-independent recipes (one point, no speed)
  double tolerance = SolveOptions{}.tolerance;  // accuracy of each ε (SolveOptions::tolerance)
};

struct CheckPoint {
  Clamp clamp = Clamp::on;
  std::optional<double> velocity_m_s;  // empty for a speed-independent recipe
  double zeta = 0.0;
  // Empty where the end does not exist: without the clamp, a Tsuji member with ζ >= sqrt(5) is overdamped
  // and the overlap never returns to 0 (the spheres never separate: ε = 0 in the limit).
  std::optional<double> actual_eps;
  // The ε of the same clamp at the calibration speed (the reference speed the recipe is set up at; for a
  // speed-independent recipe the one ε). Empty where that end does not exist.
  std::optional<double> eps_at_calibration;
  // Two different things, kept apart (docs/damping.md): the recipe's own error where it is set up,
  // (ε(v_cal) - requested) / requested, and the physical speed dependence of ε away from there,
  // ε(v) / ε(v_cal) - 1 (0 for a speed-independent recipe). Their product form:
  // ε(v) / requested = (1 + recipe error) (1 + speed dependence). Empty where an end does not exist.
  [[nodiscard]] std::optional<double> recipe_error_at_calibration_speed(double requested) const {
    if (!eps_at_calibration) return std::nullopt;
    return (*eps_at_calibration - requested) / requested;
  }
  [[nodiscard]] std::optional<double> speed_dependence() const {
    if (!actual_eps || !eps_at_calibration) return std::nullopt;
    return *actual_eps / *eps_at_calibration - 1.0;
  }
};

struct CheckResult {
  RecipeSetting setting;
  std::vector<CheckPoint> points;  // per clamp (in request order), then per speed
};

// Throws InvalidInput for a request out of range (eps, speeds, tolerance, an empty clamp list),
// NumericalFailure when a solve fails.
CheckResult check_recipe(const CheckRequest& request, CollisionSolver& solver);

// `request` checked at each requested ε of `eps_requested` in turn (its own eps_requested is not read): one
// result per ε, in that order (`damping-check --map`).
std::vector<CheckResult> check_recipe_at(CheckRequest request, const std::vector<double>& eps_requested,
                                         CollisionSolver& solver);

// `points` impact speeds [m/s] spaced evenly in log v from v_min to v_max (v_min alone for one point).
// Throws InvalidInput naming the bad bound or count.
inline constexpr int kMaxSpeedPoints = 1000;  // speed_grid's largest `points`
std::vector<double> speed_grid(double v_min_m_s, double v_max_m_s, int points);

// The requested ε of the map: 0.05, 0.10, ..., 0.95 and 0.99.
std::vector<double> map_eps_grid();

}  // namespace restitution::damping_check
