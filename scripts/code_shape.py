#!/usr/bin/env python3
"""The shape of tfem's library code, as the restructuring notes report it.

    python3 scripts/code_shape.py [SRC_DIR]     (default: src)

Prints the lines of the library without the verification harness
(src/studies), the functions longer than 80 lines, those that take tuple
parameters or seven parameters or more, and the public methods of `Model`.
Functions are found by their `fn` line and their body by brace matching
(strings and comments are skipped), which is enough for rustfmt'd code.
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


def functions(path):
    """(name, first line, body lines, parameter text) of every fn with a body."""
    text = path.read_text()
    code = strip_code(text)
    found = []
    for m in FN.finditer(code):
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
        # The body: the next '{' unless a ';' comes first (a declaration).
        b = q
        while b < len(code) and code[b] not in "{;":
            b += 1
        if b >= len(code) or code[b] == ";":
            continue
        depth, e = 0, b
        while e < len(code):
            if code[e] == "{":
                depth += 1
            elif code[e] == "}":
                depth -= 1
                if depth == 0:
                    break
            e += 1
        first = code.count("\n", 0, m.start()) + 1
        last = code.count("\n", 0, e) + 1
        found.append((m.group(1), first, last - first + 1, params))
    return found


def split_params(params):
    """Top-level comma-separated parameters."""
    out, depth, cur = [], 0, ""
    for ch in params:
        if ch in "([{<":
            depth += 1
        elif ch in ")]}>":
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
    src = Path(sys.argv[1] if len(sys.argv) > 1 else "src")
    files = sorted(p for p in src.rglob("*.rs") if "studies" not in p.parts)
    lines = sum(len(p.read_text().splitlines()) for p in files)
    long_fns, tuples, many = [], [], []
    for p in files:
        text = p.read_text()
        test_at = text.find("#[cfg(test)]")
        test_line = text.count("\n", 0, test_at) + 1 if test_at >= 0 else None
        for name, first, length, params in functions(p):
            if test_line is not None and first > test_line:
                continue
            where = f"{p}:{first} {name}"
            if length > 80:
                long_fns.append((length, where))
            ps = split_params(params)
            packed = [q for q in ps if re.match(r"\(", q)]
            if packed:
                tuples.append(where)
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
    print(f"functions with 7 or more parameters (a tuple's members counted): {len(many)}")
    for where in many:
        print(f"  {where}")
    print(f"public methods of Model: {len(methods)}")


if __name__ == "__main__":
    main()
