#!/usr/bin/env python3
"""Documents that cannot go stale, and the tree's size rules (ctest: tree.*).

  tree_test.py paths                    every repository path a comment or a Markdown document names exists
  tree_test.py json-keys TRITRI         the check JSON's documented keys are exactly those `tritri check` writes
  tree_test.py sizes                    no function over 80 lines, no non-test file over 400 lines

What counts as a path: a run of the characters [A-Za-z0-9_.+/-] containing a "/", in a
comment (C++ `//` and `/* */`, `#` in CMake, Python and shell; Python docstrings too) or
anywhere in a Markdown document, whose first component is either a top-level entry of the
repository (`algorithms/exact/README.md`, `.ci/run`) or a folder beside the file that names it
(`generator/families.cpp` in cases/README.md, `workloads/scene.cpp` in harness/bench/). It may
end in `:LINE` or `:FIRST-LAST`, and the file must then have that many lines. A token with
`*` is a glob and must match something; one with a placeholder (`<`, `>`, `{`, `}`, `...`, or
a component in capitals such as `FOLDER`, or a capitalised word after `_` or `-` in a
component, such as `cmd_NAME.cpp`) is not a path. A leading `./` and a sentence's final
`.` or `,` are not part of it. URLs (`://`) and build outputs (`build/`) are not checked.

A heading cited by name, `FILE.md, "Heading"` (the quotes may be backslash-escaped in code),
must be the start of a heading in that file (backquotes aside, in both).
"""

import ast
import glob
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

MAX_FUNCTION_LINES = 80
MAX_FILE_LINES = 400
# Files allowed over the limits, with why. Empty: none is.
SIZE_EXCEPTIONS = {}

SOURCE = (".cpp", ".hpp", ".h", ".c", ".inc", ".py")
COMMENTED = SOURCE + (".cmake", ".sh", ".in")
NOT_CHECKED = ("build/", "results/")
TOP = set()  # the repository's top-level entries: set by check_paths from the file list

PATH = re.compile(r"(?<![\w.+/-])([A-Za-z0-9_.+-]+(?:/[A-Za-z0-9_.+*<>{}-]+)+/?)(?::(\d+)(?:-(\d+))?)?")
HEADING_CITE = re.compile(r"([\w./+-]*\.md)`?,\s*\\?\"([^\"\\]+)\\?\"")


def tracked_files():
    try:
        out = subprocess.run(["git", "-C", ROOT, "ls-files"], capture_output=True, text=True, check=True).stdout
        files = [f for f in out.splitlines() if os.path.exists(os.path.join(ROOT, f))]
        if files:
            return files
    except (OSError, subprocess.CalledProcessError):
        pass
    files = []  # not a git checkout (a source tarball): every file but the build's
    for d, dirs, names in os.walk(ROOT):
        dirs[:] = [x for x in dirs if not x.startswith((".git", "build", "results"))]
        files += [os.path.relpath(os.path.join(d, n), ROOT) for n in names]
    return files


def comment_text(path, text):
    """The parts of a source file that are prose: its comments (and Python's docstrings)."""
    if path.endswith(".md"):
        return text
    if path.endswith(".py"):
        parts = [m.group(0) for m in re.finditer(r"#[^\n]*", text)]
        try:
            for node in ast.walk(ast.parse(text)):
                if isinstance(node, ast.Expr) and isinstance(getattr(node, "value", None), ast.Constant) \
                        and isinstance(node.value.value, str):
                    parts.append(node.value.value)
        except SyntaxError:
            pass
        return "\n".join(parts)
    if path.endswith((".cpp", ".hpp", ".h", ".c", ".inc")):
        return "\n".join(m.group(0) for m in re.finditer(r"//[^\n]*|/\*.*?\*/", text, re.S))
    return "\n".join(m.group(0) for m in re.finditer(r"(?m)#[^\n]*", text))


def resolve(token, citing):
    """The file a path token names, relative to the top or to the citing file's folder, or None
    when the token is not a path by the rule above."""
    token = token.rstrip(".,")
    while token.startswith("./"):
        token = token[2:]
    if "://" in token or "/" not in token or re.search(r"[<>{}]|\.\.\.", token) \
            or any(re.fullmatch(r"[A-Z][A-Z_]+", part) or re.search(r"[_-][A-Z]{2,}(?![a-z])", part)
                   for part in token.split("/")):
        return None
    first = token.split("/", 1)[0]
    here = os.path.dirname(citing)
    if first in TOP:
        base = ""
    elif here and os.path.isdir(os.path.join(ROOT, here, first)):
        base = here
    else:
        return None
    name = os.path.normpath(os.path.join(base, token.rstrip("/")))
    if name.startswith(NOT_CHECKED) or first in ("build", "results"):
        return None
    return name


def exists(name):
    full = os.path.join(ROOT, name)
    return glob.glob(full) if "*" in name else os.path.exists(full)


def line_count(name):
    with open(os.path.join(ROOT, name), encoding="utf-8", errors="replace") as f:
        return sum(1 for _ in f)


def headings(name):
    with open(os.path.join(ROOT, name), encoding="utf-8") as f:
        return [line.lstrip("#").strip().replace("`", "") for line in f if line.startswith("#")]


def stale_references(files):
    problems = []
    for path in files:
        if not (path.endswith((".md",) + COMMENTED) or os.path.basename(path) in ("CMakeLists.txt",)
                or path.startswith("scripts/") or path == ".ci/run"):
            continue
        with open(os.path.join(ROOT, path), encoding="utf-8", errors="replace") as f:
            text = comment_text(path, f.read())
        for m in PATH.finditer(text):
            name = resolve(m.group(1), path)
            if name is None:
                continue
            if not exists(name):
                problems.append("%s: names %s, which does not exist" % (path, m.group(0)))
            elif m.group(2) and os.path.isfile(os.path.join(ROOT, name)):
                last = int(m.group(3) or m.group(2))
                if line_count(name) < last:
                    problems.append("%s: names %s, but %s has %d lines" % (path, m.group(0), name, line_count(name)))
        for m in HEADING_CITE.finditer(re.sub(r"\n\s*(?://|#|\*)?\s*", " ", text)):
            target = m.group(1)
            name = resolve(target, path) if "/" in target else os.path.join(os.path.dirname(path), target)
            if name and os.path.isfile(os.path.join(ROOT, name)) and \
                    not any(h.startswith(m.group(2).replace("`", "")) for h in headings(name)):
                problems.append('%s: cites "%s" in %s, which has no such heading' % (path, m.group(2), name))
    return problems


def check_paths():
    files = tracked_files()
    TOP.update(f.split("/", 1)[0] for f in files)
    problems = stale_references(files)
    for p in problems:
        print(p)
    print("%d passed, %d failed" % (1 if not problems else 0, 1 if problems else 0))
    return 1 if problems else 0


# ---- the documented JSON keys ----

def documented_keys(markdown, heading_start):
    """The key paths of the JSON sketched in the first code block under the heading: in `{}` a
    quoted word is a key unless it follows `:` (a value); words joined by `|` are alternatives
    (keys or values, as the first is); `KEY: null | {...}` nests under KEY; in `[]` quoted words
    are values. `// ...` is a comment."""
    with open(os.path.join(ROOT, markdown), encoding="utf-8") as f:
        text = f.read()
    at = text.index(heading_start)
    block = text[text.index("```", at) + 3:]
    block = re.sub(r"//[^\n]*", "", block[block.index("\n"):block.index("```")])
    keys = set()
    stack = [("{", [""])]  # (bracket, the path prefixes of the keys in it)
    group, pending, prev, role = [], [], None, None
    for tok in re.findall(r'"[^"]*"|[{}\[\]:,|]', block):
        if tok in "{[":
            parents = stack[-1][1]
            names = pending or [""]
            prefixes = [p + n + ("[]" if tok == "[" else "") for p in parents for n in names]
            stack.append((tok, [x + "." if tok == "{" else x for x in prefixes]))
            pending, group = [], []
        elif tok in "}]":
            stack.pop()
            pending, group = [], []
        elif tok == ":":
            pending = group if role == "key" else pending
        elif tok == ",":
            pending, group = [], []
        elif tok.startswith('"') and stack[-1][0] == "{":
            role = role if prev == "|" else ("value" if prev == ":" else "key")
            if role == "key":
                group = (group if prev == "|" else []) + [tok.strip('"')]
                keys.update(p + tok.strip('"') for p in stack[-1][1])
        prev = tok
    return {k.replace("..", ".").lstrip(".") for k in keys}


def written_keys(doc, path="", out=None):
    out = set() if out is None else out
    if isinstance(doc, dict):
        for k, v in doc.items():
            out.add(path + k)
            written_keys(v, path + k + ".", out)
    elif isinstance(doc, list):
        for v in doc:
            written_keys(v, path[:-1] + "[].", out)
    return out


def check_json_keys(tritri):
    """`tritri check --json` with the options that fill every documented part, against
    harness/README.md's sketch of it."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "check.json")
        subprocess.run([tritri, "check", "--quiet", "--scorecard", "--scorecard-bases", "4", "--shard", "0/1",
                        "--algo", "moller97,guigue03-segment,yuhe13,fcl", "--json", out,
                        os.path.join(ROOT, "cases", "builtin.cases")], check=False, stdout=subprocess.DEVNULL)
        with open(out, encoding="utf-8") as f:
            written = written_keys(json.load(f))
    documented = documented_keys("harness/README.md", "## JSON (`--json OUT`)")
    problems = ["harness/README.md documents %s, which tritri check does not write" % k
                for k in sorted(documented - written)]
    problems += ["tritri check writes %s, which harness/README.md does not document" % k
                 for k in sorted(written - documented)]
    for p in problems:
        print(p)
    print("%d passed, %d failed" % (0 if problems else 1, 1 if problems else 0))
    return 1 if problems else 0


# ---- sizes ----

def cpp_function_lengths(text):
    """(first line, lines) of each function body in C++ source: a `{` whose statement has a
    `(`, opened outside any function, and not a control statement or an initializer."""
    code = re.sub(r"//[^\n]*|/\*.*?\*/|\"(?:\\.|[^\"\\\n])*\"|'(?:\\.|[^'\\\n])*'",
                  lambda m: re.sub(r"[^\n]", " ", m.group(0)), text, flags=re.S)
    code = re.sub(r"(?m)^[ \t]*#.*$", "", code)  # preprocessor lines
    out, stack, start = [], [], 0
    for i, ch in enumerate(code):
        if ch in ";{}":
            if ch == "{":
                head = code[start:i]
                inside = any(kind == "function" for kind, _ in stack)
                is_function = (not inside and "(" in head and "=" not in head.split("(")[0]
                               and not re.search(r"(^|\n)\s*(namespace|struct|class|enum|union|extern)\b[^\n]*$", head)
                               and not re.match(r"\s*(if|for|while|switch|catch|else|do)\b", head))
                stack.append(("function" if is_function else "scope", code.count("\n", 0, i) + 1))
            elif ch == "}" and stack:
                kind, line = stack.pop()
                if kind == "function":
                    out.append((line, code.count("\n", 0, i) + 1 - line + 1))
            start = i + 1
    return out


def python_function_lengths(text):
    return [(n.lineno, n.end_lineno - n.lineno + 1) for n in ast.walk(ast.parse(text))
            if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))]


def is_test(path):
    name = os.path.basename(path)
    return re.search(r"(_test|_fuzz|^test_)", name) is not None or "/tests/" in "/" + path


def check_sizes():
    problems = []
    for path in tracked_files():
        if not path.endswith(SOURCE) or path.startswith("harness/authors/"):
            continue  # harness/authors/ holds the published authors' code, kept as printed
        with open(os.path.join(ROOT, path), encoding="utf-8", errors="replace") as f:
            text = f.read()
        lines = text.count("\n")
        if not is_test(path) and lines > MAX_FILE_LINES and path not in SIZE_EXCEPTIONS:
            problems.append("%s: %d lines (at most %d)" % (path, lines, MAX_FILE_LINES))
        lengths = python_function_lengths(text) if path.endswith(".py") else cpp_function_lengths(text)
        for line, n in lengths:
            if n > MAX_FUNCTION_LINES and path not in SIZE_EXCEPTIONS:
                problems.append("%s:%d: a function of %d lines (at most %d)" % (path, line, n, MAX_FUNCTION_LINES))
    for p in problems:
        print(p)
    print("%d passed, %d failed" % (0 if problems else 1, 1 if problems else 0))
    return 1 if problems else 0


def main(argv):
    if argv[1:2] == ["paths"]:
        return check_paths()
    if argv[1:2] == ["json-keys"] and len(argv) == 3:
        return check_json_keys(argv[2])
    if argv[1:2] == ["sizes"]:
        return check_sizes()
    sys.exit(__doc__)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
