#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The C++ standard the public headers need (docs/library.md, "C++ standard"): each include/restitution/*.hpp
# compiles alone, strictly (no GNU extensions, -Wpedantic -Werror), as C++17, the standard the package requires of
# its consumers (src/CMakeLists.txt: cxx_std_17; restitution.pc passes no -std), and as C++20, the library's own.
# Most DEM codes are C++17: a header that needs more locks them out of the C++ API.
# Usage: public_headers_standard.sh SOURCE_DIR [CXX]
set -euo pipefail
source=$1
cxx=${2:-c++}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
for header in "$source"/include/restitution/*.hpp; do
  name=$(basename "$header")
  echo "#include \"restitution/$name\"" >"$work/$name.cpp"
  for standard in c++17 c++20; do
    if ! "$cxx" -std=$standard -Wall -Wextra -Wpedantic -Werror -fsyntax-only -I"$source/include" "$work/$name.cpp" \
      2>"$work/log"; then
      echo "$name does not compile alone as $standard:"
      head -5 "$work/log"
      status=1
    fi
  done
done
[ $status -eq 0 ] && echo "public headers: each compiles alone as C++17 and as C++20"
exit $status
