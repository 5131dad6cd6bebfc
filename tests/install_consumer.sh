#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The library as a product: installs the build into a temporary prefix, checks the installed header set,
# builds examples/cpp against the installed package from a separate folder (strict ISO C++, warnings as
# errors: the public headers need no GNU extension), runs it and compares its ε at both ends with
# data/reference_solutions.csv within the solver's accuracy contract |ε - ε_ref| <= tol · min(ε, 1 - ε).
# The same app is then built without CMake, by `c++ app.cpp $(pkg-config --cflags --libs restitution)` alone,
# and checked the same way, and once more against the shared library (-lrestitution: its SONAME, its exports).
# The installed program answers --version with the version cmake/version.cmake computes, as does
# pkg-config --modversion, its man page (help2man) renders with `man -l`, and it runs the default scene from the
# installed share/restitution.
# Usage: install_consumer.sh BUILD_DIR SOURCE_DIR   (RESTITUTION_INSTALLED_PREFIX=P: check P, install nothing)
set -euo pipefail
build=$1
source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# RESTITUTION_INSTALLED_PREFIX=/usr checks an installation made otherwise (tests/deb_package.sh: the .deb).
prefix=${RESTITUTION_INSTALLED_PREFIX:-$work/prefix}
if [ -z "${RESTITUTION_INSTALLED_PREFIX:-}" ]; then
  cmake --install "$build" --prefix "$prefix" >/dev/null
fi
# The libraries' folder the build was configured with: lib, or lib/<multiarch triplet> for the prefix /usr.
libdir="$prefix/$(sed -n 's/^CMAKE_INSTALL_LIBDIR:[A-Z]*=//p' "$build/CMakeCache.txt")"

headers=$(cd "$prefix/include/restitution" && ls | tr '\n' ' ')
expected="adhesion.hpp adhesive_calibration.hpp adhesive_contact.hpp calibration.hpp collision_solver.hpp contact_law.hpp errors.hpp fast.hpp fit.hpp head_on_parameters.hpp material.hpp parameter_rows.hpp parameter_table.hpp restitution.hpp series.hpp solve_types.hpp sweep.hpp units.hpp "
if [ "$headers" != "$expected" ]; then
  echo "installed headers: $headers"
  echo "expected:          $expected"
  exit 1
fi
if grep -nE '__float128|quadmath|<Eigen|<toml|<boost|<fmt|<sundials|<cvode' "$prefix/include/restitution/"*.hpp; then
  echo "a public header needs a private dependency (above)"
  exit 1
fi
for f in restitutionConfig.cmake restitutionConfigVersion.cmake restitutionTargets.cmake; do
  test -f "$libdir/cmake/restitution/$f" || { echo "missing $libdir/cmake/restitution/$f"; exit 1; }
done

version=$(cmake -DROOT="$source" -P "$source/cmake/version.cmake" | sed -n 1p)  # docs/release.md
program_version=$("$prefix/bin/restitution" --version | head -1)  # the next line names the SUNDIALS build
if [ "$program_version" != "restitution $version" ]; then
  echo "installed bin/restitution --version: $program_version, VERSION: $version"
  exit 1
fi
export PKG_CONFIG_PATH="$libdir/pkgconfig"
if [ "$(pkg-config --modversion restitution)" != "$version" ]; then
  echo "pkg-config --modversion restitution: $(pkg-config --modversion restitution), VERSION: $version"
  exit 1
fi
# No flag of our own: restitution.pc brings every library and no -std, so this is C++17, g++ 12's default.
# shellcheck disable=SC2046  # pkg-config's output is a list of words
c++ -o "$work/app_pkgconfig" "$source/examples/cpp/app.cpp" $(pkg-config --cflags --libs restitution)
# The shared library beside the static one: SONAME librestitution.so.X.Y of the version, restitution's API its
# only exports (no CVODE, N_Vector, SUNDIALS or fmt symbol), and a consumer linked with -lrestitution loads it.
soname=$(readelf -d "$libdir/librestitution.so" | sed -n 's/.*Library soname: \[\(.*\)\]/\1/p')
expected_soname="librestitution.so.$(cut -d. -f1,2 <<<"$version")"
[ "$soname" = "$expected_soname" ] || { echo "SONAME of $libdir/librestitution.so: '$soname', expected $expected_soname"; exit 1; }
test -f "$libdir/$soname" || { echo "$libdir/$soname (the SONAME's link) is not installed"; exit 1; }
foreign=$(nm -D --defined-only -C "$libdir/librestitution.so" | grep -vE ' (typeinfo( name)? for |vtable for |VTT for |guard variable for )?restitution::' || true)
[ -z "$foreign" ] || { echo "lib/librestitution.so exports more than restitution's API:"; head <<<"$foreign"; exit 1; }
c++ -std=c++17 -o "$work/app_shared" "$source/examples/cpp/app.cpp" -I"$prefix/include" -L"$libdir" \
  -lrestitution -Wl,-rpath,"$libdir"
grep -qF "[$soname]" <<<"$(readelf -d "$work/app_shared")" || { echo "app_shared does not load $soname:"; readelf -d "$work/app_shared" | grep NEEDED; exit 1; }
man_page="$prefix/share/man/man1/restitution.1"
[ -f "$man_page" ] || man_page+=.gz  # the Debian package's page is compressed
test -f "$man_page" || { echo "missing share/man/man1/restitution.1"; exit 1; }
rendered=$(LC_ALL=C MANWIDTH=80 man -l "$man_page" 2>&1 | tr -s " ")  # ASCII hyphens, unjustified
for expected in "restitution - coefficient of restitution" "restitution eps" "--tolerance" "restitution $version" "share/doc/restitution"; do
  grep -qF -- "$expected" <<<"$rendered" || { echo "man -l $man_page lacks '$expected':"; head -20 <<<"$rendered"; exit 1; }
done

for doc in cli.md library.md release.md README.md LICENSE CHANGELOG.md; do  # the docs SEE ALSO points to
  test -f "$prefix/share/doc/restitution/$doc" || { echo "missing share/doc/restitution/$doc"; exit 1; }
done

# The installed program needs no checkout: a bare `run` (outside any checkout) takes the installed default scene
# and plots with the installed scripts.
run_log=$(cd "$work" && "$prefix/bin/restitution" run --quick --out "$work/run" 2>&1) ||
  { echo "installed restitution run failed: $run_log"; exit 1; }
grep -qF "$prefix/share/restitution/scenes/default.toml" <<<"$run_log" ||
  { echo "installed restitution run did not take the installed default scene: $run_log"; exit 1; }
ls "$work"/run/*.png >/dev/null 2>&1 || { echo "installed restitution run made no plot: $run_log"; exit 1; }

cmake -S "$source/examples/cpp" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_EXTENSIONS=OFF \
  -DCMAKE_CXX_FLAGS="-Wall -Wextra -Wpedantic -Werror" >/dev/null
cmake --build "$work/build" >/dev/null

# A library carrying its optimized CVODE (cmake/sundials.cmake) needs no SUNDIALS in the consumer's link.
# Here-strings, not `| grep -q`: grep -q leaves at the first match, and under pipefail the writer's SIGPIPE
# would count as a failure.
optimized=$(grep -c "SUNDIALS .*(optimized" <<<"$("$build/restitution" --version)" || true)
if [ "$optimized" -gt 0 ] && grep -q sundials <<<"$(ldd "$work/build/app")"; then
  echo "the consumer links a SUNDIALS library although librestitution.a carries its own CVODE:"
  ldd "$work/build/app" | grep sundials
  exit 1
fi

# The CVODE the library carries is private to it: the installed archive exports no CVODE, N_Vector or SUNDIALS
# symbol, and a consumer that calls the system's CVODE itself (tests/install/sundials_beside.cpp) binds its calls
# to libsundials_cvode.so while restitution's solves keep the library's own copy (local symbols in the program).
if [ "$optimized" -gt 0 ]; then
  exported=$(nm -g --defined-only "$libdir/librestitution.a" | grep -E ' [A-Z] (CVode|N_V|SUN)' || true)
  [ -z "$exported" ] || { echo "the installed librestitution.a exports SUNDIALS symbols:"; head <<<"$exported"; exit 1; }
  # shellcheck disable=SC2046  # pkg-config's output is a list of words
  c++ -o "$work/sundials_beside" "$source/tests/install/sundials_beside.cpp" $(pkg-config --cflags --libs restitution) \
    -lsundials_cvode -lsundials_nvecserial -ldl
  beside=$("$work/sundials_beside")
  grep -qE '^cvode_library .*/libsundials_cvode\.so' <<<"$beside" ||
    { echo "the consumer's CVodeCreate does not come from the system's libsundials_cvode:"; echo "$beside"; exit 1; }
  awk '$1 == "own_solve" && $2 + 0 < 1e-6 { ok = 1 } END { exit !ok }' <<<"$beside" ||
    { echo "the consumer's own CVODE solve is wrong:"; echo "$beside"; exit 1; }
  local_cvode=$(nm "$work/sundials_beside" | grep -cE ' t CVode' || true)
  [ "$local_cvode" -gt 0 ] ||
    { echo "restitution's CVODE is not inside the program as local symbols"; exit 1; }
  [ "$(awk '$1 == "eps_delayed_recovery" { print $2 }' <<<"$beside")" = \
    "$("$work/app_pkgconfig" 1 | awk '$1 == "delayed-recovery" { print $2 }')" ] ||
    { echo "restitution beside the system's SUNDIALS gives another eps:"; echo "$beside"; exit 1; }
fi

# Default tolerance of SolveOptions: 1e-10. ζ spans the weakly and the strongly damped regime.
status=0
for app in "$work/build/app" "$work/app_pkgconfig" "$work/app_shared"; do
for zeta in 0.001 1 100 10000; do
  output=$("$app" "$zeta")
  awk -F, -v zeta="$zeta" -v out="$output" -v tol=1e-10 '
    BEGIN { n = split(out, lines, "\n"); for (i = 1; i <= n; ++i) { split(lines[i], kv, " "); got[kv[1]] = kv[2] } }
    /^#/ || $1 == "zeta" { next }
    $1 + 0 == zeta + 0 {
      found = 1
      bad += check("naive", got["naive"], $4, $5)
      bad += check("delayed-recovery", got["delayed-recovery"], $8, $9)
    }
    function check(end, eps, ref, ref_one_minus, m) {
      if (ref == "") return 0  # the table has no naive end beyond zeta ~ 1e3
      m = ref < ref_one_minus ? ref : ref_one_minus
      if (eps == "" || (eps - ref > tol * m) || (ref - eps > tol * m)) {
        printf "zeta %s %s: app %s, reference %s, allowed %.3g\n", zeta, end, eps, ref, tol * m
        return 1
      }
      return 0
    }
    END { if (!found) { print "zeta " zeta " not in the reference table"; exit 1 } exit bad > 0 }
  ' "$source/data/reference_solutions.csv" || { echo "($app)"; status=1; }
done
done
[ $status -eq 0 ] && echo "installed package: headers, CMake package, pkg-config, program, man page and example app check out"
exit $status
