# SPDX-License-Identifier: BSD-3-Clause
"""The include graph between the modules under src/ has no cycle, the installable library reaches no study, and
the Python module (python/src) includes only the installed API, its own headers and a module's public interface,
never a header under a module folder (no study's private header, no library internals). The command line
(src/cli) only renders: it includes no module of the solving layers, no numerical library and no private header
of a study that has a public interface.

A module is a folder under src/; `#include "M/..."` in a file of module A is an edge A -> M. A public header
include/restitution/H.hpp belongs to the module that implements it: the folder named H, else the folder of
H.cpp, else the one folder whose sources include it first (restitution.hpp, the umbrella: version/, which says what built the code: restitution's version and commit, the SUNDIALS build);
a header no folder implements (errors.hpp: inline only) is no module. So `#include "restitution/H.hpp"` in module
A is an edge A -> H's module, and a public header's own includes are edges of its module (the umbrella's are
not: it includes everything for users and implements nothing of it). Each edge is printed with the number of
include lines behind it. A module may have a public interface, src/M/include/P/, that its CMake target exports:
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
public = source.parent / "include" / "restitution"
umbrella = "restitution.hpp"
first_includes = {}  # public header -> folders whose sources include it first
for path in source.rglob("*.cpp"):
    included = re.findall(r'^#include "([^"]+)"', path.read_text(encoding="utf-8"), re.M)
    if included and included[0].startswith("restitution/"):
        first_includes.setdefault(included[0], set()).add(path.relative_to(source).parts[0])


def implementer(header):
    """The module implementing include/restitution/<header>, or None for an inline-only header."""
    stem = header.removesuffix(".hpp")
    if stem in modules:
        return stem
    folders = {p.relative_to(source).parts[0] for p in source.glob(f"*/{stem}.cpp")}
    if len(folders) == 1:
        return folders.pop()
    if not re.search(r"\)\s*(const\s*)?(noexcept\s*)?;", (public / header).read_text(encoding="utf-8")):
        return None  # declares no function it does not define: nothing to implement
    folders = first_includes.get(f"restitution/{header}", set())
    if len(folders) == 1:
        return folders.pop()
    if folders:
        failures.append(f"public header {header}: implemented by which of {sorted(folders)}?")
    return None


failures = []
owner = {h.name: implementer(h.name) for h in sorted(public.glob("*.hpp"))}
edges = {m: {} for m in modules}


def add_edge(module, target):
    if target in modules and target != module:
        edges[module][target] = edges[module].get(target, 0) + 1


def include_targets(text):
    """The modules a file's includes reach: folders, interfaces and the owners of public headers."""
    for header in re.findall(r'^#include "([^"]+)"', text, re.M):
        prefix = header.split("/")[0] if "/" in header else None
        if prefix == "restitution":
            yield owner.get(header.split("/", 1)[1])
        elif prefix is not None:
            yield interfaces.get(prefix, prefix)


for module in modules:
    for path in (source / module).rglob("*"):
        if path.suffix in (".cpp", ".hpp"):
            for target in include_targets(path.read_text(encoding="utf-8")):
                add_edge(module, target)
for header, module in owner.items():
    if module is not None and header != umbrella:
        for target in include_targets((public / header).read_text(encoding="utf-8")):
            add_edge(module, target)

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
    for target in sorted(set(edges[module]) & (study | {"cli"})):
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
                if owner.get(header.split("/", 1)[1]) is not None:
                    python_edges.add(owner[header.split("/", 1)[1]])
                continue  # the installed API
            if prefix in interfaces and (source / interfaces[prefix] / "include" / header).is_file():
                python_edges.add(interfaces[prefix])
                continue
            failures.append(f"python/{path.relative_to(python_source.parent)} includes {header}: neither the "
                            "installed API, its own header nor a module's public interface (src/M/include/)")
# The front end renders (docs/design.md, "Who computes, who renders"): src/cli includes no header of the solving
# layers (their folders; it calls the installed API, restitution/*.hpp), no numerical library (Boost, Eigen,
# SUNDIALS), and of a study with a public interface (src/M/include/P/) only that interface, never a header
# beside the study's sources. No file is excepted.
solver_layers = {"law", "engine", "cvode", "sundials", "taylor", "solver"}
numerical_libraries = ("boost/", "Eigen/", "unsupported/Eigen/", "cvode/", "sundials/", "nvector/", "sunmatrix/",
                       "sunlinsol/")
studies_with_interface = {m for m in interfaces.values() if m in study}
for path in sorted((source / "cli").rglob("*")):
    if path.suffix not in (".cpp", ".hpp"):
        continue
    text = path.read_text(encoding="utf-8")
    where = path.relative_to(source)
    for header in re.findall(r'^#include "([^"]+)"', text, re.M):
        prefix = header.split("/")[0] if "/" in header else None
        if prefix in solver_layers:
            failures.append(f"{where} includes {header}: the front end calls the solver through the installed "
                            "API (restitution/*.hpp), never its modules")
        elif prefix in studies_with_interface:
            interface = next(p for p, m in interfaces.items() if m == prefix)
            failures.append(f"{where} includes {header}, a private header of the study {prefix}: only its "
                            f"interface {interface}/ (what it computes belongs in the study)")
    for header in re.findall(r'^#include [<"]([^>"]+)[>"]', text, re.M):
        if header.startswith(numerical_libraries):
            failures.append(f"{where} includes {header}: a numerical library, which only the library and the "
                            "studies use")
for module in sorted(modules):
    print(f"{module} -> {', '.join(f'{t} ({n})' for t, n in sorted(edges[module].items())) or '(nothing)'}")
print(f"python -> {' '.join(sorted(python_edges)) or '(nothing)'}")
print("public headers: " + ", ".join(f"{h} ({m or 'inline only'})" for h, m in owner.items()))
# docs/design.md prints the same graph ("Include graph between modules"): an arrow per module, continuation lines
# indented, several edgeless modules on one line; it must be this graph, not an older one.
design = (pathlib.Path(sys.argv[1]) / "docs" / "design.md").read_text(encoding="utf-8")
documented = {}
block = design.split("## Include graph between modules", 1)[1].split("(`python3 tests/module_graph.py .`", 1)[0]
for line in block.splitlines():
    if "→" in line:
        names, targets = (part.strip() for part in line.split("→", 1))
        current = [name.strip() for name in names.split(",")]
        for name in current:
            documented[name] = targets
    elif line.startswith("    ") and line.strip() and documented:
        for name in current:
            documented[name] += " " + line.strip()
for module in sorted(modules):
    shown = ", ".join(f"{t} ({n})" for t, n in sorted(edges[module].items())) or "(nothing)"
    text = documented.get(module, "missing").split("   (", 1)[0].strip()
    if text != shown:
        failures.append(f"docs/design.md shows {module} -> {text}; the sources give {shown}")
if documented.get("python", "").split() != sorted(python_edges):
    failures.append(f"docs/design.md shows python -> {documented.get('python')}; the sources give "
                    f"{' '.join(sorted(python_edges))}")
for failure in failures:
    print(failure)
sys.exit(1 if failures else 0)
