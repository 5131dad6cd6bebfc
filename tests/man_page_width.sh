#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The man page (cmake/manpage.cmake) fits a terminal of 80 columns: rendered with MANWIDTH=80, no line is wider,
# and its SEE ALSO names the installed documentation (share/doc/restitution, cmake/install.cmake).
# Usage: man_page_width.sh BUILD_DIR/restitution.1
set -euo pipefail
page=$1
test -f "$page" || { echo "no $page: build the target restitution_man_page first"; exit 1; }
rendered=$(LC_ALL=C.UTF-8 MANWIDTH=80 man -l "$page" 2>/dev/null)
[ "$(wc -l <<<"$rendered")" -gt 100 ] || { echo "man -l $page rendered only:"; echo "$rendered"; exit 1; }
wide=$(awk '{ if (length($0) > 80) printf "%d: %d columns: %s\n", NR, length($0), $0 }' <<<"$rendered")
if [ -n "$wide" ]; then
  echo "man -l $page at MANWIDTH=80 has $(wc -l <<<"$wide") lines wider than 80 columns:"
  head -20 <<<"$wide"
  exit 1
fi
see_also=$(sed -n '/^SEE ALSO/,$p' <<<"$rendered")
grep -q "share/doc/restitution" <<<"$see_also" || { echo "SEE ALSO does not name share/doc/restitution:"; echo "$see_also"; exit 1; }
echo "man_page_width: $(wc -l <<<"$rendered") lines, none wider than 80 columns; SEE ALSO names share/doc/restitution"
