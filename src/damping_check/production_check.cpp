// SPDX-License-Identifier: BSD-3-Clause
#include "damping_check/production_check.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "dem/dem_codes.hpp"
#include "restitution/errors.hpp"

namespace restitution::damping_check {

ProductionCheck check_production(const dem::LinesResult& r, const Material& material,
                                 const ProductionRequest& request) {
  const dem::Code code = r.deck.code;
  if ((request.time_step_s || request.max_eps_error) && !dem::code_entry(code).velocity_verlet) {
    throw InvalidInput(
        fmt::format("--timestep and --max-eps-error model the velocity-Verlet of {}, not {}",
                    dem::code_list(" and ", [](const dem::CodeEntry& e) { return e.velocity_verlet; }),
                    dem::code_name(code)));
  }
  const dem::Pair pair = dem::pair_of(material);
  const double a = r.dissipative_constant_s;
  const CollisionEnd end = r.deck.end;
  CollisionSolver solver;
  ProductionCheck p;
  for (const auto& e : r.eps) {
    const double v = e.velocity_m_s;
    p.contact_duration_s.push_back(dem::contact_duration_s(pair, a, end, v, request.tolerance, solver));
    if (request.time_step_s) {
      p.errors.push_back(
          dem::integrator_error(pair, a, end, v, *request.time_step_s, request.tolerance, solver));
    }
    if (request.max_eps_error) {
      p.largest_time_step_s.push_back(
          dem::largest_time_step_s(pair, a, end, v, *request.max_eps_error, request.tolerance, solver));
    }
  }
  if (!p.largest_time_step_s.empty()) {
    p.largest_time_step_all_s = *std::min_element(p.largest_time_step_s.begin(), p.largest_time_step_s.end());
  }
  if (request.constant_eps) p.constant_eps = constant_eps_lines(r, pair, request.tolerance, solver);
  return p;
}

}  // namespace restitution::damping_check
