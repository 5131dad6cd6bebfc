// SPDX-License-Identifier: BSD-3-Clause
#include "restitution/restitution.hpp"

// RESTITUTION_LIBRARY_VERSION and RESTITUTION_LIBRARY_COMMIT come from cmake/version.cmake, set on this file
// alone (src/CMakeLists.txt), so that a new commit recompiles one file.
namespace restitution {

LibraryVersion library_version() {
  return {RESTITUTION_LIBRARY_VERSION, RESTITUTION_LIBRARY_COMMIT};
}

}  // namespace restitution
