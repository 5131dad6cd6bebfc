// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Where the program finds the files it ships beside itself: the plot scripts (scripts/plots), the default
// scene (scenes/default.toml) and the reference solutions (data/reference_solutions.csv).
#include <filesystem>

namespace restitution::cli {

// PREFIX/share/restitution when the program runs as PREFIX/bin/restitution after `cmake --install`
// (cmake/install.cmake puts those files there), else the source tree named by the build tree's marker beside
// the program (src/CMakeLists.txt): no path of the build machine is compiled into the program.
std::filesystem::path resource_root();

}  // namespace restitution::cli
