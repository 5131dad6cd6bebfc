# SPDX-License-Identifier: BSD-3-Clause
"""Each engine in its own room (docs/design.md, "Engines"), checked on the includes, folder by folder.

* src/engine/ is the interface (engine.hpp): it includes no engine.
* The engines are the folders src/solver/engine_registry.cpp includes (cvode, taylor), each with the
  folders it owns (sundials/ belongs to cvode). An engine includes the interface and nothing of another engine.
* The __float128 reference (src/reference/) instantiates the Taylor recurrences itself and must not reach
  CVODE's files, so that it stays an independent check of them.
* solver/ (the facade above the engines) includes the interface and the registry's header only, never an
  engine's own files; the registry's header includes no engine either (only its .cpp, the table, does).
* law/ (below the engines) includes no engine, no interface and no solver.

A folder or group that matches no file fails, so that a rename cannot make the check pass vacuously.
Usage: engine_isolation.py SOURCE_DIR
"""
import pathlib
import re
import sys

source = pathlib.Path(sys.argv[1]) / "src"
owned = {"sundials": "cvode"}  # helper folders and the engine they belong to
table = (source / "solver" / "engine_registry.cpp").read_text(encoding="utf-8")
engines = sorted(set(re.findall(r'^#include "([^/"]+)/', table, re.M)) - {"solver", "engine", "law", "restitution"})


def group_of(path):
    """The group of a path relative to src/ (folder/file)."""
    folder = path.split("/")[0]
    if path == "solver/engine_registry.hpp":
        return "registry header"
    if path == "solver/engine_registry.cpp":
        return "registry table"
    if folder in engines:
        return f"engine {folder}"
    if folder in owned:
        return f"engine {owned[folder]}"
    return {"engine": "interface", "solver": "solver", "law": "law", "reference": "float128 reference"}.get(folder)


engine_groups = {f"engine {e}" for e in engines}
allowed = {
    "interface": {"law"},
    "law": set(),
    "registry header": {"interface"},
    "registry table": {"interface", "registry header", "law"} | engine_groups,
    "solver": {"interface", "registry header", "law"},
    "float128 reference": {"engine taylor"},
}
for group in engine_groups:
    allowed[group] = {"interface", "law"}

files = {}
for path in source.rglob("*"):
    if path.suffix in (".cpp", ".hpp", ".h"):
        relative = path.relative_to(source).as_posix()
        group = group_of(relative)
        if group is not None:
            files.setdefault(group, []).append(relative)

failures = [f"group {group} matches no file under src/" for group in sorted(allowed) if group not in files]
if "engine cvode" not in engine_groups or "engine taylor" not in engine_groups:
    failures.append(f"the registry's table includes the engines {engines}: expected cvode and taylor among them")
for group, paths in sorted(files.items()):
    for path in sorted(paths):
        for included in re.findall(r'^#include "([^"]+)"', (source / path).read_text(encoding="utf-8"), re.M):
            target = group_of(included)
            if target is not None and target != group and target not in allowed[group]:
                failures.append(f"{path} ({group}) includes {included} ({target})")
for group, paths in sorted(files.items()):
    print(f"{group}: {len(paths)} files ({', '.join(sorted({p.split('/')[0] for p in paths}))})")
for failure in failures:
    print(failure)
sys.exit(1 if failures else 0)
