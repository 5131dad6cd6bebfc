// SPDX-License-Identifier: BSD-3-Clause
// `restitution fast-table`: regenerates the fast ε(ζ) tables (src/fast/fast_table.h) from the reference
// engine; `restitution export c-header`: writes the compiled tables as one self-contained C99 header.
#include <fmt/core.h>

#include <filesystem>
#include <limits>
#include <memory>

#include "cli/common/commands.hpp"
#include "cli/common/options.hpp"
#include "cli/common/progress.hpp"
#include "cli/common/stop_signals.hpp"
#include "fast/c_header.hpp"
#include "fast_study/table_generator.hpp"
#include "files/output_files.hpp"
#include "restitution/errors.hpp"
#include "restitution/fast.hpp"

namespace restitution::cli {
namespace {

struct FastTableOptions {
  std::string out;
  fast::GeneratorSettings settings;
};

void write_text(const std::string& out, const std::string& text) {
  const std::filesystem::path path(out);
  files::check_output_file(path);
  files::write_file_atomically(path, text);
}

int run_fast_table(const FastTableOptions& o) {
  files::check_output_file(o.out);  // before the two minutes of solves, not after
  const StopSignals signals;        // Ctrl-C stops at the next interval, before the header is written
  const fast::TableData data = [&] {
    ProgressLine progress("fast-table (intervals fitted, then checked)");
    return fast::generate_tables(o.settings, progress.stoppable_callback());
  }();
  write_text(o.out, fast::c_header_text(data));
  fmt::print("wrote {}\n{}\n", o.out, data.settings);
  return 0;
}

}  // namespace

void add_fast_table_command(CLI::App& app, Action& chosen) {
  auto o = std::make_shared<FastTableOptions>();
  CLI::App* cmd = app.add_subcommand(
      "fast-table",
      "regenerate the fast eps(zeta) tables from the __float128 reference engine (about 2 minutes)");
  cmd->add_option("--out", o->out, "header to write (the repository keeps src/fast/fast_table.h)")
      ->required()
      ->check(non_empty_path());
  cmd->add_option(
         "--degree", o->settings.degree,
         fmt::format("polynomial degree per interval, in [{}, {}]", fast::kMinDegree, fast::kMaxDegree))
      ->capture_default_str();
  cmd->add_option("--per-unit", o->settings.per_unit,
                  fmt::format("intervals per unit of ln zeta, a whole number in [1, {}]", fast::kMaxPerUnit))
      ->capture_default_str();
  cmd->add_option("--s-lo", o->settings.s_lo, "ln zeta where the tables start")->capture_default_str();
  cmd->add_option("--s-hi-naive", o->settings.s_hi_naive, "ln zeta where the naive table ends")
      ->capture_default_str();
  cmd->add_option("--s-hi-naive-duration", o->settings.s_hi_naive_duration,
                  "ln zeta where the naive table of the collision duration ends")
      ->capture_default_str();
  cmd->add_option("--s-hi-delayed", o->settings.s_hi_delayed, "ln zeta where the delayed-recovery table ends")
      ->capture_default_str();
  cmd->add_option("--checks", o->settings.checks_per_interval,
                  fmt::format("random check points per interval, in [1, {}]", fast::kMaxChecksPerInterval))
      ->capture_default_str()
      ->check(whole_number_in(1, fast::kMaxChecksPerInterval));
  cmd->add_option("--seed", o->settings.seed, "seed of the check points, an integer >= 0")
      ->capture_default_str()
      ->check(whole_number_in(0, std::numeric_limits<long long>::max()));
  cmd->callback([o, &chosen] { chosen = [o] { return run_fast_table(*o); }; });
}

void add_export_command(CLI::App& app, Action& chosen) {
  auto out = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("export", "export the fast eps(zeta) tables for other programs");
  cmd->require_subcommand(1);
  CLI::App* header = cmd->add_subcommand(
      "c-header", "one self-contained C99 header (also C++): eps, 1 - eps and the inverse for both ends");
  header->add_option("--out", *out, "header file to write")->required()->check(non_empty_path());
  header->callback([out, &chosen] {
    chosen = [out] {
      write_text(*out, fast::c_header());
      fmt::print("wrote {}\n", *out);
      return 0;
    };
  });
}

}  // namespace restitution::cli
