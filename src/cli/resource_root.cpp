// SPDX-License-Identifier: BSD-3-Clause
#include "cli/resource_root.hpp"

#include <system_error>

namespace restitution::cli {

std::filesystem::path resource_root() {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);  // Linux: this program's own file
  if (!error) {
    fs::path installed = program.parent_path().parent_path() / "share" / "restitution";
    if (fs::is_directory(installed, error)) return installed;
  }
  return fs::path(RESTITUTION_SCRIPTS_DIR).parent_path();  // the source tree (src/CMakeLists.txt)
}

}  // namespace restitution::cli
