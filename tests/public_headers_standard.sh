#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The C++ standard the public headers need (docs/library.md, "C++ standard"): each include/restitution/*.hpp
# compiles alone, strictly (no GNU extensions, -Wpedantic -Werror), at the standard the package requires of its
# consumers (C++20); and at C++17 exactly the headers docs/library.md names fail (std::span in series.hpp, a
# defaulted operator== in contact_law.hpp and every header that includes it). When that set changes, the
# requirement (src/CMakeLists.txt, cmake/restitution.pc.in) and docs/library.md change with it.
# Usage: public_headers_standard.sh SOURCE_DIR [CXX]
set -euo pipefail
source=$1
cxx=${2:-c++}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
needs_cxx20="calibration.hpp collision_solver.hpp contact_law.hpp fast.hpp fit.hpp material.hpp restitution.hpp series.hpp solve_types.hpp sweep.hpp units.hpp"
status=0
failing17=""
for header in "$source"/include/restitution/*.hpp; do
  name=$(basename "$header")
  echo "#include \"restitution/$name\"" >"$work/$name.cpp"
  if ! "$cxx" -std=c++20 -Wall -Wextra -Wpedantic -Werror -fsyntax-only -I"$source/include" "$work/$name.cpp" 2>"$work/log"; then
    echo "$name does not compile alone as C++20:"; head -5 "$work/log"; status=1
  fi
  if ! "$cxx" -std=c++17 -Wall -Wextra -Wpedantic -Werror -fsyntax-only -I"$source/include" "$work/$name.cpp" 2>/dev/null; then
    failing17="$failing17${failing17:+ }$name"
  fi
done
if [ "$failing17" != "$needs_cxx20" ]; then
  echo "headers that need C++20: $failing17"
  echo "docs/library.md says:    $needs_cxx20"
  echo "update docs/library.md (and, if none is left, require C++17: src/CMakeLists.txt, cmake/restitution.pc.in)"
  status=1
fi
[ $status -eq 0 ] && echo "public headers: each compiles alone as C++20; C++17 fails where docs/library.md says"
exit $status
