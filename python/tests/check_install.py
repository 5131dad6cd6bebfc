# SPDX-License-Identifier: BSD-3-Clause
"""`cmake --install` puts the package where Debian's python3 looks: installs into a staging DESTDIR with
prefix /usr/local, checks that the install directory is on the interpreter's own sys.path for that prefix,
and imports the staged package. Usage: check_install.py CMAKE BUILD_DIR INSTALL_DIR (ctest python_install).
"""

import os
import pathlib
import subprocess
import sys
import tempfile

PREFIX = "/usr/local"


def main():
    cmake, build, install_dir = sys.argv[1:4]
    site = pathlib.Path(PREFIX) / install_dir
    if str(site) not in sys.path:
        sys.exit(f"{site} is not on {sys.executable}'s sys.path: {sys.path}")
    with tempfile.TemporaryDirectory() as stage:
        environment = dict(os.environ, DESTDIR=stage)
        subprocess.run([cmake, "--install", build, "--prefix", PREFIX], check=True, env=environment,
                       stdout=subprocess.DEVNULL)
        staged = pathlib.Path(stage) / site.relative_to("/")
        for name in ("__init__.py", "__init__.pyi", "series.py", "py.typed"):
            if not (staged / "restitution" / name).is_file():
                sys.exit(f"not installed: {staged / 'restitution' / name}")
        code = "import restitution; assert 0 < restitution.eps(1.0) < 1; print(restitution.__file__)"
        environment = dict(os.environ, PYTHONPATH=str(staged))
        out = subprocess.run([sys.executable, "-c", code], check=True, env=environment, cwd=stage,
                             capture_output=True, text=True).stdout
        if not out.startswith(str(staged)):
            sys.exit(f"imported {out.strip()}, not the installed package")
        print(f"installed to {site}, importable: {out.strip()}")


if __name__ == "__main__":
    main()
