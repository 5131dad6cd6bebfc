// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/output_files.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>
#include <system_error>

#include "child_process/child_process.hpp"
#include "cli/common/io_error.hpp"
#include "cli/common/resource_root.hpp"
#include "cli/common/stop_signals.hpp"
#include "restitution/errors.hpp"
#include "sweep/printable_name.hpp"
#include "sweep/temporary_file.hpp"

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

void flush_standard_output() {
  if (std::fflush(stdout) != 0 || std::ferror(stdout) != 0) {
    throw IoError(fmt::format("cannot write to standard output: {}", std::strerror(errno)));
  }
}

namespace {

// `file` (empty for a folder output) names what is to be written there, so that the message says which output
// failed; the system's reason comes last, in brackets, since for /proc it reads "No such file or directory".
void check_writable_folder(const fs::path& folder, const fs::path& file) {
  std::error_code error;
  const fs::path start = folder.empty() ? fs::path(".") : folder;
  fs::path existing = start;
  while (!fs::exists(fs::symlink_status(existing, error)) && existing.has_parent_path() &&
         existing.parent_path() != existing) {
    existing = existing.parent_path();
  }
  if (!fs::exists(existing)) existing = ".";  // a relative path none of whose parts exists yet
  const std::string what =
      existing != start ? fmt::format("cannot create output folder '{}'", folder.string())
      : file.empty()    ? fmt::format("cannot write into output folder '{}'", folder.string())
                        : fmt::format("cannot write '{}'", file.string());
  if (!fs::is_directory(existing)) {
    throw IoError(fmt::format("{}: '{}' is not a folder", what, existing.string()));
  }
  // access(W_OK) says yes to root everywhere, /proc included: probe with a file that is removed at once.
  std::string probe = (existing / ".restitution-probe-XXXXXX").string();
  const int fd = mkstemp(probe.data());
  if (fd < 0) {
    throw IoError(
        fmt::format("{}: the folder '{}' does not let this program create files in it (the system "
                    "says: {})",
                    what, existing.string(), std::strerror(errno)));
  }
  close(fd);
  unlink(probe.c_str());
}

}  // namespace

void check_output_folder(const fs::path& folder) {
  check_writable_folder(folder, {});
}

void check_output_file(const fs::path& path) {
  const OutputTarget target = output_target(path);
  if (!target.in_place) check_writable_folder(target.path.parent_path(), path);
}

void check_figure_file(const fs::path& path, const std::string& option) {
  if (output_target(path).in_place) {
    throw InvalidInput(
        fmt::format("{} '{}' is a device, a pipe or a stream, not a file: a figure is written as a "
                    "new file and renamed into place; name a file",
                    option, printable_name(path.string())));
  }
  check_output_file(path);
}

OutputTarget output_target(const fs::path& path) {
  std::error_code error;
  const fs::file_status followed = fs::status(path, error);
  if (fs::is_directory(followed)) {
    throw InvalidInput(fmt::format("'{}' is a folder, not a file", path.string()));
  }
  if (fs::exists(followed) && !fs::is_regular_file(followed)) return {path, true};  // device, FIFO, socket
  fs::path at = path;
  for (int hops = 0; fs::is_symlink(fs::symlink_status(at, error)); ++hops) {
    if (hops == 40) throw InvalidInput(fmt::format("'{}': too many levels of symbolic links", path.string()));
    const fs::path link = fs::read_symlink(at, error);
    if (error) throw InvalidInput(fmt::format("cannot read the link '{}': {}", at.string(), error.message()));
    at = link.is_absolute() ? link : at.parent_path() / link;
    // /dev/stdout -> /proc/self/fd/1: an open stream, whatever file it happens to be.
    if (at.lexically_normal().string().rfind("/proc/", 0) == 0) return {path, true};
  }
  return {at.lexically_normal(), false};
}

void write_in_place(const fs::path& path, const std::string& content) {
  const int fd =
      ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);  // NOLINT(cppcoreguidelines-pro-type-vararg)
  const int written = fd < 0 ? errno : write_all(fd, content.data(), content.size());
  const int closed = fd < 0 || ::close(fd) == 0 ? 0 : errno;
  if (written != 0 || closed != 0) {
    throw IoError(fmt::format("cannot write '{}': {}", printable_name(path.string()),
                              std::strerror(written != 0 ? written : closed)));
  }
}

void write_file_atomically(const fs::path& path, const std::string& content) {
  const OutputTarget target = output_target(path);
  if (target.in_place) {
    write_in_place(path, content);
    return;
  }
  std::error_code error;
  if (target.path.has_parent_path()) fs::create_directories(target.path.parent_path(), error);
  if (error) {
    throw IoError(fmt::format("cannot create the folder of '{}': {}", target.path.string(), error.message()));
  }
  const fs::path temporary = write_temporary_beside(target.path, content);
  fs::rename(temporary, target.path, error);
  if (error) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw IoError(fmt::format("cannot write '{}': {}", target.path.string(), error.message()));
  }
}

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
  check_figure_file(image, "the figure");  // the commands check first; a scene's figures are files
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
  const std::string token = random_name_part();
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
