#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# `cmake -S . -B b` on a fresh clone, as a user who is not root and without a network, touches nothing outside
# the clone: no apt-get (or other package tool) runs, and no file or folder is created, renamed or removed
# outside it except the compiler's temporaries under TMPDIR. Traced with strace; needs root to drop to `nobody`
# in a network namespace of its own, and skips (77) where it cannot.
# Usage: configure_leaves_host_alone.sh SOURCE_DIR
set -euo pipefail
source=$1
if [ "$(id -u)" -ne 0 ] || ! command -v strace >/dev/null || ! command -v unshare >/dev/null; then
  echo "needs root, strace and unshare: skipped"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
git clone -q "$source" "$work/clone"
mkdir "$work/tmp"
chown -R nobody "$work"
(cd "$work/clone" && TMPDIR="$work/tmp" unshare -n runuser -u nobody -- \
  strace -f -qq -e trace=execve,openat,creat,mkdir,rename,unlink,symlink -o "$work/trace" \
  cmake -S . -B b >"$work/configure.log" 2>&1) || { cat "$work/configure.log"; exit 1; }

status=0
packaging=$(grep -E 'execve\("[^"]*/(apt|apt-get|apt-cache|dpkg-source|sudo)"' "$work/trace" | grep -v -- '= -1' || true)
if [ -n "$packaging" ]; then
  echo "configure ran a package tool:"
  echo "$packaging"
  status=1
fi
# Paths of successful writes (relative ones are under the working folder, inside the clone).
written=$(grep -E 'openat\(.*(O_WRONLY|O_RDWR|O_CREAT)|(mkdir|rename|unlink|creat|symlink)\(' "$work/trace" |
  grep -v -- '= -1' | grep -oE '"/[^"]*"' | tr -d '"' | sort -u)
outside=$(grep -vE "^($work/clone|$work/tmp)(/|$)|^/dev/(null|tty)$" <<<"$written" || true)
if [ -n "$outside" ]; then
  echo "configure wrote outside the clone:"
  echo "$outside"
  status=1
fi
[ $status -eq 0 ] && echo "configure as nobody without a network: no package tool, nothing written outside the clone"
exit $status
