// SPDX-License-Identifier: BSD-3-Clause
#include "files/file_set.hpp"

#include <fmt/core.h>

#include <optional>
#include <system_error>

#include "files/output_files.hpp"
#include "files/temporary_file.hpp"
#include "restitution/errors.hpp"

namespace restitution::files {
namespace fs = std::filesystem;

void write_file_set(const std::vector<SetMember>& members, const std::function<void()>& stop_check) {
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
      stop_check();
      if (targets[i].in_place) continue;
      create_folder_of(targets[i].path);
      temporaries[i] = write_temporary_beside(targets[i].path, *members[i].content);
    }
    stop_check();
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
    try {
      rename_onto(*temporaries[i], targets[i].path);
    } catch (const IoError&) {
      remove_temporaries();
      std::error_code ignored;
      for (std::size_t k = 0; k < i; ++k) {
        if (!targets[k].in_place) fs::remove(targets[k].path, ignored);  // part of a set runs nothing
      }
      throw;
    }
    temporaries[i].reset();
  }
}

}  // namespace restitution::files
