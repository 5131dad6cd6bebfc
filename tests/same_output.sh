#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Runs two programs and passes when their standard outputs are the same bytes; otherwise shows where they differ.
# Usage: tests/same_output.sh PROGRAM_A PROGRAM_B
set -euo pipefail
a=$(mktemp)
b=$(mktemp)
trap 'rm -f "$a" "$b"' EXIT
"$1" >"$a"
"$2" >"$b"
if cmp -s "$a" "$b"; then
  echo "same output: $(wc -l <"$a") lines"
  exit 0
fi
echo "the outputs differ (first lines of the diff):"
diff "$a" "$b" | head -n 20
exit 1
