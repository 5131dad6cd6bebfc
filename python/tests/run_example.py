# SPDX-License-Identifier: BSD-3-Clause
"""Runs an example script into a temporary folder and checks that it wrote a non-trivial PNG.

Usage: run_example.py SCRIPT (ctest: python_example_eps_vs_velocity). Not collected by pytest.
"""

import pathlib
import subprocess
import sys
import tempfile

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def main():
    script = pathlib.Path(sys.argv[1])
    with tempfile.TemporaryDirectory() as folder:
        png = pathlib.Path(folder) / "plot.png"
        subprocess.run([sys.executable, str(script), str(png)], check=True, timeout=100)
        data = png.read_bytes()
        if not data.startswith(PNG_SIGNATURE) or len(data) < 10_000:
            sys.exit(f"{script.name} wrote no plot worth the name: {len(data)} bytes")
        print(f"{script.name}: {len(data)} bytes of PNG")


if __name__ == "__main__":
    main()
