// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/output_guards.hpp"

#include <fmt/core.h>

#include "cli/common/output_files.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {
namespace fs = std::filesystem;

void check_output_is_not_input(const fs::path& output, const std::vector<fs::path>& inputs) {
  std::error_code error;
  if (!fs::exists(output, error)) return;  // a file that does not exist yet is no input
  for (const fs::path& input : inputs) {
    if (fs::equivalent(output, input, error)) {
      throw InvalidInput(
          fmt::format("--output '{}' is the input '{}': writing it would replace the input; "
                      "name another file",
                      output.string(), input.string()));
    }
  }
}

void check_no_folder_through_link(const fs::path& output) {
  std::error_code error;
  if (!fs::is_symlink(fs::symlink_status(output, error))) return;
  const fs::path target = output_target(output).path;
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::is_directory(folder, error)) {
    throw InvalidInput(
        fmt::format("--output '{}' is a link to '{}', whose folder does not exist: create it, "
                    "or name another file",
                    output.string(), target.string()));
  }
}

}  // namespace restitution::cli
