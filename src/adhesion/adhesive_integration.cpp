// SPDX-License-Identifier: BSD-3-Clause
#include "adhesion/adhesive_integration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "adhesion/jkr_branch.hpp"
#include "adhesion/sjkr_branch.hpp"
#include "cvode/event_driver.hpp"
#include "restitution/errors.hpp"

namespace restitution::adhesion {
namespace {

// State: position (s or u), velocity p = dδ/dt (scaled), time, viscous work; the driver's independent
// variable is σ with dt = δ'(s) dσ (JKR) or dt = u dσ (DMT), which makes the rates polynomial in s^{1/2} or
// u: no singularity at the textbook break s = 1/2 (where δ'(s) = 0), at δ = 0 or at p = 0.
constexpr int kSize = 4;
enum Event { kBreak = 0, kMaxCompression = 1, kTurned = 2, kBound = 3 };

void derivatives(const ScaledAdhesion& scaled, const double* y, double* rates) {
  const double position = y[0];
  const double p = y[1];
  const double c = scaled.damping;
  if (scaled.model == AdhesiveModel::dmt || scaled.model == AdhesiveModel::sjkr) {
    const double u = position;
    const double force =
        scaled.model == AdhesiveModel::dmt ? u * u * u - 1.0 : sjkr_force(scaled.sjkr_radii, u);
    rates[0] = 0.5 * p;
    rates[1] = -u * (force + c * u * p);
    rates[2] = u;
    rates[3] = c * u * u * p * p;
    return;
  }
  const double s = std::max(position, 1e-3);  // trial steps never reach s ≈ 0; the guard keeps sqrt real
  const double slope = jkr_overlap_slope(s);
  rates[0] = p;
  rates[2] = slope;
  if (scaled.model == AdhesiveModel::jkr_lammps) {  // damp·m*·a·δ̇ per unit mass: c s p
    rates[1] = -slope * (jkr_force(s) + c * s * p);
    rates[3] = c * s * p * p * slope;
  } else {  // A·δ̇·dF/dδ per unit mass, times dt/dσ = δ'(s): c p f'(s)
    const double force_slope = jkr_force_slope(s);
    rates[1] = -slope * jkr_force(s) - c * p * force_slope;
    rates[3] = c * p * p * force_slope;
  }
}

double energy(const ScaledAdhesion& scaled, const double* y) {
  return 0.5 * y[1] * y[1] + branch_potential(scaled, y[0]);
}

detail::EventSystem adhesive_system(const ScaledAdhesion& scaled) {
  using detail::Crossing;
  using detail::DriverPoint;
  detail::EventSystem system;
  system.size = kSize;
  system.rates = [&scaled](const DriverPoint& point, double* rates) { derivatives(scaled, point.y, rates); };
  system.events = {
      {"break", [&scaled](const DriverPoint& x) { return x.y[0] - scaled.break_radius; }, Crossing::falling,
       true},
      {"maximal compression", [](const DriverPoint& x) { return x.y[1]; }, Crossing::falling, false},
      {"turned (bound)", [](const DriverPoint& x) { return x.y[1]; }, Crossing::rising, true},
      // Kinetic + branch energy below the bound level: the break is out of reach (damping only takes energy).
      {"bound", [&scaled](const DriverPoint& x) { return energy(scaled, x.y) - scaled.bound_level; },
       Crossing::falling, true},
  };
  return system;
}

}  // namespace

ScaledEnd integrate_adhesive(const ScaledAdhesion& scaled, double impact_speed, double tolerance) {
  const bool from_touch = scaled.model == AdhesiveModel::dmt || scaled.model == AdhesiveModel::sjkr;
  const double start = from_touch ? 0.0 : kSnapInRadius;
  // Magnitudes for the absolute tolerances: the elastic energy ½V² reaches the position ~ (V²)^{1/5} at
  // maximal compression (both branches grow as position^5 in energy).
  const double kinetic = 0.5 * impact_speed * impact_speed + scaled.break_energy + 1.0;
  const double position_scale = std::max(1.0, std::pow(kinetic, 0.2)) + start;
  const double speed_scale = std::sqrt(2.0 * kinetic);
  const double time_scale = position_scale * position_scale / speed_scale + 1.0;
  // σ runs like time over the rate δ'(s) ~ 2s (JKR) or u (DMT): the contact time scale bounds its steps, and
  // an end not reached by many such times is a failure (the bound event stops every creep before).
  const double sigma_scale = time_scale / std::max(1.0, position_scale);

  detail::DriverSettings settings;
  settings.method = detail::Multistep::adams;
  settings.corrector = detail::Corrector::newton;  // difference-quotient Jacobian: strong damping is stiff
  // CVODE's global error on this problem is ~100× its local tolerance (measured against the long-double
  // reference of tests/adhesion_reference.hpp): the plan asks 1/1000 of T, at least 1e-15.
  settings.relative_tolerance = std::max(1e-3 * tolerance, 1e-15);
  const double rtol = settings.relative_tolerance;
  settings.absolute_tolerance = {rtol * position_scale, rtol * speed_scale, rtol * time_scale,
                                 rtol * kinetic};
  settings.max_step = 0.05 * sigma_scale;
  settings.stop = 1e6 * sigma_scale;
  settings.max_steps = 200000;
  settings.variable_name = "sigma";

  sundials::Context context;
  detail::EventDriver driver(adhesive_system(scaled), settings, context);
  const std::array<double, kSize> y0{start, impact_speed, 0.0, 0.0};
  driver.start(0.0, y0.data());
  ScaledEnd end;
  const auto last = driver.run([&end](detail::DriverStep& step) {
    if (step.event(kMaxCompression)) end.max_position = step.y[0];
    return detail::AfterEvent::go_on;
  });
  if (last.reached_stop || !(last.event(kBreak) || last.event(kTurned) || last.event(kBound))) {
    throw NumericalFailure(
        fmt::format("the adhesive collision at scaled impact speed {} reached neither the "
                    "break nor a bound state",
                    impact_speed));
  }
  const double* y = last.y.data();
  end.outcome =
      last.event(kBreak) && !last.event(kTurned) ? AdhesiveOutcome::bounced : AdhesiveOutcome::stuck;
  end.position = y[0];
  end.velocity = y[1];
  end.time = y[2];
  end.viscous_work = y[3];
  end.energy_margin =
      end.outcome == AdhesiveOutcome::bounced ? 0.5 * y[1] * y[1] : energy(scaled, y) - scaled.break_energy;
  end.stats = driver.stats();
  return end;
}

}  // namespace restitution::adhesion
