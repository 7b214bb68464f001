#!/usr/bin/env python3
"""The shape of tfem's library code, as the restructuring notes report it.

    python3 scripts/code_shape.py [--list] [SRC_DIR]     (default: src)

Prints the lines of the library without the verification harness
(src/studies), the functions longer than 80 lines, those that take tuple
parameters (a tuple pattern such as `(a, b): (A, B)`) or seven parameters or
more (a tuple pattern counting as the names it binds), and the public
methods of `Model`. With --list, also prints each function with tuple
parameters as `path:line name: <its tuple parameters>`.

Functions are found by their `fn` line and their body by brace matching
(strings and comments are skipped), which is enough for rustfmt'd code: the
body is the first `{` outside parentheses and brackets after the parameter
list, so a `;` in a return type such as `-> Vec<[usize; 3]>` does not make
the fn a declaration, and the `->` of an `impl Fn(..) -> T` parameter does
not close a bracket. Test code is left out of the function counts: the
items annotated `#[cfg(test)]` (to the end of their braces, or to `;`), and
the files of modules declared `#[cfg(test)] mod name;`. The line count is of
every file, tests included.
"""

import re
import sys
from pathlib import Path


def strip_code(text):
    """The text with comments, strings and char literals blanked (same length)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == '"' or (c == "r" and re.match(r'r#*"', text[i:])):
            m = re.match(r'r(#*)"', text[i:])
            if m:
                end = '"' + m.group(1)
                j = text.find(end, i + len(m.group(0)))
                j = n if j < 0 else j + len(end)
            else:
                j = i + 1
                while j < n and text[j] != '"':
                    j += 2 if text[j] == "\\" else 1
                j += 1
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "'" and re.match(r"'(\\.|[^\\'])'", text[i:]):
            m = re.match(r"'(\\.|[^\\'])'", text[i:])
            out.append(" " * len(m.group(0)))
            i += len(m.group(0))
        else:
            out.append(c)
            i += 1
    return "".join(out)


FN = re.compile(r"\bfn\s+([A-Za-z_][A-Za-z0-9_]*)")
CFG_TEST = re.compile(r"#\s*\[\s*cfg\s*\(\s*test\s*\)\s*\]")
INNER_CFG_TEST = re.compile(r"#\s*!\s*\[\s*cfg\s*\(\s*test\s*\)\s*\]")


def match_brace(code, b):
    """The index of the '}' matching the '{' at b (len(code) if none)."""
    depth, e = 0, b
    while e < len(code):
        if code[e] == "{":
            depth += 1
        elif code[e] == "}":
            depth -= 1
            if depth == 0:
                return e
        e += 1
    return e


def body_or_end(code, i):
    """From i, the first '{' or ';' outside parentheses and brackets: its
    index and which it is (len(code), None if neither)."""
    depth = 0
    while i < len(code):
        c = code[i]
        if c in "([":
            depth += 1
        elif c in ")]":
            depth -= 1
        elif depth <= 0 and c in "{;":
            return i, c
        i += 1
    return i, None


def test_spans(code):
    """(start, end) offsets of the items annotated #[cfg(test)], and the
    names of the modules declared `#[cfg(test)] mod name;`."""
    spans, mods = [], []
    for m in CFG_TEST.finditer(code):
        i = m.end()
        # Further attributes between this one and the item.
        while True:
            while i < len(code) and code[i].isspace():
                i += 1
            if not code.startswith("#", i):
                break
            j = code.find("[", i)
            depth = 0
            while j < len(code):
                depth += {"[": 1, "]": -1}.get(code[j], 0)
                j += 1
                if depth == 0:
                    break
            i = j
        k, c = body_or_end(code, i)
        end = match_brace(code, k) if c == "{" else k
        spans.append((m.start(), end))
        decl = re.match(r"(pub(\([^)]*\))?\s+)?mod\s+(\w+)\s*;", code[i : end + 1])
        if decl:
            mods.append(decl.group(3))
    return spans, mods


def functions(path):
    """(name, first line, body lines, parameter text) of every fn with a
    body, those inside items annotated #[cfg(test)] left out."""
    text = path.read_text()
    code = strip_code(text)
    spans, _ = test_spans(code)
    found = []
    for m in FN.finditer(code):
        if any(a <= m.start() <= b for a, b in spans):
            continue
        start = m.end()
        # The parameter list: from the first '(' to its match.
        p = code.find("(", start)
        if p < 0:
            continue
        depth, q = 0, p
        while q < len(code):
            depth += {"(": 1, ")": -1}.get(code[q], 0)
            q += 1
            if depth == 0:
                break
        params = code[p + 1 : q - 1]
        # The body: the next '{' outside parentheses and brackets, unless a
        # ';' comes first (a declaration); `[usize; 3]` is inside brackets.
        b, c = body_or_end(code, q)
        if c != "{":
            continue
        e = match_brace(code, b)
        first = code.count("\n", 0, m.start()) + 1
        last = code.count("\n", 0, e) + 1
        found.append((m.group(1), first, last - first + 1, params))
    return found


def test_files(files):
    """The files of modules declared `#[cfg(test)] mod name;` (or under
    such a module's directory), and of files with an inner #![cfg(test)]."""
    out = set()
    for p in files:
        code = strip_code(p.read_text())
        if INNER_CFG_TEST.search(code):
            out.add(p)
        _, mods = test_spans(code)
        # A mod.rs / lib.rs / main.rs declares its modules beside it, any
        # other file in the directory named after it.
        base = p.parent if p.name in ("mod.rs", "lib.rs", "main.rs") else p.with_suffix("")
        for name in mods:
            for q in files:
                if q == base / f"{name}.rs" or (base / name) in q.parents:
                    out.add(q)
    return out


def split_params(params):
    """Top-level comma-separated parameters."""
    out, depth, cur = [], 0, ""
    for i, ch in enumerate(params):
        if ch in "([{<":
            depth += 1
        elif ch in ")]}" or (ch == ">" and params[i - 1 : i] != "-"):
            # The '>' of a '->' (as in `impl Fn(usize) -> f64`) closes nothing.
            depth -= 1
        if ch == "," and depth == 0:
            out.append(cur.strip())
            cur = ""
        else:
            cur += ch
    if cur.strip():
        out.append(cur.strip())
    return [p for p in out if p and not re.fullmatch(r"&?('\w+\s+)?(mut\s+)?self", p)]


def main():
    args = sys.argv[1:]
    listing = "--list" in args
    args = [a for a in args if a != "--list"]
    src = Path(args[0] if args else "src")
    files = sorted(p for p in src.rglob("*.rs") if "studies" not in p.parts)
    lines = sum(len(p.read_text().splitlines()) for p in files)
    tests = test_files(files)
    long_fns, tuples, many = [], [], []
    for p in files:
        if p in tests:
            continue
        for name, first, length, params in functions(p):
            where = f"{p}:{first} {name}"
            if length > 80:
                long_fns.append((length, where))
            ps = split_params(params)
            packed = [q for q in ps if re.match(r"\(", q)]
            if packed:
                tuples.append((where, "; ".join(" ".join(q.split()) for q in packed)))
            # A tuple pattern counts as the parameters it packs.
            count = len(ps) + sum(len(split_params(q.split(":")[0].strip()[1:-1])) - 1 for q in packed)
            if count >= 7:
                many.append(where)
    model = Path(src, "model")
    methods = set()
    for p in sorted(model.glob("*.rs")):
        text = strip_code(p.read_text())
        for block in re.finditer(r"impl\s+Model\s*\{", text):
            depth, i = 0, block.end() - 1
            while i < len(text):
                depth += {"{": 1, "}": -1}.get(text[i], 0)
                if depth == 0:
                    break
                i += 1
            body = text[block.end() : i]
            methods.update(re.findall(r"\bpub\s+fn\s+(\w+)", body))
    print(f"library lines (src without studies): {lines}")
    print(f"functions over 80 lines: {len(long_fns)}")
    for length, where in sorted(long_fns, reverse=True):
        print(f"  {length:4d}  {where}")
    print(f"functions with tuple parameters: {len(tuples)}")
    if listing:
        for where, packed in tuples:
            print(f"  {where}: {packed}")
    print(f"functions with 7 or more parameters (a tuple's members counted): {len(many)}")
    for where in many:
        print(f"  {where}")
    print(f"public methods of Model: {len(methods)}")


if __name__ == "__main__":
    main()
