// SPDX-License-Identifier: BSD-3-Clause
#include "restitution/calibration.hpp"

#include <fmt/core.h>

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>

#include "restitution/errors.hpp"
#include "restitution/fast.hpp"

namespace restitution {
namespace {

// log ε at the requested end from whichever of ε and 1 - ε carries the relative accuracy: 1 - ε as ε -> 1
// (log1p), ε itself when it is small (1 - ε rounds to 1 below ε ~ 1e-16 and loses digits well before).
double log_eps(LawKind law, double zeta, CollisionEnd end, SolveOptions options, CollisionSolver& solver) {
  options.ends = EndSet{end};
  options.keep_trajectory = false;
  const CollisionResult r = solver.solve(ContactLaw::natural(law, zeta), options);
  const EndResult& e = end_of(r, end);
  return e.eps < 0.5 ? std::log(e.eps) : std::log1p(-e.one_minus_eps);
}

void check_measured_eps(double eps) {
  if (!std::isfinite(eps) || eps <= 0.0 || eps >= 1.0) {
    throw InvalidInput(fmt::format("eps must be in (0, 1), got {}", eps));
  }
}

// The checked range in ε: every calibration path refuses an ε that only a ζ above kLargestCheckedZeta gives,
// in these words.
[[noreturn]] void throw_below_checked_range(double eps, double eps_at_largest, CollisionEnd end) {
  throw InvalidInput(
      fmt::format("eps = {} is below eps(zeta = {:g}) = {:.6g} at the {} end: outside the "
                  "checked range",
                  eps, kLargestCheckedZeta, eps_at_largest, end_name(end)));
}

// The next upper bracket: ×4, but for a naive end that exists only below a critical ζ (where ε -> 0)
// halfway to it, so that every trial has the end.
double widened(double hi, LawKind law, CollisionEnd end) {
  const ContactLaw trial = ContactLaw::natural(law, 4.0 * hi);
  if (end != CollisionEnd::naive || trial.naive_end_existence() != NaiveEndExistence::below_critical_zeta) {
    return 4.0 * hi;
  }
  return std::min(4.0 * hi, 0.5 * (hi + naive_end_critical_zeta(law)));
}

}  // namespace

double zeta_for_eps(double eps, CollisionEnd end, const SolveOptions& options, CollisionSolver& solver,
                    int* solves, LawKind law) {
  check_measured_eps(eps);
  int count = 0;
  const double target = std::log(eps);
  auto f = [&](double zeta) {
    if (zeta == 0.0) return -target;  // ε(0) = 1 exactly
    ++count;
    return log_eps(law, zeta, end, options, solver) - target;
  };
  // Bracket: f(0) > 0; widen upwards until ε drops below the target.
  double lo = 0.0;
  double hi = 0.25;
  double f_lo = f(lo);
  double f_hi = f(hi);
  while (f_hi > 0.0) {
    if (hi >= kLargestCheckedZeta) throw_below_checked_range(eps, std::exp(f_hi + target), end);
    lo = hi;
    f_lo = f_hi;
    hi = std::min(widened(hi, law, end), kLargestCheckedZeta);
    f_hi = f(hi);
  }
  if (f_hi == 0.0) return hi;
  // Each ε carries a relative error of about the tolerance; asking ζ for more digits than that is noise.
  const int bits = std::min(50, static_cast<int>(std::ceil(-std::log2(options.tolerance))) + 4);
  std::uintmax_t iterations = 200;
  const auto [a, b] = boost::math::tools::toms748_solve(
      f, lo, hi, f_lo, f_hi, boost::math::tools::eps_tolerance<double>(bits), iterations);
  if (solves != nullptr) *solves += count;
  return 0.5 * (a + b);
}

double fast_zeta_for_eps(double eps, CollisionEnd end) {
  const double zeta = fast::zeta_from_eps(eps, end);
  if (zeta > kLargestCheckedZeta) throw_below_checked_range(eps, fast::eps(kLargestCheckedZeta, end), end);
  return zeta;
}

Calibration calibrate(const CalibrationRequest& request, CollisionSolver& solver) {
  if (!std::isfinite(request.velocity_m_s) || request.velocity_m_s <= 0.0) {
    throw InvalidInput(fmt::format("velocity must be finite and > 0, got {}", request.velocity_m_s));
  }
  SolveOptions options;
  options.tolerance = request.tolerance;
  options.method = request.method;
  Calibration c;
  c.law = request.law;
  const bool hertz = request.law == LawKind::viscoelastic_hertz;
  if (request.fast && !hertz) {
    throw InvalidInput(fmt::format("the fast table holds viscoelastic Hertz only, not law {}: give a method",
                                   law_name(request.law)));
  }
  if (request.fast) {
    check_measured_eps(request.eps);
    c.zeta = fast_zeta_for_eps(request.eps, request.end);
    c.eps_at_zeta = fast::eps(c.zeta, request.end);
  } else {
    c.zeta = zeta_for_eps(request.eps, request.end, options, solver, &c.solves, request.law);
    c.eps_at_zeta = std::exp(log_eps(request.law, c.zeta, request.end, options, solver));
    ++c.solves;
  }
  c.parameter = ContactLaw::natural(request.law, c.zeta).parameter();
  if (!hertz) return c;
  c.beta = beta_from(c.zeta, request.velocity_m_s);
  c.characteristic_velocity_m_s = characteristic_velocity_m_s(c.beta);
  if (request.k) {
    c.dissipative_constant_s = dissipative_constant_from(c.beta, *request.k);
  }
  return c;
}

}  // namespace restitution
