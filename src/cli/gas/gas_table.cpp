// SPDX-License-Identifier: BSD-3-Clause
#include "cli/gas/gas_table.hpp"

#include <fmt/core.h>

#include "restitution_gas/gas_inputs.hpp"
#include "sweep/number_text.hpp"

namespace restitution::cli {

std::string gas_csv(const gas::CoolingCurve& c) {
  const std::vector<gas::CurveColumn> columns = gas::curve_columns(c);
  std::string out;
  for (std::size_t j = 0; j < columns.size(); ++j)
    out += fmt::format("{}{}", j > 0 ? "," : "", columns[j].name);
  out += "\n";
  for (std::size_t i = 0; i < c.time_s.size(); ++i) {
    for (std::size_t j = 0; j < columns.size(); ++j) {
      out += fmt::format("{}{}", j > 0 ? "," : "", number17((*columns[j].values)[i]));
    }
    out += "\n";
  }
  return out;
}

std::string gas_law_text(const gas::CoolingRequest& r) {
  if (r.law.constant_eps) return fmt::format("constant eps = {:.10g}", *r.law.constant_eps);
  return fmt::format("{}, zeta = {:.10g} at {:g} m/s, {} end", law_name(r.law.kind), r.law.zeta_at_reference,
                     r.law.reference_speed_m_s, end_name(r.law.end));
}

std::vector<std::string> gas_plot_arguments(const gas::CoolingRequest& r, const gas::CoolingCurve& c) {
  std::vector<std::string> arguments = {number17(r.initial_temperature_j), number17(c.tau0_s),
                                        number17(c.haff_eps)};
  // The law as numbers, not as text: the figure rounds them for its legend and draws the viscoelastic
  // guides (t^-5/3) only for viscoelastic Hertz.
  if (r.law.constant_eps) {
    arguments.insert(arguments.end(), {"--constant-eps", number17(*r.law.constant_eps)});
  } else {
    arguments.insert(
        arguments.end(),
        {"--law", std::string(law_name(r.law.kind)), "--end", std::string(end_name(r.law.end)), "--zeta",
         number17(r.law.zeta_at_reference), "--reference-speed", number17(r.law.reference_speed_m_s)});
  }
  return arguments;
}

}  // namespace restitution::cli
