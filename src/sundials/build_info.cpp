// SPDX-License-Identifier: BSD-3-Clause
#include "restitution/build_info.hpp"

// RESTITUTION_SUNDIALS_VERSION and RESTITUTION_SUNDIALS_OPTIMIZED come from cmake/sundials.cmake.
namespace restitution {

SundialsBuild sundials_build() {
  return {RESTITUTION_SUNDIALS_VERSION, RESTITUTION_SUNDIALS_OPTIMIZED != 0};
}

const char* sundials_build_description() {
  return RESTITUTION_SUNDIALS_OPTIMIZED != 0
             ? RESTITUTION_SUNDIALS_VERSION " (optimized, built from Debian's source package)"
             : RESTITUTION_SUNDIALS_VERSION " (Debian's libsundials, unoptimized)";
}

}  // namespace restitution
