// SPDX-License-Identifier: BSD-3-Clause
#include "cli/oblique/oblique_sweep.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

#include "cli/common/output_files.hpp"
#include "restitution/errors.hpp"
#include "restitution/sweep.hpp"

namespace restitution::cli {

using namespace restitution::oblique;

std::vector<double> angle_range(const std::string& text) {
  const auto fail = [&text](const char* why) {
    return InvalidInput(
        fmt::format("--angle-range must be FROM:TO:N (degrees, N >= 2 angles), got '{}': {}", text, why));
  };
  const std::size_t first = text.find(':');
  const std::size_t second = first == std::string::npos ? first : text.find(':', first + 1);
  if (second == std::string::npos) throw fail("two colons expected");
  const auto number = [&](std::size_t begin, std::size_t end) {
    const std::string part = text.substr(begin, end - begin);
    char* stop = nullptr;
    const double value = std::strtod(part.c_str(), &stop);
    if (part.empty() || *stop != '\0' || !std::isfinite(value)) throw fail("not a number");
    return value;
  };
  const double from = number(0, first);
  const double to = number(first + 1, second);
  const double count = number(second + 1, text.size());
  if (!(count >= 2.0 && count <= 100000.0 && count == std::floor(count))) {
    throw fail("N must be a whole number in [2, 100000]");
  }
  // Checked here, so that a bad end is blamed on the option that was typed, not on --angle.
  for (const double end : {from, to}) {
    if (!(end >= 0.0 && end < 90.0)) {
      throw InvalidInput(fmt::format(
          "--angle-range '{}': the angles must be in [0, 90) degrees from the normal, got {}", text, end));
    }
  }
  return evenly_spaced(from, to, static_cast<std::size_t>(count));
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
