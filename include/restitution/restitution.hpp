// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The restitution library in one include: contact laws, the collision solver and its engines, units and
// materials, calibration, the analytic series and the certified
// fast ε(ζ) table; which code it is (library_version(), below); and which build of SUNDIALS it carries
// (below).
#include "restitution/calibration.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/contact_law.hpp"
#include "restitution/errors.hpp"
#include "restitution/fast.hpp"
#include "restitution/fit.hpp"
#include "restitution/material.hpp"
#include "restitution/series.hpp"
#include "restitution/solve_types.hpp"
#include "restitution/sweep.hpp"
#include "restitution/units.hpp"

namespace restitution {

// Which code the library is (docs/release.md): every output that carries the SUNDIALS build names it too, so
// that a number can be traced to the code that computed it.
struct LibraryVersion {
  // "0.3.0" at a release; "0.4.0.dev252+gf916007b96cf" between releases (252 commits after it, at that
  // commit)
  const char* version;
  const char* commit;  // the 40 hex digits of the commit built, or "unknown" outside git and an sdist
};

LibraryVersion library_version();

// Which build of SUNDIALS the library's CVODE engine runs on: the program's --version and every JSON output
// say it, because it doubles or halves the cost of a CVODE solve (docs/performance.md). The numbers do not
// depend on it.
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
