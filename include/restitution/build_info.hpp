// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Which build of SUNDIALS the library's CVODE engine runs on: the program's --version and every JSON output
// say it, because it doubles or halves the cost of a CVODE solve (docs/performance.md). The numbers do not
// depend on it.

namespace restitution {

struct SundialsBuild {
  const char* version;  // e.g. "6.4.1"
  // true: CVODE compiled -O3 from Debian's source package (scripts/sundials) and carried inside the library;
  // false: Debian's libsundials-dev, compiled without optimization.
  bool optimized;
};

SundialsBuild sundials_build();
// "6.4.1 (optimized, built from Debian's source package)" | "6.4.1 (Debian's libsundials, unoptimized)"
const char* sundials_build_description();

}  // namespace restitution
