// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Subcommands of the `restitution` program. Each add_*_command registers its options on the app and,
// when its subcommand is chosen, stores the action to run after parsing. Actions return the exit status
// and may throw restitution::InvalidInput (exit 2) or NumericalFailure (exit 1).
#include <CLI/CLI.hpp>
#include <functional>

namespace restitution::cli {

using Action = std::function<int()>;

void add_eps_command(CLI::App& app, Action& chosen);
void add_reference_command(CLI::App& app, Action& chosen);
void add_work_precision_command(CLI::App& app, Action& chosen);
void add_fit_command(CLI::App& app, Action& chosen);
void add_fit_data_command(CLI::App& app, Action& chosen);
void add_stability_command(CLI::App& app, Action& chosen);
void add_calibrate_command(CLI::App& app, Action& chosen);
void add_run_command(CLI::App& app, Action& chosen);
void add_series_command(CLI::App& app, Action& chosen);
void add_sweep_command(CLI::App& app, Action& chosen);
void add_dem_command(CLI::App& app, Action& chosen);
void add_fast_table_command(CLI::App& app, Action& chosen);
void add_export_command(CLI::App& app, Action& chosen);
void add_damping_check_command(CLI::App& app, Action& chosen);
void add_gas_command(CLI::App& app, Action& chosen);
void add_oblique_command(CLI::App& app, Action& chosen);

// Every subcommand of the program, in the order `--help` lists them: the one list main() and the
// command-line fuzz target share.
void add_all_commands(CLI::App& app, Action& chosen);

}  // namespace restitution::cli
