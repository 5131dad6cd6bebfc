#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# cmake/version.cmake in a scratch git repository (docs/release.md): the release commit is X.Y.Z, every later
# commit X.(Y+1).0.devN+gHASH counted from the commit that changed VERSION or from the tag vX.Y.Z, a shallow
# clone says dev0, a folder that is no checkout of its own reads SDIST_VERSION, and without either the version
# is VERSION with commit "unknown".
# Usage: version_from_git.sh SOURCE_DIR
set -euo pipefail
script=$1/cmake/version.cmake
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
expect() {  # expect WHAT FOLDER VERSION COMMIT
  local got
  got=$(cmake -DROOT="$2" -P "$script" | tr '\n' ' ')
  if [ "$got" != "$3 $4 " ]; then
    echo "$1: got '$got', expected '$3 $4 '"
    status=1
  fi
}
git_() { git -C "$work/repo" -c user.name=test -c user.email=test@example.org -c commit.gpgsign=false "$@"; }

mkdir "$work/repo"
git_ init -q
echo 0.3.0 >"$work/repo/VERSION"
git_ add VERSION
git_ commit -qm "release 0.3.0"
expect "the release commit" "$work/repo" 0.3.0 "$(git_ rev-parse HEAD)"
for n in 1 2; do
  echo $n >"$work/repo/file"
  git_ add file
  git_ commit -qm "change $n"
done
expect "two commits after it" "$work/repo" "0.4.0.dev2+g$(git_ rev-parse --short=12 HEAD)" "$(git_ rev-parse HEAD)"
# A tag on the first change (not the VERSION commit) is the base when HEAD descends from it.
git_ tag v0.3.0 HEAD~1
expect "one commit after the tag" "$work/repo" "0.4.0.dev1+g$(git_ rev-parse --short=12 HEAD)" "$(git_ rev-parse HEAD)"
git_ tag -d v0.3.0 >/dev/null
echo 0.4.0 >"$work/repo/VERSION"
git_ commit -qam "release 0.4.0"
expect "the next release commit" "$work/repo" 0.4.0 "$(git_ rev-parse HEAD)"

# A shallow clone cannot count the commits: dev0, with the hash that names the commit.
echo 3 >"$work/repo/file"
git_ commit -qam "change 3"
git clone -q --depth 1 "file://$work/repo" "$work/shallow"
expect "a shallow clone" "$work/shallow" "0.5.0.dev0+g$(git_ rev-parse --short=12 HEAD)" "$(git_ rev-parse HEAD)"

# A folder inside the checkout that is no checkout itself (an unpacked sdist) reads its SDIST_VERSION.
mkdir "$work/repo/unpacked"
echo 0.3.0 >"$work/repo/unpacked/VERSION"
printf '0.4.0.dev7+gabcdef012345\n%s\n' "$(printf 'a%.0s' {1..40})" >"$work/repo/unpacked/SDIST_VERSION"
expect "an unpacked sdist" "$work/repo/unpacked" 0.4.0.dev7+gabcdef012345 "$(printf 'a%.0s' {1..40})"
rm "$work/repo/unpacked/SDIST_VERSION"
expect "neither git nor an sdist" "$work/repo/unpacked" 0.3.0 unknown

echo "0.3" >"$work/repo/unpacked/VERSION"
if cmake -DROOT="$work/repo/unpacked" -P "$script" >/dev/null 2>&1; then
  echo "VERSION '0.3' (no X.Y.Z) was accepted"
  status=1
fi
[ $status -eq 0 ] && echo "version_from_git: release, development, tag, sdist and fallback versions check out"
exit $status
