#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The Python package as a user installs it: builds a wheel from this checkout with Debian's setuptools
# (`pip wheel --no-build-isolation --no-deps .`, setup.py driving CMake), installs it into a fresh venv that sees
# Debian's numpy (--system-site-packages), and runs the pytest suite (python/tests) against the INSTALLED
# package from a folder outside the checkout, with no PYTHONPATH (conftest.py checks where restitution comes
# from), and executes examples/notebooks/restitution_tour.ipynb with Debian's nbconvert in a kernel of that venv.
# Also checks restitution.__version__ against cmake/version.cmake's, that `pip install --no-build-isolation .`
# straight from the checkout (the README's command) installs an importable package into another fresh venv, and
# that the sdist (`python3 -m build --sdist --no-isolation`) alone builds a wheel whose eps(1) is right and which
# links the optimized CVODE the sdist carries (third_party/sundials), without a word at import.
# Usage: tests/pip_install.sh [SOURCE_DIR]   (CMAKE_ARGS, RESTITUTION_CMAKE_BUILD_DIR etc. pass through to setup.py)
set -euo pipefail
source=$(cd "${1:-$(dirname "$0")/..}" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
unset PYTHONPATH

start=$SECONDS
(cd "$source" && /usr/bin/python3 -m pip wheel --no-build-isolation --no-deps --wheel-dir "$work/dist" . >"$work/wheel.log" 2>&1) ||
  { tail -40 "$work/wheel.log"; echo "pip_install: building the wheel failed"; exit 1; }
wheel=$(ls "$work"/dist/restitution-*.whl)
echo "pip_install: built $(basename "$wheel") in $((SECONDS - start)) s"

/usr/bin/python3 -m venv --system-site-packages "$work/venv"
"$work/venv/bin/pip" install --no-index --no-deps --quiet "$wheel"

version=$(cmake -DROOT="$source" -P "$source/cmake/version.cmake" | sed -n 1p)  # docs/release.md
cd "$work"
"$work/venv/bin/python" - "$work/venv" "$version" <<'PY'
import pathlib, sys
import restitution
venv, version = pathlib.Path(sys.argv[1]).resolve(), sys.argv[2]
where = pathlib.Path(restitution.__file__).resolve()
assert where.is_relative_to(venv), f"imported {where}, not the venv's copy"
assert restitution.__version__ == version, f"__version__ {restitution.__version__} != cmake/version.cmake's {version}"
eps = restitution.eps(1.0)
assert 0 < eps < 1, eps
print(f"pip_install: restitution {restitution.__version__} from {where.parent}, eps(1) = {eps}")
PY
RESTITUTION_INSTALLED_UNDER="$work/venv" RESTITUTION_SOURCE_DIR="$source" \
  "$work/venv/bin/python" -m pytest -q -p no:cacheprovider "$source/python/tests"
# The notebook with Debian's nbconvert, in a kernel that runs the venv's python (Debian's kernel runs
# /usr/bin/python3, which does not see the venv): it must import the wheel installed there.
"$work/venv/bin/python" "$source/python/tests/run_notebook.py" "$source/examples/notebooks/restitution_tour.ipynb" \
  "$work/venv/bin/python" "$work/venv"

# The README's command: pip builds from the checkout itself (reusing setup.py's CMake build folder).
/usr/bin/python3 -m venv --system-site-packages "$work/venv2"
(cd "$source" && "$work/venv2/bin/pip" install --no-build-isolation --no-deps --quiet . >"$work/install.log" 2>&1) ||
  { tail -40 "$work/install.log"; echo "pip_install: pip install . failed"; exit 1; }
"$work/venv2/bin/python" -c "import restitution, sys; assert restitution.__file__.startswith('$work/venv2'), restitution.__file__; print('pip_install: pip install . gives', restitution.__version__, restitution.eps(1.0))"

# The sdist alone builds: it is unpacked into build/sdist-check (a fixed folder, so that ccache finds the objects of
# the last run; no git checkout of its own, so the version comes from its SDIST_VERSION), a wheel is built from it
# with CMake's own folder (not RESTITUTION_CMAKE_BUILD_DIR) and installed into a third fresh venv.
(cd "$source" && /usr/bin/python3 -m build --sdist --no-isolation --outdir "$work/sdist" . >"$work/sdist.log" 2>&1) ||
  { tail -40 "$work/sdist.log"; echo "pip_install: python3 -m build --sdist failed"; exit 1; }
sdist=$(ls "$work"/sdist/restitution-*.tar.gz)
listing=$(tar tzf "$sdist")
for needed in VERSION SDIST_VERSION CMakeLists.txt cmake/version.cmake src/CMakeLists.txt include/restitution/restitution.hpp \
  python/CMakeLists.txt data/reference_solutions.csv scripts/plots docs/cli.md scripts/sundials-build \
  third_party/sundials/README.md third_party/sundials/DEBIAN_VERSION third_party/sundials/source/LICENSE \
  third_party/sundials/source/src/cvode/cvode.c; do
  grep -q "^restitution-[^/]*/$needed" <<<"$listing" || { echo "pip_install: the sdist lacks $needed"; exit 1; }
done
unpacked="$source/build/sdist-check"
rm -rf "$unpacked"
mkdir -p "$unpacked"
tar xzf "$sdist" -C "$unpacked" --strip-components=1
echo "pip_install: the sdist: $(du -k "$sdist" | cut -f1) KiB, $(grep -c . <<<"$listing") entries, of them" \
  "$(grep -c '^restitution-[^/]*/third_party/sundials/.*[^/]$' <<<"$listing") files in third_party/sundials"
# No build/sundials: the sdist's own CVODE source is built (cmake/sundials.cmake), as for a pip user. ccache
# (CMake reads the launchers from the environment, SUNDIALS' C too) keeps this fast in CI; CCACHE_DISABLE=1
# gives the cold time.
if command -v ccache >/dev/null; then
  export CMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER:-ccache}
  export CMAKE_C_COMPILER_LAUNCHER=${CMAKE_C_COMPILER_LAUNCHER:-ccache}
fi
sdist_start=$SECONDS
(cd "$unpacked" && env -u RESTITUTION_CMAKE_BUILD_DIR /usr/bin/python3 -m pip wheel --no-build-isolation --no-deps \
  --wheel-dir "$work/sdist-dist" . >"$work/sdist-wheel.log" 2>&1) ||
  { tail -40 "$work/sdist-wheel.log"; echo "pip_install: building a wheel from the sdist failed"; exit 1; }
echo "pip_install: built a wheel from the sdist in $((SECONDS - sdist_start)) s"
/usr/bin/python3 -m venv --system-site-packages "$work/venv3"
"$work/venv3/bin/pip" install --no-index --no-deps --quiet "$work"/sdist-dist/restitution-*.whl
import_output=$(cd "$work" && "$work/venv3/bin/python" -W error -c "import restitution" 2>&1)
[ -z "$import_output" ] || { echo "$import_output"; echo "pip_install: importing the sdist's wheel printed the above"; exit 1; }
"$work/venv3/bin/python" - "$version" "$source/data/reference_solutions.csv" <<'PY'
import csv, sys
import restitution
version, table = sys.argv[1], sys.argv[2]
assert restitution.__version__ == version, f"the sdist's wheel says {restitution.__version__}, the checkout {version}"
sundials = restitution.build_info()["sundials"]
assert sundials["optimized"] and "bundled in the sdist" in sundials["description"], sundials
print(f"pip_install: the sdist's wheel runs SUNDIALS {sundials['description']}")
rows = [r for r in csv.reader(line for line in open(table) if not line.startswith("#"))]
header, rows = rows[0], rows[1:]
row = next(r for r in rows if float(r[0]) == 1.0)
ref = float(row[header.index("delayed_recovery_eps")])
ref_one_minus = float(row[header.index("delayed_recovery_one_minus_eps")])
eps = restitution.eps(1.0)
assert abs(eps - ref) <= 1e-10 * min(ref, ref_one_minus), f"eps(1) = {eps}, reference {ref}"
print(f"pip_install: the sdist's wheel {restitution.__version__}: eps(1) = {eps} (reference {ref})")
PY
rm -rf "$unpacked"
echo "pip_install: done in $((SECONDS - start)) s"
