# SPDX-License-Identifier: BSD-3-Clause
"""The include graph between the modules under src/ has no cycle, the installable library reaches no study, and
the Python module (python/src) includes only the installed API, its own headers and a module's public interface,
never a header under a module folder (no study's private header, no library internals).

A module is a folder under src/; `#include "M/..."` in a file of module A is an edge A -> M (restitution/ is the
public API and no module). A module may have a public interface, src/M/include/P/, that its CMake target exports:
`#include "P/..."` is an edge to M as well (src/series_study/include/restitution_series_study/). The study
folders are read from src/CMakeLists.txt (restitution_study_modules).
Usage: module_graph.py SOURCE_DIR
"""
import pathlib
import re
import sys

source = pathlib.Path(sys.argv[1]) / "src"
study = set(re.search(r"set\(restitution_study_modules ([^)]*)\)",
                      (source / "CMakeLists.txt").read_text()).group(1).split())
modules = {d.name for d in source.iterdir() if d.is_dir()}
# The interface prefixes P of src/M/include/P/ and their module M.
interfaces = {p.name: p.parent.parent.name for p in source.glob("*/include/*") if p.is_dir()}
edges = {m: set() for m in modules}
for module in modules:
    for path in (source / module).rglob("*"):
        if path.suffix in (".cpp", ".hpp"):
            for prefix in re.findall(r'^#include "([^/"]+)/', path.read_text(encoding="utf-8"), re.M):
                target = interfaces.get(prefix, prefix)
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
python_edges = set()
python_source = source.parent / "python" / "src"
for path in sorted(python_source.rglob("*")):
    if path.suffix in (".cpp", ".hpp"):
        for header in re.findall(r'^#include "([^"]+)"', path.read_text(encoding="utf-8"), re.M):
            prefix = header.split("/")[0] if "/" in header else None
            if prefix is None and (path.parent / header).is_file():
                continue  # the module's own header
            if prefix == "restitution" and (source.parent / "include" / header).is_file():
                continue  # the installed API
            if prefix in interfaces and (source / interfaces[prefix] / "include" / header).is_file():
                python_edges.add(interfaces[prefix])
                continue
            failures.append(f"python/{path.relative_to(python_source.parent)} includes {header}: neither the "
                            "installed API, its own header nor a module's public interface (src/M/include/)")
for module in sorted(modules):
    print(f"{module} -> {' '.join(sorted(edges[module])) or '(public headers only)'}")
print(f"python -> {' '.join(m + ' (its interface)' for m in sorted(python_edges)) or '(public headers only)'}")
for failure in failures:
    print(failure)
sys.exit(1 if failures else 0)
