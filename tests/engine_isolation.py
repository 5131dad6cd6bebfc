"""No engine includes another engine's headers (docs/design.md, "Engines").

The engines behind src/engine/engine.hpp are groups of files: CVODE is its engine, its phases, its tolerance
policy, its integrator and the SUNDIALS handles; Taylor is src/taylor. The __float128 reference (src/reference)
instantiates the Taylor recurrences itself and must not reach CVODE's files either, so that it stays an
independent check of them. A file of one group that includes a file of another group fails, and so does
a group that matches no file (a rename must not make the check pass vacuously).
Usage: engine_isolation.py SOURCE_DIR
"""
import pathlib
import re
import sys

source = pathlib.Path(sys.argv[1]) / "src"
groups = {
    "interface": ["engine/*"],
    "cvode": ["core/cvode_*", "core/tolerance_policy.*", "sundials/*"],
    "taylor": ["taylor/*"],
    "float128 reference": ["reference/*"],
}
# Which groups' files a group may include besides its own: the interface includes no engine, every engine
# the interface, the reference the Taylor recurrences (the same engine in another number type).
allowed = {
    "interface": set(),
    "cvode": {"interface"},
    "taylor": {"interface"},
    "float128 reference": {"taylor"},
}
members = {name: {p.relative_to(source).as_posix() for pattern in patterns for p in source.glob(pattern)
                  if p.suffix in (".cpp", ".hpp", ".h")}
           for name, patterns in groups.items()}
group_of = {path: name for name, paths in members.items() for path in paths}

failures = [f"group {name} matches no file under src/" for name, paths in members.items() if not paths]
for name, paths in sorted(members.items()):
    for path in sorted(paths):
        for included in re.findall(r'^#include "([^"]+)"', (source / path).read_text(encoding="utf-8"), re.M):
            target = group_of.get(included)
            if target is not None and target != name and target not in allowed[name]:
                failures.append(f"{path} ({name}) includes {included} ({target})")
for name, paths in sorted(members.items()):
    print(f"{name}: {len(paths)} files")
for failure in failures:
    print(failure)
sys.exit(1 if failures else 0)
