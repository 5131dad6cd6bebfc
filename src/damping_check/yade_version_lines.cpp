// SPDX-License-Identifier: BSD-3-Clause
#include "damping_check/yade_version_lines.hpp"

#include "damping_check/inverse.hpp"

namespace restitution::damping_check {

void target_yade_version(dem::LinesResult& r, const dem::YadeVersion& version, double tolerance) {
  r.yade_version = version;
  if (version.has_vn()) return;  // the exact lines, whose notes say which versions take vn
  InverseRequest inverse;
  inverse.recipe = Recipe::thornton_2013;
  inverse.target_eps = r.yade.value().true_eps;  // the law's ε at the reference speed
  inverse.target_velocity_m_s = r.reference_velocity_m_s;
  inverse.clamp = Clamp::on;  // YADE's Mindlin law clamps: the delayed-recovery end
  inverse.tolerance = tolerance;
  CollisionSolver solver;
  const InverseResult found = invert_recipe(inverse, solver);
  const double betan = found.check.setting.code_value;
  const double eps = found.check.points.front().actual_eps.value();
  r.yade_exact_deck = r.deck;
  r.yade_exact_eps = r.eps;
  r.deck = dem::yade_constant_eps_deck(r.deck, betan, eps, version);
  for (dem::SpeedEps& e : r.eps) e.eps = eps;
  for (dem::SizeCheck& s : r.sizes) s.eps_lines = eps;
}

}  // namespace restitution::damping_check
