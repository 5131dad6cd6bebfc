// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/commands.hpp"

namespace restitution::cli {

void add_all_commands(CLI::App& app, Action& chosen) {
  add_eps_command(app, chosen);
  add_reference_command(app, chosen);
  add_work_precision_command(app, chosen);
  add_fit_command(app, chosen);
  add_fit_data_command(app, chosen);
  add_stability_command(app, chosen);
  add_calibrate_command(app, chosen);
  add_run_command(app, chosen);
  add_series_command(app, chosen);
  add_sweep_command(app, chosen);
  add_dem_command(app, chosen);
  add_fast_table_command(app, chosen);
  add_export_command(app, chosen);
  add_damping_check_command(app, chosen);
  add_gas_command(app, chosen);
  add_oblique_command(app, chosen);
}

}  // namespace restitution::cli
