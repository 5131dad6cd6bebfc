// SPDX-License-Identifier: BSD-3-Clause
#include "dem/lines_check.hpp"

#include <algorithm>

#include "analysis/contract_error.hpp"
#include "dem/yade_conversion.hpp"
#include "restitution/calibration.hpp"
#include "restitution/errors.hpp"

namespace restitution::dem {

double dissipative_constant(const Material& material, const DampingSource& source, CollisionEnd end,
                            double tolerance, Method method, CollisionSolver& solver) {
  // k only when calibrating: the source's own errors come first.
  const double k = source.eps && !source.dissipative_constant_s ? elastic_constants(material).k : 0.0;
  return dissipative_constant(k, source, end, tolerance, method, solver);
}

double dissipative_constant(double k, const DampingSource& source, CollisionEnd end, double tolerance,
                            Method method, CollisionSolver& solver) {
  if (source.dissipative_constant_s.has_value() == source.eps.has_value()) {
    throw InvalidInput("give either --eps and --velocity (calibrate) or --dissipative-constant");
  }
  if (source.dissipative_constant_s) return *source.dissipative_constant_s;
  if (!source.velocity_m_s) throw InvalidInput("--eps needs --velocity, the impact speed it was measured at");
  CalibrationRequest request;
  request.eps = *source.eps;
  request.velocity_m_s = *source.velocity_m_s;
  request.end = end;
  request.tolerance = tolerance;
  request.method = method;
  request.k = k;
  return *calibrate(request, solver).dissipative_constant_s;
}

LinesResult check_lines(const LinesRequest& request) {
  const Code code = request.code;
  const CollisionEnd end = request.end;
  if (always_clamps(code) && end == CollisionEnd::naive) {
    // Refuse before calibrating: the deck would refuse anyway.
    (void)make_deck(code, end, {}, 0.0, 1.0);
  }
  check_friction(request.friction);
  const Pair pair = pair_of(request.material);
  const double k = elastic_constants(request.material).k;
  CollisionSolver solver;
  LinesResult r;
  r.dissipative_constant_s = dissipative_constant(request.material, request.damping, end, request.tolerance,
                                                  Method::automatic, solver);
  r.reference_velocity_m_s = request.damping.velocity_m_s.value_or(1.0);
  r.friction = request.friction;
  r.deck = make_deck(code, end, pair, r.dissipative_constant_s, r.reference_velocity_m_s, request.friction);
  const double v = r.reference_velocity_m_s;
  const std::vector<double> speeds =
      request.speeds_m_s.empty() ? std::vector<double>{v / 10.0, v, 10.0 * v} : request.speeds_m_s;
  const double beta = deck_beta(r.deck, pair);
  for (double s : speeds) r.eps.push_back({s, eps_for(beta, s, end, request.tolerance, solver)});
  r.sizes = size_checks(r.deck, pair, r.dissipative_constant_s, v, {0.5, 2.0}, request.tolerance, solver);
  if (code_entry(code).eps_conversion) {
    YadeCheck y;
    y.true_eps =
        eps_for(hertz_constants(k, r.dissipative_constant_s).beta, v, end, request.tolerance, solver);
    y.dissipative_constant_s = yade_dissipative_constant(y.true_eps, v, k);
    y.eps_at_vn =
        eps_for(hertz_constants(k, y.dissipative_constant_s).beta, v, end, request.tolerance, solver);
    r.yade = y;
  }
  return r;
}

CodeComparison compare_with_code(Code code, const Material& material, const DampingSource& damping,
                                 CollisionEnd end, const std::vector<double>& speeds_m_s, double friction,
                                 double tolerance, Method method, const std::string& program) {
  const Pair pair = pair_of(material);
  CollisionSolver solver;
  CodeComparison c;
  c.dissipative_constant_s = dissipative_constant(material, damping, end, tolerance, method, solver);
  c.deck = make_deck(code, end, pair, c.dissipative_constant_s, damping.velocity_m_s.value_or(1.0), friction);
  const double beta = deck_beta(c.deck, pair);
  for (double v : speeds_m_s) c.predicted_eps.push_back(eps_for(beta, v, end, tolerance, solver));
  if (program.empty()) return c;
  c.measured = measure_dem_eps(program, c.deck, pair, speeds_m_s);
  for (std::size_t i = 0; i < speeds_m_s.size(); ++i) {
    const double predicted = c.predicted_eps[i];
    c.relative_difference.push_back(analysis::contract_difference(c.measured->extrapolated[i], predicted));
  }
  return c;
}

}  // namespace restitution::dem
