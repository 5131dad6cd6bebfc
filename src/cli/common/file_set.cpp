// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/file_set.hpp"

#include <fmt/core.h>

#include <optional>
#include <system_error>

#include "cli/common/output_files.hpp"
#include "cli/common/stop_signals.hpp"
#include "restitution/errors.hpp"
#include "sweep/temporary_file.hpp"

namespace restitution::cli {
namespace fs = std::filesystem;

void write_file_set(const std::vector<SetMember>& members) {
  std::vector<OutputTarget> targets;
  targets.reserve(members.size());
  for (const SetMember& m : members) targets.push_back(output_target(m.path));
  std::vector<std::optional<fs::path>> temporaries(members.size());
  const auto remove_temporaries = [&temporaries] {
    std::error_code ignored;
    for (const auto& t : temporaries) {
      if (t) fs::remove(*t, ignored);
    }
  };
  try {
    for (std::size_t i = 0; i < members.size(); ++i) {
      throw_if_interrupted();
      if (targets[i].in_place) continue;
      std::error_code error;
      if (targets[i].path.has_parent_path()) fs::create_directories(targets[i].path.parent_path(), error);
      if (error) {
        throw IoError(
            fmt::format("cannot create the folder of '{}': {}", targets[i].path.string(), error.message()));
      }
      temporaries[i] = write_temporary_beside(targets[i].path, *members[i].content);
    }
    throw_if_interrupted();
  } catch (...) {
    remove_temporaries();
    throw;
  }
  // From here on the set is finished whatever happens: a half-replaced set is worse than a late stop.
  for (std::size_t i = members.size(); i-- > 0;) {
    std::error_code ignored;
    if (!targets[i].in_place) fs::remove(targets[i].path, ignored);
  }
  for (std::size_t i = 0; i < members.size(); ++i) {
    if (targets[i].in_place) {
      write_in_place(targets[i].path, *members[i].content);
      continue;
    }
    std::error_code error;
    fs::rename(*temporaries[i], targets[i].path, error);
    if (error) {
      remove_temporaries();
      std::error_code ignored;
      for (std::size_t k = 0; k < i; ++k) {
        if (!targets[k].in_place) fs::remove(targets[k].path, ignored);  // part of a set runs nothing
      }
      throw IoError(fmt::format("cannot write '{}': {}", targets[i].path.string(), error.message()));
    }
    temporaries[i].reset();
  }
}

}  // namespace restitution::cli
