# SPDX-License-Identifier: BSD-3-Clause
"""The include graph between the modules under src/ has no cycle, the installable library reaches no study, and
the Python module (python/src) includes only the installed API, its own headers and the study headers that
python/CMakeLists.txt declares in restitution_python_study_headers (no study's private header, no library internals).

A module is a folder under src/; `#include "M/..."` in a file of module A is an edge A -> M (restitution/ is the
public API and no module). The study folders are read from src/CMakeLists.txt (restitution_study_modules).
Usage: module_graph.py SOURCE_DIR
"""
import pathlib
import re
import sys

source = pathlib.Path(sys.argv[1]) / "src"
study = set(re.search(r"set\(restitution_study_modules ([^)]*)\)",
                      (source / "CMakeLists.txt").read_text()).group(1).split())
modules = {d.name for d in source.iterdir() if d.is_dir()}
edges = {m: set() for m in modules}
for module in modules:
    for path in (source / module).rglob("*"):
        if path.suffix in (".cpp", ".hpp"):
            for target in re.findall(r'^#include "([^/"]+)/', path.read_text(encoding="utf-8"), re.M):
                if target in modules and target != module:
                    edges[module].add(target)

failures = []
state = {}  # 1: on the current path, 2: done


def visit(module, path):
    state[module] = 1
    for target in sorted(edges[module]):
        if state.get(target) == 1:
            failures.append("include cycle: " + " -> ".join(path[path.index(target):] + [target]))
        elif target not in state:
            visit(target, path + [target])
    state[module] = 2


for module in sorted(modules):
    if module not in state:
        visit(module, [module])
library = modules - study - {"cli"}
for module in sorted(library):
    for target in sorted(edges[module] & (study | {"cli"})):
        failures.append(f"the installable library's module {module} includes {target}")
python_allowed = set(re.search(r"set\(restitution_python_study_headers ([^)]*)\)",
                               (source.parent / "python" / "CMakeLists.txt").read_text()).group(1).split())
python_edges = set()
for path in sorted((source.parent / "python" / "src").rglob("*")):
    if path.suffix in (".cpp", ".hpp"):
        for header in re.findall(r'^#include "([^"]+)"', path.read_text(encoding="utf-8"), re.M):
            target = header.split("/")[0] if "/" in header else None
            if target in modules:
                python_edges.add(target)
                if header not in python_allowed:
                    failures.append(f"python/{path.relative_to(source.parent / 'python')} includes {header}, "
                                    "not the installed API nor a declared study interface")
for module in sorted(modules):
    print(f"{module} -> {' '.join(sorted(edges[module])) or '(public headers only)'}")
print(f"python -> {' '.join(sorted(python_edges)) or '(public headers only)'}")
for failure in failures:
    print(failure)
sys.exit(1 if failures else 0)
