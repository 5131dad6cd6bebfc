// SPDX-License-Identifier: BSD-3-Clause
#include "files/output_guards.hpp"

#include <fmt/core.h>

#include "files/output_files.hpp"
#include "files/printable_name.hpp"
#include "files/resolved_path.hpp"
#include "restitution/errors.hpp"

namespace restitution::files {
namespace fs = std::filesystem;

namespace {

std::string labelled(const NamedPath& p) {
  return p.option.empty() ? fmt::format("'{}'", printable_name(p.path.string()))
                          : fmt::format("{} '{}'", p.option, printable_name(p.path.string()));
}

}  // namespace

bool same_file_place(const fs::path& output, const fs::path& other) {
  std::error_code error;
  if (fs::exists(output, error) && fs::exists(other, error) && fs::equivalent(output, other, error))
    return true;
  return resolved_path(output) == resolved_path(other);
}

void check_outputs_apart(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    for (const NamedPath& input : inputs) {
      if (same_file_place(outputs[i].path, input.path)) {
        throw InvalidInput(
            fmt::format("{} is the input {}: writing it would replace the input; name another file",
                        labelled(outputs[i]), labelled(input)));
      }
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (same_file_place(outputs[i].path, outputs[j].path)) {
        throw InvalidInput(
            fmt::format("{} and {} are the same file: one would replace the other; name two files",
                        labelled(outputs[j]), labelled(outputs[i])));
      }
    }
  }
}

}  // namespace restitution::files
