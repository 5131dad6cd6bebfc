// SPDX-License-Identifier: BSD-3-Clause
#include "dem/yade_runner.hpp"

#include <fmt/core.h>

#include <cstdlib>
#include <utility>

#include "dem/process_output.hpp"
#include "restitution/units.hpp"

namespace restitution::dem {
namespace {

// A Python string literal holding `text` verbatim.
std::string python_literal(const std::string& text) {
  std::string out = "'";
  for (const char c : text) {
    if (c == '\\' || c == '\'') out += '\\';
    out += c;
  }
  return out + "'";
}

DemRun run_yade(const std::string& program, const Deck& deck, const Pair& pair,
                const std::vector<double>& speeds, int steps_per_time) {
  DemRun run;
  run.output = output_with_input_file(
      yade_script(deck, pair, speeds, steps_per_time), ".py",
      [&](const std::string& path) { return fmt::format("{} -n -x {} 2>&1", program, path); });
  // yade prints banners and warnings: only the script's own lines count.
  TaggedEps read = tagged_eps(run.output, "RESTITUTION_EPS", speeds.size());
  run.eps = std::move(read.eps);
  run.gap_m = std::move(read.gap_m);
  return run;
}

}  // namespace

std::string yade_program() {
  return output_of("command -v yade 2>/dev/null").empty() ? "" : "yade";
}

std::string yade_script(const Deck& deck, const Pair& pair, const std::vector<double>& speeds,
                        int steps_per_time) {
  std::string s = "LINES = [";
  for (const std::string& line : deck.lines) s += python_literal(line) + ", ";
  s += "]\nspeeds = [";
  for (const double v : speeds) s += fmt::format("{:.17g}, ", v);
  // k / m_eff as the pair has it: the natural time T = (k/m)^{-2/5} v^{-1/5} of each speed.
  const double k_over_m =
      hertz_stiffness(pair.effective_modulus_pa, pair.effective_radius_m) / pair.effective_mass_kg;
  s += fmt::format("]\nr1, r2, k, n = {:.17g}, {:.17g}, {:.17g}, {}\n", pair.radius1_m, pair.radius2_m,
                   k_over_m, steps_per_time);
  s += R"(for i, v in enumerate(speeds):
    O.reset()
    exec(LINES[0])
    O.bodies.append([sphere((-r1, 0, 0), r1), sphere((r2, 0, 0), r2)])
    O.bodies[0].state.vel = Vector3(v / 2, 0, 0)
    O.bodies[1].state.vel = Vector3(-v / 2, 0, 0)
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [eval(LINES[1])], [eval(LINES[2])]),
                 NewtonIntegrator(damping=0)]
    O.dt = k ** -0.4 * v ** -0.2 / n
    O.run(6 * n, True)
    eps = (O.bodies[1].state.vel[0] - O.bodies[0].state.vel[0]) / v
    gap = O.bodies[1].state.pos[0] - O.bodies[0].state.pos[0] - (r1 + r2)
    print("RESTITUTION_EPS %d %.17g %.17g" % (i, eps, gap))
)";
  return s;
}

DemMeasurement measure_yade_eps(const std::string& program, const Deck& deck, const Pair& pair,
                                const std::vector<double>& speeds, int coarse_steps_per_time) {
  return richardson(run_yade(program, deck, pair, speeds, coarse_steps_per_time),
                    run_yade(program, deck, pair, speeds, 10 * coarse_steps_per_time));
}

}  // namespace restitution::dem
