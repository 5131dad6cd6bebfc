#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The Debian packages (cmake/package.cmake): restitution (program, man page, data, docs), librestitutionX.Y (the
# shared library), librestitution-dev (headers, static library, restitution.pc, CMake package) and, if the Python
# module is built, python3-restitution. They are packed from a build configured for the prefix /usr (Debian's
# layout: lib/<multiarch triplet>, lib/python3/dist-packages), the folder deb beside BUILD_DIR, configured like
# BUILD_DIR otherwise (same compiler and launcher: with ccache its objects are BUILD_DIR's). Each package must
# carry the version of the code with Debian's "~dev" and the revision -1, and lintian must report no error and
# no warning on it. With RESTITUTION_DEB_INSTALL=1 (CI only: .ci/run sets it) and as root, all are installed
# with dpkg -i and checked as an installation: --version, tests/install_consumer.sh (the CMake, pkg-config and
# shared-library consumers, the man page), tests/c_header_example.sh (the exported C header) and the Python
# module imported by /usr/bin/python3 outside the source tree; then purged, and nothing of them may be left.
# Elsewhere, since dpkg -i writes to /usr, the packages are unpacked into a scratch folder and checked there.
# Usage: deb_package.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cached() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt"; }
package_build="$(dirname "$build")/deb"
options=(-DCMAKE_INSTALL_PREFIX=/usr -DCMAKE_BUILD_TYPE="$(cached CMAKE_BUILD_TYPE)"
  -DCMAKE_CXX_COMPILER="$(cached CMAKE_CXX_COMPILER)" -DRESTITUTION_BUILD_TESTS=OFF -DRESTITUTION_BUILD_BENCH=OFF)
for variable in CMAKE_CXX_COMPILER_LAUNCHER RESTITUTION_BUILD_PYTHON RESTITUTION_SUNDIALS_OPTIMIZED; do
  value=$(cached "$variable")
  if [ -n "$value" ]; then options+=("-D$variable=$value"); fi
done
cmake -S "$source" -B "$package_build" -G "$(cached CMAKE_GENERATOR)" "${options[@]}" >"$work/configure.log" 2>&1 ||
  { tail -30 "$work/configure.log"; echo "configuring $package_build failed"; exit 1; }
targets=(restitution restitution_lib restitution_shared restitution_man_page restitution_deb_changelog)
# A here-string, not `| grep -q`: grep -q leaves at the first match, and under pipefail the writer's SIGPIPE would
# count as "no Python module" and silently drop its package.
help=$(cmake --build "$package_build" --target help)
python=$(grep -c '^_restitution:' <<<"$help" || true)
if [ "$python" -gt 0 ]; then targets+=(_restitution); fi
cmake --build "$package_build" --target "${targets[@]}" >"$work/build.log" 2>&1 ||
  { tail -30 "$work/build.log"; echo "building $package_build failed"; exit 1; }
(cd "$package_build" && cpack -G DEB -B "$work" >"$work/cpack.log" 2>&1) || { tail -30 "$work/cpack.log"; echo "cpack failed"; exit 1; }

version=$(cmake -DROOT="$source" -P "$source/cmake/version.cmake" | sed -n 1p)
soversion=$(cut -d. -f1,2 <<<"$version")
soname="librestitution.so.$soversion"
triplet=$(dpkg-architecture -qDEB_HOST_MULTIARCH)
libdir="usr/lib/$triplet"
declare -A expected=(
  [restitution]="usr/bin/restitution usr/share/man/man1/restitution.1.gz usr/share/doc/restitution/cli.md
    usr/share/restitution/scenes/default.toml"
  ["librestitution$soversion"]="$libdir/$soname"
  [librestitution-dev]="$libdir/librestitution.a $libdir/librestitution.so usr/include/restitution/restitution.hpp
    $libdir/pkgconfig/restitution.pc $libdir/cmake/restitution/restitutionConfig.cmake"
)
if [ "$python" -gt 0 ]; then
  expected[python3-restitution]="usr/lib/python3/dist-packages/restitution/__init__.py"
fi
debs=()
status=0
for package in "${!expected[@]}"; do
  deb=$(find "$work" -maxdepth 1 -name "${package}_*.deb")
  [ -n "$deb" ] || { echo "cpack made no package $package: $(cd "$work" && ls ./*.deb)"; exit 1; }
  debs+=("$deb")
  deb_version=$(dpkg-deb -f "$deb" Version)
  [ "$deb_version" = "${version/.dev/~dev}-1" ] || { echo "$package: version $deb_version, code version $version"; exit 1; }
  contents=$(dpkg-deb -c "$deb" | awk '{ print $6 }')
  for path in ${expected[$package]} "usr/share/doc/$package/copyright" "usr/share/doc/$package/changelog.Debian.gz"; do
    grep -qx "\./$path" <<<"$contents" || { echo "$(basename "$deb") lacks /$path"; exit 1; }
  done
  echo "deb_package: $(basename "$deb"), $(grep -vc '/$' <<<"$contents") files, Depends: $(dpkg-deb -f "$deb" Depends)"
  # Default level: errors and warnings (pedantic and informational tags are not shown).
  tags=$(lintian --fail-on none "$deb" 2>&1 | grep -E '^[EW]: ' || true)
  if [ -n "$tags" ]; then
    echo "lintian on $(basename "$deb"):"
    echo "$tags"
    status=1
  fi
done
[ $status -eq 0 ] || { echo "deb_package: lintian reports errors or warnings (above)"; exit 1; }
grep -q "libstdc++6" <<<"$(dpkg-deb -f "$work"/restitution_*.deb Depends)" ||
  { echo "restitution's Depends lacks libstdc++6 (dpkg-shlibdeps)"; exit 1; }
echo "deb_package: ${#debs[@]} packages, lintian reports no error and no warning"

if [ "${RESTITUTION_DEB_INSTALL:-0}" != 1 ] || [ "$(id -u)" -ne 0 ]; then
  # No root, or not CI: the packages' files, unpacked into a scratch folder, checked as an installation there
  # (every installed file finds the others relative to itself).
  for deb in "${debs[@]}"; do dpkg-deb -x "$deb" "$work/root"; done
  RESTITUTION_INSTALLED_PREFIX="$work/root/usr" bash "$source/tests/install_consumer.sh" "$package_build" "$source"
  echo "deb_package: the unpacked packages check out (dpkg -i: RESTITUTION_DEB_INSTALL=1 as root, CI only)"
  exit 0
fi
# Installed means dpkg's status "install ok installed": a package removed with its configuration left ("rc") is
# not installed, and is purged like the ones this check installs.
packages=("${!expected[@]}")
for package in "${packages[@]}"; do
  if grep -q ' installed$' <<<"$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)"; then
    echo "deb_package: $package is installed on this machine already; not replacing it"
    exit 1
  fi
done
[ ! -e /usr/bin/restitution ] || { echo "deb_package: /usr/bin/restitution exists already; not replacing it"; exit 1; }
trap 'dpkg --purge "${packages[@]}" >/dev/null 2>&1 || true; rm -rf "$work"' EXIT
dpkg -i "${debs[@]}" >"$work/dpkg.log" 2>&1 || { cat "$work/dpkg.log"; echo "dpkg -i failed"; exit 1; }
[ "$(/usr/bin/restitution --version | sed -n 1p)" = "restitution $version" ] ||
  { echo "/usr/bin/restitution --version: $(/usr/bin/restitution --version | sed -n 1p), expected restitution $version"; exit 1; }
RESTITUTION_INSTALLED_PREFIX=/usr bash "$source/tests/install_consumer.sh" "$package_build" "$source"
bash "$source/tests/c_header_example.sh" /usr/bin/restitution "$source"
if [ "$python" -gt 0 ]; then
  # From the scratch folder: the source tree's python/ must not be what is imported.
  imported=$(cd "$work" && /usr/bin/python3 -c "import restitution; print(restitution.__file__); print(restitution.eps(1.0))")
  [[ "$(sed -n 1p <<<"$imported")" == /usr/lib/python3/dist-packages/restitution/* ]] ||
    { echo "python3 imported restitution from $(sed -n 1p <<<"$imported")"; exit 1; }
  echo "deb_package: python3 -c 'import restitution; print(restitution.eps(1.0))': $(sed -n 2p <<<"$imported")"
fi
files=$(for package in "${packages[@]}"; do dpkg -L "$package"; done | sort -u)
dpkg --purge "${packages[@]}" >"$work/purge.log" 2>&1 || { cat "$work/purge.log"; echo "dpkg --purge failed"; exit 1; }
trap 'rm -rf "$work"' EXIT
for package in "${packages[@]}"; do
  if dpkg -L "$package" >/dev/null 2>&1; then echo "dpkg -L $package still lists files after the purge"; exit 1; fi
done
# The packages' own files (folders like /usr/lib are shared with others) must all be gone.
left=$(while read -r path; do if [ -e "$path" ] && [ ! -d "$path" ]; then echo "$path"; fi; done <<<"$files")
[ -z "$left" ] || { echo "left after the purge:"; echo "$left"; exit 1; }
echo "deb_package: dpkg -i, --version, the C++, C-header and Python consumers check out; purged, nothing left"
