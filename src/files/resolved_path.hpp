// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The one name of the place a path leads to, for comparing outputs with inputs and for the locks on outputs:
// two names of one file (a symbolic link to it, a link to its folder, `a/../b`) resolve alike, whether or not
// the file exists yet.
#include <filesystem>

namespace restitution::files {

// `path` made absolute, every symbolic link followed, its last part's too when it dangles (where writing
// would create the file), and `.`/`..` resolved. Parts that do not exist yet are kept as written. A loop of
// links is left where it loops (the write itself then fails and says so).
std::filesystem::path resolved_path(const std::filesystem::path& path);

// True when the resolved `path` is the resolved `folder` or lies below it.
bool resolves_within(const std::filesystem::path& path, const std::filesystem::path& folder);

}  // namespace restitution::files
