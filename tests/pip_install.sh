#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The Python package as a user installs it: builds a wheel from this checkout with Debian's setuptools
# (`pip wheel --no-build-isolation --no-deps .`, setup.py driving CMake), installs it into a fresh venv that sees
# Debian's numpy (--system-site-packages), and runs the pytest suite (python/tests) against the INSTALLED
# package from a folder outside the checkout, with no PYTHONPATH (conftest.py checks where restitution comes
# from), and executes examples/notebooks/restitution_tour.ipynb with Debian's nbconvert in a kernel of that venv. Also checks restitution.__version__ against the file VERSION, and that `pip install --no-build-isolation .`
# straight from the checkout (the README's command) installs an importable package into another fresh venv.
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

version=$(tr -d '[:space:]' <"$source/VERSION")
cd "$work"
"$work/venv/bin/python" - "$work/venv" "$version" <<'PY'
import pathlib, sys
import restitution
venv, version = pathlib.Path(sys.argv[1]).resolve(), sys.argv[2]
where = pathlib.Path(restitution.__file__).resolve()
assert where.is_relative_to(venv), f"imported {where}, not the venv's copy"
assert restitution.__version__ == version, f"__version__ {restitution.__version__} != VERSION {version}"
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
echo "pip_install: done in $((SECONDS - start)) s"
