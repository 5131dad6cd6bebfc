#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""docs/cli.md cannot drift from the program's --help, and docs/README.md lists every page of docs/.

Runs `restitution [CMD...] --help` for every subcommand (found recursively under "Subcommands:") and reads the
options each lists. docs/cli.md has one section per command, headed `## restitution CMD` (or `###`); each must
name every option of its command as `--option` (both names of an alias such as `--output,--out`), and may
name no option its command lacks. Outside those sections every `--option` must exist in some command, but for
the "before" column of a table (the old spellings of the page's table "Spellings", hidden from --help). `--help`
needs no mention (every command has it; the page says so once). Every command must have its section and every
section must be a command. Each failure names the command, the option and where it is missing.

Usage: docs_cli.py RESTITUTION SOURCE_DIR
"""
import json
import pathlib
import re
import subprocess
import sys

OPTION_LINE = re.compile(r"^  (-\w,)?(--[\w-]+(?:,--[\w-]+)*)")
SUBCOMMAND_LINE = re.compile(r"^  ([a-z][a-z0-9-]*)\b")
HEADING = re.compile(r"^(#{1,6}) (.*)$")
COMMAND_HEADING = re.compile(r"^`?restitution((?: [a-z][a-z0-9-]*)*)`?$")
DOC_OPTION = re.compile(r"(?<![\w-])--[a-z][\w-]*")
ALWAYS = {"--help", "--version"}
OTHER_TOOL = re.compile(r"\b(cmake|ctest|pkg-config|pip|pytest|man)( [\w./\"$-]+)*")  # their options are not ours


def help_text(program, path):
    done = subprocess.run([program, *path, "--help"], capture_output=True, text=True, timeout=60)
    if done.returncode != 0:
        sys.exit(f"`restitution {' '.join(path)} --help` exited {done.returncode}: {done.stderr.strip()}")
    return done.stdout


def sections_of(help_output):
    """{'Options': [lines], 'Subcommands': [lines], ...} from a CLI11 --help text."""
    sections, current = {}, None
    for line in help_output.splitlines():
        if re.match(r"^[A-Z][a-z]+:$", line):
            current = sections.setdefault(line[:-1], [])
        elif current is not None and line.startswith(" "):
            current.append(line)
        else:
            current = None
    return sections


def commands(program, path=()):
    """{('eps',): {'--zeta', ...}, ('series', 'eval'): {...}, ...}: every (sub)command and its options."""
    found = {}
    sections = sections_of(help_text(program, list(path)))
    if path:
        found[path] = {name for line in sections.get("Options", []) if (m := OPTION_LINE.match(line))
                       for name in m.group(2).split(",")} - ALWAYS
    for line in sections.get("Subcommands", []):
        if m := SUBCOMMAND_LINE.match(line):
            found.update(commands(program, path + (m.group(1),)))
    return found


def doc_sections(text):
    """[(command path or None, heading line, body)] of a markdown page, split at every heading."""
    result, path, line_number, body = [], None, 1, []
    in_fence = False
    for number, line in enumerate(text.splitlines(), 1):
        in_fence ^= line.startswith("```")
        heading = None if in_fence else HEADING.match(line)
        if heading:
            result.append((path, line_number, "\n".join(body)))
            command = COMMAND_HEADING.match(heading.group(2).strip())
            path = tuple(command.group(1).split()) if command else None
            line_number, body = number, []
        else:
            body.append(line)
    result.append((path, line_number, "\n".join(body)))
    return result


def without_old_spellings(body):
    """body without the cells of a table's "before" column: the old spellings, which --help no longer lists."""
    kept, before = [], None
    for line in body.splitlines():
        cells = line.split("|")
        if not line.startswith("|"):
            before = None
        elif before is None and "before" in [c.strip() for c in cells]:
            before = [c.strip() for c in cells].index("before")
        elif len(cells) > before:
            cells[before] = ""
            line = "|".join(cells)
        kept.append(line)
    return "\n".join(kept)


def json_example_problems(program, page_text):
    """The example of `eps --zeta 1 --json` must be what the program prints: the same keys in the same order
    and the same values, but for the counts (stats), the code's version and the SUNDIALS build, which differ
    between builds."""
    marker = "JSON of `restitution eps --zeta 1 --json`"
    if marker not in page_text:
        return [f"docs/cli.md has no example headed {marker}"]
    block = page_text.split(marker, 1)[1].split("```json\n", 1)[1].split("```", 1)[0]
    documented = json.loads(block)
    done = subprocess.run([program, "eps", "--zeta", "1", "--json"], capture_output=True, text=True, timeout=60)
    printed = json.loads(done.stdout)

    def compare(doc, real, where):
        if isinstance(doc, dict) and isinstance(real, dict):
            if list(doc) != list(real):
                return [f"docs/cli.md's eps JSON example{where} has keys {list(doc)}, the program prints {list(real)}"]
            return [p for key in doc if key not in ("stats", "restitution", "sundials") or where
                    for p in compare(doc[key], real[key], f"{where}.{key}")]
        if doc != real:
            return [f"docs/cli.md's eps JSON example{where} is {doc!r}, the program prints {real!r}"]
        return []

    problems = compare(documented, printed, "")
    for key in ("stats", "restitution", "sundials"):  # keys only: counts and versions belong to the build
        if list(documented.get(key, {})) != list(printed.get(key, {})):
            problems.append(f"docs/cli.md's eps JSON example.{key} has keys {list(documented.get(key, {}))}, "
                            f"the program prints {list(printed.get(key, {}))}")
    return problems


def main():
    program, source = sys.argv[1], pathlib.Path(sys.argv[2])
    docs = source / "docs"
    page = docs / "cli.md"
    program_commands = commands(program)
    every_option = set().union(*program_commands.values()) | ALWAYS
    problems, documented = [], set()
    for path, line, body in doc_sections(page.read_text(encoding="utf-8")):
        named = set(DOC_OPTION.findall(OTHER_TOOL.sub("", without_old_spellings(body))))
        if path is None:
            problems += [f"docs/cli.md:{line}: {option} is mentioned but no command has it in --help"
                         for option in sorted(named - every_option)]
            continue
        name = "restitution " + " ".join(path)
        if path not in program_commands:
            if path:  # `## restitution` alone heads the program's own section
                problems.append(f"docs/cli.md:{line}: section `{name}`, but --help lists no such command")
            continue
        documented.add(path)
        for option in sorted(program_commands[path] - named):
            problems.append(f"`{name} --help` lists {option}, but docs/cli.md's section `{name}` (line {line}) "
                            f"does not mention it")
        for option in sorted(named - program_commands[path] - ALWAYS):
            problems.append(f"docs/cli.md's section `{name}` (line {line}) mentions {option}, but "
                            f"`{name} --help` does not list it")
    for path in sorted(set(program_commands) - documented):
        subcommands = [p for p in program_commands if p[:len(path)] == path and len(p) > len(path)]
        if not program_commands[path] and subcommands:
            continue  # a group such as `series`: only --help of its own; its subcommands have sections
        problems.append(f"`restitution {' '.join(path)}` has no section `## restitution {' '.join(path)}` "
                        f"in docs/cli.md")

    problems += json_example_problems(program, page.read_text(encoding="utf-8"))

    index = (docs / "README.md").read_text(encoding="utf-8")
    for doc in sorted(docs.glob("*.md")):
        if doc.name != "README.md" and f"]({doc.name})" not in index:
            problems.append(f"docs/README.md does not list {doc.name}")
    for link in re.findall(r"\]\(([\w.-]+\.md)\)", index):
        if not (docs / link).exists():
            problems.append(f"docs/README.md lists {link}, which is not in docs/")

    for problem in problems:
        print(problem)
    options = sum(len(o) for o in program_commands.values())
    print(f"{len(program_commands)} commands, {options} options: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
