#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Runs every example of README.md and docs/*.md, so that the pages cannot drift from the program.

A block or a command can be marked as not run, with the reason, and is then reported as such:
  <!-- not run: REASON -->   on the line before a fence: the whole block;
  COMMAND  # ... not run: REASON    a command line of an sh block whose comment ends so.
The program is on PATH, so docs may write `restitution ...` as well as `build/release/restitution ...`.
Each other fenced block is checked by its language tag:
  sh      every command line runs (exit 0) in a scratch folder that sees the build, scenes, data and
          examples of the checkout; `bash scripts/...` lines (the set-up commands) are left to CI itself;
  toml    a scene: `restitution run FILE --quick --out DIR` must succeed;
  python  runs with the built module on PYTHONPATH;
  cpp, c, cmake  must stand verbatim in a file under examples/, which its own test compiles and runs;
  json    illustrates an output format: not run.
A block tagged with anything else fails the test, so that nothing new slips past unchecked.

Usage: readme_examples.py SOURCE_DIR BUILD_DIR
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

FENCE = re.compile(r"^```(\w*)\n(.*?)^```", re.M | re.S)
BLOCK_NOT_RUN = re.compile(r"<!--\s*not run:\s*(\S.*?)\s*-->\s*$")
LINE_NOT_RUN = re.compile(r"#.*\bnot run:\s*(\S.*)$")


def blocks(readme: str):
    """(language, text, line, reason it is not run or None) of every fenced block."""
    for match in FENCE.finditer(readme):
        line = readme.count("\n", 0, match.start()) + 1
        before = readme[:match.start()].rstrip("\n").rsplit("\n", 1)[-1]
        marked = BLOCK_NOT_RUN.search(before)
        yield match.group(1), match.group(2), line, marked.group(1) if marked else None


def command_lines(text: str):
    """Shell commands of a block, with backslash continuations joined and comments dropped."""
    joined = re.sub(r"\\\n\s*", " ", text)
    for raw in joined.splitlines():
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        yield line


def scratch_folder(source: pathlib.Path, build: pathlib.Path) -> pathlib.Path:
    """A folder where README commands can write freely: build/release is the build under test."""
    work = pathlib.Path(tempfile.mkdtemp(prefix="readme-examples-"))
    (work / "build").mkdir()
    (work / "build" / "release").symlink_to(build)
    for name in ("scenes", "data", "examples"):
        if (source / name).exists():
            shutil.copytree(source / name, work / name)
    (work / "scripts").symlink_to(source / "scripts")
    return work


def run(cmd, cwd, env, where):
    done = subprocess.run(cmd, cwd=cwd, env=env, shell=isinstance(cmd, str), capture_output=True,
                          text=True, timeout=600)
    if done.returncode != 0:
        return [f"{where}: `{cmd}` exited {done.returncode}\n{done.stdout[-2000:]}{done.stderr[-2000:]}"]
    return []


def main() -> int:
    source, build = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve()
    pages = [source / "README.md"] + sorted((source / "docs").glob("*.md"))
    work = scratch_folder(source, build)
    env = dict(os.environ, PYTHONPATH=str(build / "python"), MPLBACKEND="Agg",
               PATH=f"{build}{os.pathsep}{os.environ.get('PATH', '')}")
    examples = [p.read_text(encoding="utf-8", errors="replace")
                for p in (source / "examples").rglob("*") if p.is_file()] if (source / "examples").exists() else []
    failures, ran, not_run = [], 0, []
    try:
        for page, language, text, line, reason in ((page, *block) for page in pages
                                                   for block in blocks(page.read_text(encoding="utf-8"))):
            where = f"{page.relative_to(source)}:{line}"
            if language == "json":
                continue
            if reason:
                not_run.append(f"{where}: {language} block not run: {reason}")
                continue
            if language == "sh":
                for cmd in command_lines(text):
                    if cmd.startswith("bash scripts/"):
                        continue
                    if marked := LINE_NOT_RUN.search(cmd):
                        not_run.append(f"{where}: `{cmd.split('#')[0].strip()}` not run: {marked.group(1)}")
                        continue
                    failures += run(cmd, work, env, where)
                    ran += 1
            elif language == "toml":
                scene = work / f"{page.stem}_scene_{line}.toml"
                scene.write_text(text, encoding="utf-8")
                failures += run([str(build / "restitution"), "run", str(scene), "--quick", "--out",
                                 str(work / f"{page.stem}_scene_{line}")], work, env, where)
                ran += 1
            elif language == "python":
                script = work / f"{page.stem}_example_{line}.py"
                script.write_text(text, encoding="utf-8")
                failures += run(["/usr/bin/python3", str(script)], work, env, where)
                ran += 1
            elif language in ("cpp", "c", "cmake"):
                if not any(text.strip() in example for example in examples):
                    failures.append(f"{where}: this {language} block stands in no file under examples/")
                ran += 1
            else:
                failures.append(f"{where}: block tagged '{language}' has no checker; tag it sh, toml, python, "
                                f"cpp, c, cmake or json")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    for note in not_run:
        print(note)
    for failure in failures:
        print(failure)
    print(f"{ran - len(failures)} passed, {len(failures)} failed, {len(not_run)} marked not run")
    return 1 if failures or ran == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
