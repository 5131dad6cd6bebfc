// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/plot_script.hpp"

#include <fmt/core.h>
#include <sys/wait.h>

#include <csignal>

#include <cstdlib>
#include <string_view>
#include <system_error>

#include "child_process/child_process.hpp"
#include "cli/common/resource_root.hpp"
#include "cli/common/stop_signals.hpp"
#include "files/output_files.hpp"
#include "files/temporary_file.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {
namespace fs = std::filesystem;

namespace {

// The python interpreter with Debian's matplotlib; RESTITUTION_PYTHON overrides it (tests use this to
// simulate a machine without matplotlib).
std::string python_interpreter() {
  const char* chosen = std::getenv("RESTITUTION_PYTHON");
  return chosen != nullptr ? chosen : "/usr/bin/python3";
}

fs::path scripts_folder() {
  const char* chosen = std::getenv("RESTITUTION_SCRIPTS_DIR");
  return chosen != nullptr ? fs::path(chosen) : resource_root() / "scripts";
}

// Runs the program (no shell: nothing to quote) with its output discarded and waits for it; it gets SIGTERM
// when this process is asked to stop (SIGINT or SIGTERM to this process alone; Ctrl-C reaches the whole
// process group anyway) and never outlives it (child_process/child_process.hpp). Returns its wait status, -1
// when it could not be started.
int run_quietly(const std::vector<std::string>& command) {
  return run_child(command, ChildOutput::discard, [] { return stop_signal_received() != 0; }).status;
}

// A child killed by SIGINT or SIGTERM was stopped by the user (Ctrl-C reaches the whole process group), as
// was this process when its own handler saw the signal: stop the command rather than carry on without it.
// This process's own signal comes first: when it got SIGINT, the SIGTERM its child died of is only the one
// run_quietly forwarded, and the command exits 130 for the user's Ctrl-C, not 143.
void stop_if_signalled(int status) {
  throw_if_interrupted();
  if (status > 0 && WIFSIGNALED(status) && (WTERMSIG(status) == SIGINT || WTERMSIG(status) == SIGTERM)) {
    throw Interrupted(WTERMSIG(status));
  }
}

}  // namespace

std::vector<std::string> figure_file_names(const std::string& stem, const std::vector<std::string>& formats) {
  std::vector<std::string> names;
  names.reserve(formats.size());
  for (const std::string& format : formats) names.push_back(fmt::format("{}.{}", stem, format));
  return names;
}

std::string no_plot_warning(const std::string& what, const std::string& why) {
  constexpr std::string_view kSaid = "no plot: ";
  const std::string reason = why.rfind(kSaid, 0) == 0 ? why.substr(kSaid.size()) : why;
  return fmt::format("restitution: warning: no {} plot: {}\n", what, reason);
}

std::string run_plot_script(const std::string& script, const fs::path& data, const fs::path& image,
                            const std::vector<std::string>& arguments,
                            const std::vector<std::string>& formats) {
  files::check_figure_file(image, "the figure");  // the commands check first; a scene's figures are files
  const fs::path path = scripts_folder() / "plots" / (script + ".py");
  if (!fs::exists(path)) return fmt::format("no plot: script {} not found", path.string());
  const std::string python = python_interpreter();
  const int probe = run_quietly({python, "-c", "import matplotlib"});
  stop_if_signalled(probe);  // a probe killed by Ctrl-C says nothing about matplotlib
  if (probe != 0) {
    return fmt::format(
        "no plot: {} cannot import matplotlib (install python3-matplotlib: bash scripts/setup)", python);
  }
  // matplotlib picks the format by the extension, so the temporary names keep it: NAME.<random>.tmp.png, ...
  // (random: another run's figures, or a link planted under a fixed name, are never written through). The
  // script creates them: a file made here in advance would outlive a SIGKILL of this process.
  const std::string token = files::random_name_part();
  const auto figure = [&](const std::string& format, bool temporary) {
    const std::string stem = image.stem().string();
    return image.parent_path() / (temporary ? fmt::format("{}.{}.tmp.{}", stem, token, format)
                                            : fmt::format("{}.{}", stem, format));
  };
  std::error_code error;
  const auto remove_temporaries = [&] {
    for (const std::string& format : formats) fs::remove(figure(format, true), error);
  };
  std::string format_list;
  for (const std::string& format : formats) format_list += (format_list.empty() ? "" : ",") + format;
  std::vector<std::string> command = {python, path.string(), data.string(),
                                      figure(formats.front(), true).string()};
  command.insert(command.end(), arguments.begin(), arguments.end());
  command.insert(command.end(), {"--format", format_list});
  const int status = run_quietly(command);
  if (status != 0 || stop_signal_received() != 0) {
    remove_temporaries();  // the figures of a failed or stopped script are no plot
    stop_if_signalled(status);
    return fmt::format("no plot: {} failed with status {}", path.filename().string(),
                       WIFEXITED(status) ? WEXITSTATUS(status) : -1);
  }
  for (const std::string& format : formats) {
    if (fs::file_size(figure(format, true), error) == 0 || error) {
      remove_temporaries();
      return fmt::format("no plot: {} wrote no {} figure", path.filename().string(), format);
    }
  }
  for (const std::string& format : formats) {
    fs::rename(figure(format, true), figure(format, false), error);
    if (error) {
      remove_temporaries();
      throw IoError(fmt::format("cannot write '{}': {}", figure(format, false).string(), error.message()));
    }
  }
  return {};
}

}  // namespace restitution::cli
