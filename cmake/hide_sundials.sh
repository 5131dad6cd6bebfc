#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Makes the CVODE that the installed librestitution.a carries invisible to its consumers: every object of the
# archive is linked into one relocatable object (ld -r), and each global symbol that the SUNDIALS objects define
# (CVode*, N_V*, SUN*, and their internal helpers) becomes local to it. restitution's own calls were resolved
# inside that object, so they keep the optimized copy; a consumer that links its own SUNDIALS (any version) gets
# its own, and neither can take the other's place.
# Usage: hide_sundials.sh ARCHIVE SUNDIALS_OBJECT...   (run by `cmake --install`, cmake/install.cmake)
set -euo pipefail
archive=$1
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

nm --defined-only --extern-only --format=posix "$@" 2>/dev/null | awk 'NF >= 2 && $2 != "U" { print $1 }' |
  sort -u >"$work/sundials_symbols"
[ -s "$work/sundials_symbols" ] || { echo "hide_sundials: no symbol defined by the SUNDIALS objects" >&2; exit 1; }
ld -r --whole-archive "$archive" -o "$work/restitution.o"
objcopy --localize-symbols="$work/sundials_symbols" "$work/restitution.o"
rm -f "$work/librestitution.a"
ar rcs "$work/librestitution.a" "$work/restitution.o"
# The file is replaced only when it is complete.
cp "$work/librestitution.a" "$archive.hiding"
mv "$archive.hiding" "$archive"
