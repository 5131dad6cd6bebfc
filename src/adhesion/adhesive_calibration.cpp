// SPDX-License-Identifier: BSD-3-Clause
#include "restitution/adhesive_calibration.hpp"

#include <fmt/format.h>

#include "restitution/adhesive_contact.hpp"
#include "restitution/errors.hpp"

namespace restitution {
namespace {

struct Trial {
  AdhesiveContact contact;
  double eps = 0.0;
};

}  // namespace

AdhesiveDampingCalibration calibrate_adhesive_damping(AdhesiveModel model, const Material& material,
                                                      double surface_energy_j_per_m2, double eps,
                                                      double impact_speed_m_per_s, double tolerance) {
  if (!(eps > 0.0 && eps < 1.0)) {
    throw InvalidInput(fmt::format("the measured eps must lie in (0, 1), got {}", eps));
  }
  AdhesiveDampingCalibration out;
  auto trial = [&](double a_s) {
    Trial t{adhesive_contact_of(model, material, surface_energy_j_per_m2, a_s), 0.0};
    t.eps = solve_adhesive(t.contact, impact_speed_m_per_s, tolerance).eps;
    ++out.solves;
    return t;
  };
  const AdhesiveContact elastic = adhesive_contact_of(model, material, surface_energy_j_per_m2, 0.0);
  const AdhesiveCollision undamped = solve_adhesive(elastic, impact_speed_m_per_s, tolerance);
  ++out.solves;
  out.elastic_eps = undamped.eps;
  if (!(undamped.eps > eps)) {
    throw InvalidInput(fmt::format(
        "eps = {} at {} m/s is not below the undamped {} model's eps = {} ({}): damping only lowers eps; a "
        "larger surface energy or another model is needed",
        eps, impact_speed_m_per_s, adhesive_model_name(model), undamped.eps,
        adhesive_outcome_name(undamped.outcome)));
  }
  // ε falls from the elastic value to 0 (stuck) as A grows: bracket upwards, then bisect.
  double low = 0.0;
  double high = 1e-3 * undamped.contact_time_s;
  Trial at_high = trial(high);
  for (int k = 0; at_high.eps > eps; ++k) {
    if (k == 200)
      throw NumericalFailure("calibrate_adhesive_damping: no damping brings eps down to the target");
    low = high;
    high *= 4.0;
    at_high = trial(high);
  }
  Trial best = at_high;
  while (high - low > tolerance * high) {
    const double middle = 0.5 * (low + high);
    const Trial at_middle = trial(middle);
    (at_middle.eps > eps ? low : high) = middle;
    if (at_middle.eps <= eps) best = at_middle;
  }
  out.dissipative_constant_s = high;
  out.contact = best.contact;
  out.eps_at_velocity = best.eps;
  return out;
}

}  // namespace restitution
