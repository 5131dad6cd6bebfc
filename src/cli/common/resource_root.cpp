// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/resource_root.hpp"

#include <fstream>
#include <string>
#include <system_error>

namespace restitution::cli {

namespace fs = std::filesystem;

namespace {

// The build tree's marker (src/CMakeLists.txt): a file restitution-source-tree holding the source tree's
// path, in the program's folder or one above it (the test programs run from build/<preset>/tests/).
fs::path marked_source_tree(const fs::path& program_folder) {
  fs::path folder = program_folder;
  for (int level = 0; level < 2 && !folder.empty(); ++level, folder = folder.parent_path()) {
    std::ifstream marker(folder / "restitution-source-tree");
    std::string source;
    if (marker && std::getline(marker, source) && !source.empty()) return source;
  }
  return {};
}

}  // namespace

fs::path resource_root() {
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);  // Linux: this program's own file
  if (error) return fs::current_path(error);
  fs::path installed = program.parent_path().parent_path() / "share" / "restitution";
  if (fs::is_directory(installed, error)) return installed;
  fs::path source = marked_source_tree(program.parent_path());
  // Neither installed nor in a build tree: the program's own folder, where the files are then reported
  // missing by name.
  return source.empty() ? program.parent_path() : source;
}

}  // namespace restitution::cli
