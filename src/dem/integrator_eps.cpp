// SPDX-License-Identifier: BSD-3-Clause
#include "dem/integrator_eps.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "restitution/contact_law.hpp"
#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution::dem {
namespace {

// A collision lasts about 3 natural times; a thousand is far past any end, also the naive one at large ζ.
constexpr double kLongestCollision = 1000.0;

struct Law {
  double zeta = 0.0;
  double natural_time_s = 0.0;
};

Law law_at(const Pair& pair, double dissipative_constant_s, double velocity_m_s) {
  const double k =
      hertz_stiffness(pair.effective_modulus_pa, pair.effective_radius_m) / pair.effective_mass_kg;
  return {zeta_from(hertz_constants(k, dissipative_constant_s).beta, velocity_m_s),
          natural_time_scale_s(k, velocity_m_s)};
}

struct PhaseErrors {
  double mean = 0.0;
  double worst = 0.0;
};

PhaseErrors phase_errors(double zeta, CollisionEnd end, double step, double eps_law) {
  PhaseErrors e;
  for (int p = 0; p < kIntegratorPhases; ++p) {
    const double d = verlet_eps(zeta, end, step, (p + 0.5) / kIntegratorPhases) - eps_law;
    e.mean += d / kIntegratorPhases;
    if (std::abs(d) > std::abs(e.worst)) e.worst = d;
  }
  return e;
}

EndResult law_end(double zeta, CollisionEnd end, double tolerance, CollisionSolver& solver) {
  SolveOptions options;
  options.ends = EndSet{end};
  options.tolerance = tolerance;
  options.keep_trajectory = false;
  return end_of(solver.solve(ContactLaw::hertz_natural(zeta), options), end);
}

}  // namespace

double verlet_eps(double zeta, CollisionEnd end, double step, double phase) {
  const bool clamp = end == CollisionEnd::delayed_recovery;
  double x = -phase * step;  // the overlap
  double u = 1.0;            // its rate, x'
  double a = 0.0;            // x''
  bool touched = false;
  const auto steps = static_cast<long>(std::ceil(kLongestCollision / step));
  for (long n = 0; n < steps; ++n) {
    u += 0.5 * step * a;
    x += step * u;
    if (x > 0.0) {
      // The force at the new positions and the half-step velocity, as the pair style sees them.
      const double s = std::sqrt(x);
      a = -(x * s + zeta * s * u);
      if (clamp) a = std::min(a, 0.0);
      touched = true;
    } else {
      a = 0.0;
      if (touched) return -u;
    }
    u += 0.5 * step * a;
  }
  throw NumericalFailure(
      fmt::format("the integrated collision at zeta = {} did not end in {} steps", zeta, steps));
}

double contact_duration_s(const Pair& pair, double dissipative_constant_s, CollisionEnd end,
                          double velocity_m_s, double tolerance, CollisionSolver& solver) {
  const Law law = law_at(pair, dissipative_constant_s, velocity_m_s);
  return law_end(law.zeta, end, tolerance, solver).tau * law.natural_time_s;
}

IntegratorError integrator_error(const Pair& pair, double dissipative_constant_s, CollisionEnd end,
                                 double velocity_m_s, double time_step_s, double tolerance,
                                 CollisionSolver& solver) {
  const Law law = law_at(pair, dissipative_constant_s, velocity_m_s);
  const EndResult exact = law_end(law.zeta, end, tolerance, solver);
  IntegratorError e;
  e.velocity_m_s = velocity_m_s;
  e.contact_duration_s = exact.tau * law.natural_time_s;
  e.eps_law = exact.eps;
  if (!(time_step_s > 0.0) || time_step_s > 0.2 * e.contact_duration_s) {
    throw InvalidInput(fmt::format(
        "--timestep must be > 0 and at most a fifth of the contact duration ({:.4g} s at {} m/s), got {}",
        e.contact_duration_s, velocity_m_s, time_step_s));
  }
  const PhaseErrors p = phase_errors(law.zeta, end, time_step_s / law.natural_time_s, exact.eps);
  e.mean_error = p.mean;
  e.worst_error = p.worst;
  return e;
}

double largest_time_step_s(const Pair& pair, double dissipative_constant_s, CollisionEnd end,
                           double velocity_m_s, double max_eps_error, double tolerance,
                           CollisionSolver& solver) {
  if (!(max_eps_error >= 1e-7 && max_eps_error <= 0.1)) {
    throw InvalidInput(fmt::format("--max-eps-error must be in [1e-7, 0.1], got {}", max_eps_error));
  }
  const Law law = law_at(pair, dissipative_constant_s, velocity_m_s);
  const double eps_law = law_end(law.zeta, end, tolerance, solver).eps;
  const auto fits = [&](double step) {
    return std::abs(phase_errors(law.zeta, end, step, eps_law).worst) <= max_eps_error;
  };
  // The error grows about linearly with the step: halve from half a natural time until it fits, then bisect
  // (in log h) between the last step that fails and the first that fits.
  double bad = 0.5;
  double good = bad;
  while (!fits(good)) {
    bad = good;
    good *= 0.5;
  }
  if (good == bad) return good * law.natural_time_s;
  while (bad / good > 1.01) {
    const double mid = std::sqrt(good * bad);
    (fits(mid) ? good : bad) = mid;
  }
  return good * law.natural_time_s;
}

}  // namespace restitution::dem
