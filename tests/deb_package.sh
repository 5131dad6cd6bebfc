#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The Debian package (cmake/package.cmake): `cpack -G DEB` in the build folder makes it; it must hold the program,
# the man page, both libraries (the shared one with its SONAME link), the headers, restitution.pc, the CMake
# package and the docs under /usr, and carry the version of the code with Debian's "~dev". With
# RESTITUTION_DEB_INSTALL=1 (CI only: .ci/run sets it) and as root, it is installed with dpkg -i, checked as an
# installation by tests/install_consumer.sh (the program's --version, the pkg-config, CMake and shared-library
# consumers, the man page) and removed again; elsewhere, since dpkg -i writes to /usr, the package is unpacked
# into a scratch folder and that is checked the same way.
# Usage: deb_package.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# What the package installs must be built (a no-op after scripts/test's full build).
targets=(restitution restitution_lib restitution_shared restitution_man_page)
if cmake --build "$build" --target help | grep -q '^_restitution:'; then targets+=(_restitution); fi  # the Python module
cmake --build "$build" --target "${targets[@]}" >/dev/null
(cd "$build" && cpack -G DEB -B "$work" >"$work/cpack.log" 2>&1) || { tail -30 "$work/cpack.log"; echo "cpack failed"; exit 1; }
deb=$(ls "$work"/restitution_*.deb)
version=$(cmake -DROOT="$source" -P "$source/cmake/version.cmake" | sed -n 1p)
deb_version=$(dpkg-deb -f "$deb" Version)
[ "$deb_version" = "${version/.dev/~dev}" ] || { echo "package version $deb_version, code version $version"; exit 1; }
soname="librestitution.so.$(cut -d. -f1,2 <<<"$version")"
contents=$(dpkg-deb -c "$deb" | awk '{ print $6 }')
for path in usr/bin/restitution usr/share/man/man1/restitution.1 usr/lib/librestitution.a "usr/lib/$soname" \
  usr/lib/librestitution.so usr/include/restitution/restitution.hpp usr/lib/pkgconfig/restitution.pc \
  usr/lib/cmake/restitution/restitutionConfig.cmake usr/share/doc/restitution/cli.md \
  usr/share/restitution/scenes/default.toml; do
  grep -qx "\./$path" <<<"$contents" || { echo "$(basename "$deb") lacks /$path"; exit 1; }
done
depends=$(dpkg-deb -f "$deb" Depends)
grep -q "libstdc++6" <<<"$depends" || { echo "Depends lacks libstdc++6 (dpkg-shlibdeps): '$depends'"; exit 1; }
echo "deb_package: $(basename "$deb"), $(wc -l <<<"$contents") entries, Depends: $depends"

if [ "${RESTITUTION_DEB_INSTALL:-0}" != 1 ] || [ "$(id -u)" -ne 0 ]; then
  # No root, or not CI: the package's files, unpacked into a scratch folder, checked as an installation there
  # (every installed file finds the others relative to itself).
  dpkg-deb -x "$deb" "$work/root"
  RESTITUTION_INSTALLED_PREFIX="$work/root/usr" bash "$source/tests/install_consumer.sh" "$build" "$source"
  echo "deb_package: the unpacked package checks out (dpkg -i: RESTITUTION_DEB_INSTALL=1 as root, CI only)"
  exit 0
fi
# Installed means dpkg's status "install ok installed": a package removed with its configuration left ("rc") is
# not installed, and is purged like the one this check installs.
if dpkg-query -W -f='${Status}' restitution 2>/dev/null | grep -q ' installed$' || [ -e /usr/bin/restitution ]; then
  echo "deb_package: restitution is installed on this machine already; not replacing it"
  exit 1
fi
trap 'dpkg --purge restitution >/dev/null 2>&1 || true; rm -rf "$work"' EXIT
dpkg -i "$deb" >/dev/null
[ "$(/usr/bin/restitution --version | sed -n 1p)" = "restitution $version" ] ||
  { echo "/usr/bin/restitution --version: $(/usr/bin/restitution --version | sed -n 1p), expected restitution $version"; exit 1; }
RESTITUTION_INSTALLED_PREFIX=/usr bash "$source/tests/install_consumer.sh" "$build" "$source"
echo "deb_package: dpkg -i, /usr/bin/restitution --version and the consumers check out; purged again"
