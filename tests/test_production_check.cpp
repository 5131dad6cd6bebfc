// SPDX-License-Identifier: BSD-3-Clause
// What a production run with the law's lines needs (damping_check/production_check.hpp): per listed speed the
// contact duration, the velocity-Verlet ε error at a time step and the largest time step that keeps the worst
// error within a bound; the overall largest step is the smallest of those, and a code whose integrator is not
// velocity-Verlet is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "damping_check/production_check.hpp"
#include "dem/dem_codes.hpp"
#include "dem/integrator_eps.hpp"
#include "dem/lines_check.hpp"
#include "restitution/errors.hpp"

namespace {

using namespace restitution;

Material rubber() {
  Material m;
  m.young_modulus_pa = 1e7;
  m.poisson_ratio = 0.45;
  m.density_kg_m3 = 1100.0;
  m.radius1_m = m.radius2_m = 0.01;
  return m;
}

dem::LinesResult lines(const std::string& code) {
  dem::LinesRequest request;
  request.code = dem::code_from_name(code);
  request.material = rubber();
  request.damping.eps = 0.8;
  request.damping.velocity_m_s = 1.0;
  return dem::check_lines(request);
}

TEST(ProductionCheck, LargestStepKeepsEverySpeedWithinTheBound) {
  const dem::LinesResult r = lines("lammps");
  damping_check::ProductionRequest request;
  request.max_eps_error = 1e-3;
  request.time_step_s = 1e-6;
  const damping_check::ProductionCheck p = damping_check::check_production(r, rubber(), request);
  ASSERT_EQ(p.contact_duration_s.size(), r.eps.size());
  ASSERT_EQ(p.errors.size(), r.eps.size());
  ASSERT_EQ(p.largest_time_step_s.size(), r.eps.size());
  ASSERT_TRUE(p.largest_time_step_all_s.has_value());
  EXPECT_EQ(*p.largest_time_step_all_s,
            *std::min_element(p.largest_time_step_s.begin(), p.largest_time_step_s.end()));
  CollisionSolver solver;
  const dem::Pair pair = dem::pair_of(rubber());
  for (std::size_t i = 0; i < r.eps.size(); ++i) {
    const double v = r.eps[i].velocity_m_s;
    EXPECT_EQ(p.errors[i].velocity_m_s, v);
    // Faster impacts are shorter (Hertz: t_c ∝ v^{-1/5}).
    if (i > 0 && v > r.eps[i - 1].velocity_m_s)
      EXPECT_LT(p.contact_duration_s[i], p.contact_duration_s[i - 1]);
    // The overall step, integrated at this speed, keeps the worst error within the bound.
    const dem::IntegratorError e = dem::integrator_error(
        pair, r.dissipative_constant_s, r.deck.end, v, *p.largest_time_step_all_s, request.tolerance, solver);
    EXPECT_LE(std::abs(e.worst_error), 1.001 * *request.max_eps_error) << "v = " << v;
    EXPECT_NEAR(e.contact_duration_s, p.contact_duration_s[i], 1e-9 * p.contact_duration_s[i]);
  }
  EXPECT_FALSE(p.constant_eps.has_value());
}

TEST(ProductionCheck, NothingAskedIsNothingComputed) {
  const dem::LinesResult r = lines("lammps");
  const damping_check::ProductionCheck p = damping_check::check_production(r, rubber(), {});
  EXPECT_EQ(p.contact_duration_s.size(), r.eps.size());
  EXPECT_TRUE(p.errors.empty());
  EXPECT_TRUE(p.largest_time_step_s.empty());
  EXPECT_FALSE(p.largest_time_step_all_s.has_value());
}

TEST(ProductionCheck, RefusesATimeStepForACodeWithoutVelocityVerlet) {
  for (const dem::CodeEntry& entry : dem::dem_codes()) {
    if (entry.velocity_verlet) continue;
    const dem::LinesResult r = lines(entry.name);
    damping_check::ProductionRequest request;
    request.time_step_s = 1e-6;
    try {
      (void)damping_check::check_production(r, rubber(), request);
      ADD_FAILURE() << entry.name << " accepted --timestep";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find("--timestep and --max-eps-error"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(entry.name), std::string::npos) << e.what();
    }
  }
}

}  // namespace
