// SPDX-License-Identifier: BSD-3-Clause
#include "restitution/restitution.hpp"

// RESTITUTION_SUNDIALS_VERSION, RESTITUTION_SUNDIALS_OPTIMIZED, RESTITUTION_SUNDIALS_PATCHES and
// RESTITUTION_SUNDIALS_SOURCE come from cmake/sundials.cmake.
namespace restitution {

SundialsBuild sundials_build() {
  return {RESTITUTION_SUNDIALS_VERSION, RESTITUTION_SUNDIALS_OPTIMIZED != 0};
}

const char* sundials_build_description() {
  constexpr const char* optimized = RESTITUTION_SUNDIALS_VERSION
      " (optimized, built from " RESTITUTION_SUNDIALS_SOURCE "; patches: " RESTITUTION_SUNDIALS_PATCHES ")";
  constexpr const char* system = RESTITUTION_SUNDIALS_VERSION " (Debian's libsundials, unoptimized)";
  return RESTITUTION_SUNDIALS_OPTIMIZED != 0 ? optimized : system;
}

}  // namespace restitution
