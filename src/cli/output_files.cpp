#include "cli/output_files.hpp"

#include <fmt/core.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <system_error>

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
  return chosen != nullptr ? fs::path(chosen) : fs::path(RESTITUTION_SCRIPTS_DIR);
}

std::string quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

void prepare_output_folder(const fs::path& folder) {
  std::error_code error;
  fs::create_directories(folder, error);
  if (error || !fs::is_directory(folder)) {
    throw IoError(fmt::format("cannot create output folder '{}': {}", folder.string(),
                              error ? error.message() : "not a folder"));
  }
  if (access(folder.c_str(), W_OK) != 0) {
    throw IoError(fmt::format("output folder '{}' is not writable", folder.string()));
  }
}

void write_file_atomically(const fs::path& path, const std::string& content) {
  const fs::path temporary = path.string() + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw IoError(fmt::format("cannot write '{}'", temporary.string()));
    out << content;
    out.flush();
    if (!out) throw IoError(fmt::format("cannot write '{}'", temporary.string()));
  }
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) {
    fs::remove(temporary, error);
    throw IoError(fmt::format("cannot write '{}'", path.string()));
  }
}

std::string number17(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return fmt::format("{:.17g}", value);
}

std::string run_plot_script(const std::string& script, const std::vector<std::string>& arguments) {
  const fs::path path = scripts_folder() / "plots" / (script + ".py");
  if (!fs::exists(path)) return fmt::format("no plot: script {} not found", path.string());
  const std::string python = python_interpreter();
  const std::string probe = quoted(python) + " -c 'import matplotlib' >/dev/null 2>&1";
  if (std::system(probe.c_str()) != 0) {
    return fmt::format(
        "no plot: {} cannot import matplotlib (install python3-matplotlib: bash scripts/setup)", python);
  }
  std::string command = quoted(python) + " " + quoted(path.string());
  for (const std::string& a : arguments) command += " " + quoted(a);
  command += " >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  if (status != 0) {
    return fmt::format("no plot: {} failed with status {}", path.filename().string(),
                       WIFEXITED(status) ? WEXITSTATUS(status) : -1);
  }
  return {};
}

}  // namespace restitution::cli
