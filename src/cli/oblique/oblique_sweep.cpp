// SPDX-License-Identifier: BSD-3-Clause
#include "cli/oblique/oblique_sweep.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <utility>

#include "cli/common/plot_script.hpp"
#include "cli/common/range_option.hpp"
#include "restitution/errors.hpp"
#include "restitution/sweep.hpp"
#include "sweep/number_text.hpp"

namespace restitution::cli {

using namespace restitution::oblique;

std::vector<double> angle_range(const std::string& text) {
  const RangeText range = parse_range(text, "--angle-range", "degrees, N >= 2 angles", 2, 100000);
  // Checked here, so that a bad end is blamed on the option that was typed, not on --angle.
  for (const double end : {range.from, range.to}) {
    if (!(end >= 0.0 && end < 90.0)) {
      throw InvalidInput(fmt::format(
          "--angle-range '{}': the angles must be in [0, 90) degrees from the normal, got {}", text, end));
    }
  }
  return evenly_spaced(range.from, range.to, static_cast<std::size_t>(range.count));
}

const char* oblique_csv_header() {
  // The first ten columns as before sweeps over spin; the initial spin and Maw's ψ were added at the end,
  // then the second sphere's spin (0 on a wall) and whether the impact was solved.
  return "angle_deg,normal_restitution,tangential_restitution,rebound_angle_deg,spin_rad_s,impulse_ratio,"
         "contact_time_s,stick_time_s,slip_time_s,switches,initial_spin_rad_s,psi_in,psi_out,spin2_rad_s,"
         "status";
}

std::string oblique_csv_header_with_model() {
  return std::string("tangential_model,") + oblique_csv_header();
}

std::string oblique_csv_rows(const std::vector<ObliqueImpact>& impacts, const char* model) {
  constexpr double kDegree = 3.14159265358979323846 / 180.0;
  std::string csv;
  for (const ObliqueImpact& i : impacts) {
    const ObliqueResult& r = i.result;
    if (model != nullptr) csv += std::string(model) + ",";
    const std::string switches = i.solved() ? fmt::format("{}", r.switches.size() - 1) : "nan";
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", number17(i.angle_deg),
                       number17(r.normal_restitution), number17(r.tangential_restitution),
                       number17(r.rebound_angle_rad / kDegree), number17(r.spin_first_rad_s),
                       number17(r.impulse_ratio), number17(r.contact_time_s), number17(r.stick_time_s),
                       number17(r.slip_time_s), switches, number17(i.initial_spin_rad_s), number17(i.psi_in),
                       number17(i.psi_out), number17(r.spin_second_rad_s), i.solved() ? "solved" : "failed");
  }
  return csv;
}

std::string oblique_csv(const std::vector<ObliqueImpact>& impacts) {
  return std::string(oblique_csv_header()) + "\n" + oblique_csv_rows(impacts, nullptr);
}

MawModel maw_model(const ObliqueSetup& setup) {
  StickingLimit limit = sticking_limit_restitution(setup);
  return {setup.tangential.kind, limit.tangential_restitution, std::move(limit.failure)};
}

std::vector<std::string> maw_plot_arguments(const ObliqueSetup& setup, double normal_restitution,
                                            const std::vector<MawModel>& models) {
  std::vector<std::string> arguments = {number17(maw_chi(setup)), number17(normal_restitution)};
  for (const MawModel& m : models) {
    arguments.insert(arguments.end(),
                     {"--model", tangential_name(m.model), number17(m.sticking_restitution)});
  }
  return arguments;
}

double first_solved_restitution(const std::vector<ObliqueImpact>& impacts) {
  const auto solved =
      std::find_if(impacts.begin(), impacts.end(), [](const ObliqueImpact& i) { return i.solved(); });
  return solved == impacts.end() ? std::nan("") : solved->result.normal_restitution;
}

std::string plot_maw(const ObliqueSetup& setup, const MawModel& model, double normal_restitution,
                     const std::filesystem::path& csv, const std::filesystem::path& image,
                     const std::vector<std::string>& formats) {
  if (!(setup.tangential.friction > 0.0)) return "Maw's diagram needs friction > 0";
  if (std::isnan(normal_restitution)) return "no impact was solved";
  return run_plot_script("oblique_maw", csv, image, maw_plot_arguments(setup, normal_restitution, {model}),
                         formats);
}

}  // namespace restitution::cli
