// SPDX-License-Identifier: BSD-3-Clause
#include "files/resolved_path.hpp"

#include <system_error>

namespace restitution::files {
namespace fs = std::filesystem;

fs::path resolved_path(const fs::path& path) {
  constexpr int kMaxLinks = 40;  // as the kernel's ELOOP
  std::error_code error;
  fs::path at = fs::absolute(path, error);
  if (error) return path.lexically_normal();
  if (!at.has_filename()) at = at.parent_path();  // "out/" names "out"
  for (int hops = 0; hops < kMaxLinks; ++hops) {
    // The folders above first: a link among them changes where the last part's own link points from.
    const fs::path folder = fs::weakly_canonical(at.parent_path(), error);
    if (error) return at.lexically_normal();
    at = folder / at.filename();
    if (!fs::is_symlink(fs::symlink_status(at, error))) break;
    const fs::path target = fs::read_symlink(at, error);
    if (error) break;
    at = target.is_absolute() ? target : folder / target;
  }
  return at.lexically_normal();
}

bool resolves_within(const fs::path& path, const fs::path& folder) {
  const fs::path p = resolved_path(path);
  const fs::path f = resolved_path(folder);
  auto at = p.begin();
  for (auto part = f.begin(); part != f.end(); ++part, ++at) {
    if (part->empty()) continue;  // a trailing separator
    if (at == p.end() || *at != *part) return false;
  }
  return true;
}

}  // namespace restitution::files
