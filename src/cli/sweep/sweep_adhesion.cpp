// SPDX-License-Identifier: BSD-3-Clause
#include "cli/sweep/sweep_adhesion.hpp"

#include <fmt/core.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "adhesion/adhesive_study.hpp"
#include "cli/common/adhesion_options.hpp"
#include "cli/common/head_on_options.hpp"
#include "files/output_files.hpp"
#include "restitution/adhesion.hpp"
#include "restitution/errors.hpp"
#include "restitution/sweep.hpp"
#include "sweep/number_text.hpp"

namespace restitution::cli {
namespace {

// What the ζ and β forms and the resumable file take, none of which an adhesive sweep has.
void refuse_other_forms(const SweepOptions& o) {
  const std::vector<std::pair<bool, const char*>> others = {
      {o.zeta_min || o.zeta_max, "--zeta-range"},
      {o.beta.has_value(), "--beta"},
      {o.stiffness || o.damping_coefficient || o.effective_mass,
       "--stiffness, --damping-coefficient and --effective-mass"},
      {o.inputs.law != law_name(LawKind::viscoelastic_hertz), "--law"},
      {o.resume, "--resume"},
      {o.threads.has_value(), "--threads"},
  };
  for (const auto& [given, option] : others) {
    if (given) {
      throw InvalidInput(fmt::format(
          "{} does not go with --adhesion: an adhesive sweep takes the material, --surface-energy, "
          "--velocity-range (m/s) and optionally --dissipative-constant and --log, and runs on one thread "
          "into a file written whole at the end",
          option));
    }
  }
  if (!o.velocity_min || !o.velocity_max) {
    throw InvalidInput("an adhesive sweep needs --velocity-range FROM:TO:N (impact speeds in m/s)");
  }
}

std::string table(const AdhesiveContact& contact, const std::vector<double>& speeds, double tolerance) {
  const AdhesiveStudy study = study_adhesive_contact(contact, speeds, tolerance);
  std::string text = adhesive_table_header();
  for (std::size_t i = 0; i < speeds.size(); ++i)
    text += adhesive_table_row(speeds[i], study.collisions[i], study.sticking.speed_m_per_s);
  return text;
}

}  // namespace

std::string adhesive_table_header() {
  return "velocity_m_per_s,outcome,eps,one_minus_eps,contact_time_s,max_compression_m,hysteresis_work_j,"
         "viscous_work_j,kinetic_to_adhesion_energy,sticking_speed_m_per_s\n";
}

std::string adhesive_table_row(double speed_m_per_s, const AdhesiveCollision& c,
                               double sticking_speed_m_per_s) {
  return fmt::format("{},{},{},{},{},{},{},{},{},{}\n", number17(speed_m_per_s),
                     adhesive_outcome_name(c.outcome), number17(c.eps), number17(c.one_minus_eps),
                     number17(c.contact_time_s), number17(c.max_compression_m), number17(c.hysteresis_work_j),
                     number17(c.viscous_work_j), number17(c.kinetic_to_adhesion_energy),
                     number17(sticking_speed_m_per_s));
}

int run_adhesive_sweep(const SweepOptions& o) {
  refuse_other_forms(o);
  if (!o.adhesion.model) {
    throw InvalidInput("--surface-energy belongs to --adhesion: give --adhesion MODEL");
  }
  const AdhesiveContact contact = adhesive_contact_from(
      adhesive_model_from_name(*o.adhesion.model), o.adhesion, material_from(material_options_of(o.inputs)),
      o.dissipative_constant.value_or(0.0));
  std::vector<double> speeds;
  try {
    speeds = zeta_values(
        {*o.velocity_min, *o.velocity_max, static_cast<std::size_t>(o.points), o.log, "velocity"});
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("--velocity-range '{}': {}", o.velocity_range, e.what()));
  }
  const files::OutputTarget target = files::output_target(o.out);
  files::check_output_file(o.out);
  const std::string text = table(contact, speeds, o.inputs.tolerance);
  if (target.in_place) {
    files::write_in_place(target.path, text);
  } else {
    files::write_file_atomically(target.path, text);
  }
  fmt::print("wrote {}: {} points\n", o.out, speeds.size());
  return 0;
}

}  // namespace restitution::cli
