// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Which code the library is (docs/release.md): every output that carries the SUNDIALS build names it too, so
// that a number can be traced to the code that computed it.
namespace restitution {

struct LibraryVersion {
  // "0.3.0" at a release; "0.4.0.dev252+gf916007b96cf" between releases (252 commits after it, at that
  // commit)
  const char* version;
  const char* commit;  // the 40 hex digits of the commit built, or "unknown" outside git and an sdist
};

LibraryVersion library_version();

}  // namespace restitution
