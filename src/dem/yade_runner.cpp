// SPDX-License-Identifier: BSD-3-Clause
#include "dem/yade_runner.hpp"

#include <fmt/core.h>

#include <cstdlib>
#include <utility>

#include "dem/check_deck_codes.hpp"
#include "dem/process_output.hpp"

namespace restitution::dem {
namespace {

DemRun run_yade(const std::string& program, const Deck& deck, const Pair& pair,
                const std::vector<double>& speeds, int steps_per_time) {
  ChildRun ran = output_with_input_file(yade_script(deck, pair, speeds, steps_per_time), ".py",
                                        [&](const std::string& path) {
                                          return std::vector<std::string>{program, "-n", "-x", path};
                                        });
  // yade prints banners and warnings: only the script's own lines count.
  TaggedEps read = tagged_eps(ran.output, "RESTITUTION_EPS", speeds.size());
  DemRun run;
  run.failure = code_run_failure(ran, program, read);
  run.exited_ok = child_succeeded(ran.status);
  run.output = std::move(ran.output);
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
  std::string s = yade_collide_function(deck.lines);
  s += "\nspeeds = [";
  for (const double v : speeds) s += fmt::format("{:.17g}, ", v);
  // The natural time T = (k/m)^{-2/5} v^{-1/5} of each speed; each run lasts 6 T.
  s += fmt::format("]\nr1, r2, T1, n = {:.17g}, {:.17g}, {:.17g}, {}\n", pair.radius1_m, pair.radius2_m,
                   natural_time_s(pair, 1.0), steps_per_time);
  s += R"(for i, v in enumerate(speeds):
    eps, gap = collide(r1, r2, v, T1 * v ** -0.2 / n, 6 * n)
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
