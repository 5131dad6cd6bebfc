// SPDX-License-Identifier: BSD-3-Clause
// `restitution run [SCENE]`: runs a scene file (default: scenes/default.toml, the 2008 paper) and writes its
// tables, plots and report into the scene's output folder.
#include <fmt/core.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <utility>

#include "cli/common/commands.hpp"
#include "cli/common/deprecated_alias.hpp"
#include "cli/common/options.hpp"
#include "cli/common/progress.hpp"
#include "cli/common/resource_root.hpp"
#include "cli/common/stop_signals.hpp"
#include "cli/scene/scene_outputs.hpp"
#include "cli/solve/work_precision_files.hpp"
#include "files/output_files.hpp"
#include "files/output_lock.hpp"
#include "files/printable_name.hpp"
#include "files/resolved_path.hpp"
#include "restitution/errors.hpp"
#include "restitution/sweep.hpp"
#include "scene/scene.hpp"
#include "scene/scene_plan.hpp"
#include "scene/scene_run.hpp"
#include "scene/scene_sections.hpp"

namespace restitution::cli {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kQuickPoints = 6;

struct RunOptions {
  std::string scene;
  std::string output;
  bool quick = false;
  unsigned threads = 0;
  std::string format;  // empty: the scene's `format`
};

// ./scenes/default.toml when run from the repository, else the installed or the source tree's one.
fs::path default_scene() {
  fs::path here = fs::path("scenes") / "default.toml";
  if (fs::exists(here)) return here;
  return resource_root() / "scenes" / "default.toml";
}

int run_scene_file(const RunOptions& o) {
  const fs::path path = o.scene.empty() ? default_scene() : fs::path(o.scene);
  scene::Scene s = scene::load_scene(path);
  if (!o.format.empty()) s.figure_formats = scene::figure_formats_from_list(o.format);
  if (o.quick) s.tolerance = std::max(s.tolerance, 1e-8);
  if (o.quick) scene::make_quick(s, kQuickPoints);
  const fs::path folder = o.output.empty() ? s.output : fs::path(o.output);
  const std::string shown = files::printable_name(folder.string());  // a name may hold escape sequences
  // The scene's own `output` stays under the working folder after symlinks too (the parser refuses '..'
  // and absolute names); --out names any folder, the user's own choice.
  if (o.output.empty() && !files::resolves_within(folder, fs::current_path())) {
    throw InvalidInput(
        fmt::format("the scene's output '{}' leads outside the working folder through a "
                    "symbolic link: a scene writes under the folder it is run from "
                    "(or name the folder: restitution run FILE --out DIR)",
                    shown));
  }
  scene::Plan plan =
      scene::plan_scene(s);            // refuses points outside the solver's range before a folder exists
  files::check_output_folder(folder);  // fail before the work, not after
  // Before the work too: a second run into the folder is refused at once, not after its own solves.
  const files::FolderLock lock(folder, fmt::format("--out '{}'", shown));

  scene::RunSettings settings;
  settings.threads = o.threads;
  settings.reference_file = default_reference_file();
  ProgressLine progress("collisions");
  settings.progress = progress.callback();
  const auto start = std::chrono::steady_clock::now();
  const scene::SceneResults results = scene::run_scene(s, std::move(plan), settings);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Ctrl-C while computing ends the process at once (nothing is written yet); while writing and plotting
  // it is caught, so that the run stops between files and exits 130 (main) with nothing half-written.
  const StopSignals signals;
  const WrittenOutputs written = write_scene_outputs(s, results, folder, seconds);
  for (const auto& w : written.warnings) std::fprintf(stderr, "restitution: warning: %s\n", w.c_str());
  // [[dem]] and [[damping_check]] sections solve their own collisions, outside the shared plan.
  const bool own_solves = scene::has_sections(s, "dem") || scene::has_sections(s, "damping_check");
  fmt::print("scene {}: {} planned collisions in {:.2f} s{}{}\n", files::printable_name(path.string()),
             results.collisions, seconds,
             own_solves ? " (dem and damping_check sections solve their own, not counted)" : "",
             o.quick ? " (quick settings)" : "");
  fmt::print("wrote {}/: ", shown);
  for (std::size_t i = 0; i < written.files.size(); ++i)
    fmt::print("{}{}", i != 0 ? ", " : "", written.files[i]);
  fmt::print("\n");
  return 0;
}

}  // namespace

void add_run_command(CLI::App& app, Action& chosen) {
  auto o = std::make_shared<RunOptions>();
  CLI::App* cmd =
      app.add_subcommand("run", "run a scene file: tables, plots and a report (default: the 2008 paper)");
  cmd->add_option("scene", o->scene, "scene file (TOML); default scenes/default.toml");
  CLI::Option* out =
      cmd->add_option("--out", o->output,
                      "output folder, any path (default: the scene's `output`, which must stay "
                      "under the working directory)")
          ->check(non_empty_path());
  add_deprecated_alias(*cmd, out, "--output");
  cmd->add_flag(
      "--quick", o->quick,
      fmt::format("small settings for CI: at most {} points per range, tolerance >= 1e-8", kQuickPoints));
  cmd->add_option("--threads", o->threads,
                  fmt::format("worker threads, in [1, {}] (default: one per core)", kMaxSweepThreads))
      ->check(CLI::Range(1U, kMaxSweepThreads));
  add_figure_format_option(cmd, o->format)
      ->default_str("the scene's `format`, else png")
      ->description(
          "figure formats, comma-separated: png (300 dpi), pdf, svg (overrides the scene's `format`)");
  cmd->callback([o, &chosen] { chosen = [o] { return run_scene_file(*o); }; });
}

}  // namespace restitution::cli
