#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Lists the C++ function bodies longer than a limit (default 120 lines) and fails when there is one.

Usage: function_length.py [--limit N] [--list] DIR...

A body is a brace block whose opening brace follows a parameter list (`)`, possibly followed by const,
noexcept, override, a trailing return type or a constructor's initializer list) at namespace or class scope.
Lambdas and blocks inside a body count as part of it. Comments, string and character literals are blanked
first, so braces in them do not count. The length is the number of lines from the opening brace's line to the
closing one's, both included: what a reader scrolls through.
"""
import argparse
import pathlib
import re
import sys

SOURCE_SUFFIXES = {".cpp", ".hpp", ".h", ".cc"}
# What may stand between a parameter list's ')' and the body's '{' of a function definition.
_TAIL = re.compile(
    r"\)\s*(?:const|noexcept(?:\([^()]*\))?|override|final|mutable|&|&&|\s)*"
    r"(?:->\s*[\w:<>,\s*&]+)?\s*(?::\s*[\w:]+\s*[({][^;{}]*[)}](?:\s*,\s*[\w:]+\s*[({][^;{}]*[)}])*)?\s*$",
    re.S)
_CONTROL = re.compile(r"\b(?:if|for|while|switch|catch)\s*\($")


def blank_comments_and_literals(text: str) -> str:
    """The text with comments and literals replaced by spaces, newlines kept (line numbers stay right)."""
    pattern = re.compile(r'//[^\n]*|/\*.*?\*/|R"(?P<d>[^(\s]*)\(.*?\)(?P=d)"|"(?:\\.|[^"\\\n])*"|'
                         r"'(?:\\.|[^'\\\n])*'", re.S)
    return pattern.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def _opens_function(before: str) -> bool:
    """Whether the code just before a '{' ends a function head."""
    head = before[-400:]
    match = _TAIL.search(head)
    if not match:
        return False
    # The '(' matching the ')' that ends the parameter list: a control statement is no function.
    close = match.start()
    depth = 0
    for i in range(close, -1, -1):
        if head[i] == ")":
            depth += 1
        elif head[i] == "(":
            depth -= 1
            if depth == 0:
                return not _CONTROL.search(head[max(0, i - 12):i + 1])
    return False


def long_functions(path: pathlib.Path, limit: int):
    """(first line, length) of each function body in `path` longer than `limit` lines."""
    text = blank_comments_and_literals(path.read_text(encoding="utf-8"))
    found = []
    stack = []  # for each open brace: (is a function body at the outermost level, its line)
    line = 1
    for i, ch in enumerate(text):
        if ch == "\n":
            line += 1
        elif ch == "{":
            inside_function = any(is_function for is_function, _ in stack)
            stack.append((not inside_function and _opens_function(text[:i]), line))
        elif ch == "}" and stack:
            is_function, start = stack.pop()
            length = line - start + 1
            if is_function and length > limit:
                found.append((start, length))
    return found


def self_test() -> None:
    """The counter on a sample that it can get wrong: a long function, a long control block in a short one, braces
    in literals and comments, an initializer list and a table that is no function."""
    import tempfile
    body = "\n".join(["  x += 1;"] * 5)
    sample = (f"int long_one(int x) const noexcept {{\n{body}\n  return x;\n}}\n"  # 8 lines
              "Point::Point(int a) : x_(a), y_{a} {\n  s = \"{{{\"; // }\n  c = '{';\n}\n"  # 4 lines
              f"const int table[] = {{\n{body}\n}};\n"
              f"void short_one() {{ if (x) {{\n{body}\n}} }}\n")  # 7 lines
    with tempfile.NamedTemporaryFile("w", suffix=".cpp", delete=False) as f:
        f.write(sample)
    found = long_functions(pathlib.Path(f.name), 3)
    pathlib.Path(f.name).unlink()
    assert found == [(1, 8), (9, 4), (20, 7)], found


def main() -> int:
    self_test()
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--limit", type=int, default=120)
    parser.add_argument("--list", action="store_true", help="print every long function and exit 0")
    parser.add_argument("dirs", nargs="+")
    args = parser.parse_args()
    offenders = []
    for folder in args.dirs:
        for path in sorted(pathlib.Path(folder).rglob("*")):
            if path.suffix in SOURCE_SUFFIXES and path.is_file():
                offenders += [(path, start, length) for start, length in long_functions(path, args.limit)]
    for path, start, length in offenders:
        print(f"{path}:{start}: a function of {length} lines (limit {args.limit})")
    print(f"{len(offenders)} function(s) over {args.limit} lines")
    return 0 if args.list or not offenders else 1


if __name__ == "__main__":
    sys.exit(main())
