#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Executes a copy of a notebook in a temporary folder with Debian's jupyter-nbconvert, in a kernel that runs the given
interpreter, and checks that the package it imported is the one under test. The copy has nothing beside it: a
notebook that reads a file relative to where it is shipped fails here, as it would for a user who copied it.

Usage: run_notebook.py NOTEBOOK PYTHON PACKAGE_PREFIX
Debian's kernel runs /usr/bin/python3; a kernelspec for PYTHON (a venv's python, say) is installed into a
temporary folder on JUPYTER_PATH, as docs/python.md tells a user to do. The notebook's last cell prints
"restitution <version> from <folder>"; that folder must lie under PACKAGE_PREFIX (the venv, or the build tree).
"""

import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time

KERNEL = "restitution-under-test"


def main(notebook, python, prefix):
    notebook = pathlib.Path(notebook).resolve()
    with tempfile.TemporaryDirectory() as work:
        work = pathlib.Path(work)
        kernel = subprocess.run([python, "-m", "ipykernel", "install", "--prefix", str(work), "--name", KERNEL],
                                capture_output=True, text=True)
        if kernel.returncode != 0:
            sys.exit(f"run_notebook: {python} cannot install a kernel (Debian: python3-ipykernel):\n{kernel.stderr}")
        env = dict(os.environ, JUPYTER_PATH=str(work / "share" / "jupyter"), PYDEVD_DISABLE_FILE_VALIDATION="1")
        env.pop("MPLBACKEND", None)  # the kernel's inline backend draws the figures into the notebook
        started = time.monotonic()
        # nbconvert runs a notebook in its own folder: the copy's, alone in a folder of its own.
        alone = work / "copy"
        alone.mkdir()
        copy = alone / notebook.name
        shutil.copyfile(notebook, copy)
        try:
            done = subprocess.run(["jupyter-nbconvert", "--to", "notebook", "--execute",
                                   f"--ExecutePreprocessor.kernel_name={KERNEL}", "--ExecutePreprocessor.timeout=600",
                                   "--output-dir", str(work), str(copy)], env=env, capture_output=True, text=True)
        except FileNotFoundError:
            sys.exit("run_notebook: jupyter-nbconvert is missing (Debian: jupyter-nbconvert python3-ipykernel; "
                     "scripts/setup installs them)")
        if done.returncode != 0:
            sys.exit(f"run_notebook: executing {notebook.name} failed:\n{done.stderr[-4000:]}")
        cells = json.loads((work / notebook.name).read_text())["cells"]
    text = "".join("".join(output.get("text", "")) for cell in cells if cell["cell_type"] == "code"
                   for output in cell["outputs"])
    where = [line.split(" from ", 1)[1] for line in text.splitlines() if line.startswith("restitution ") and " from " in line]
    if not where or not pathlib.Path(where[-1]).resolve().is_relative_to(pathlib.Path(prefix).resolve()):
        sys.exit(f"run_notebook: the notebook imported restitution from {where or 'nowhere it said'}, not under {prefix}")
    print(f"run_notebook: {notebook.name} ran in {time.monotonic() - started:.0f} s with {python}, restitution from {where[-1]}")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
