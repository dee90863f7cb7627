#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Contract checks of the public headers (tools/check.sh stage "contracts").

1. The doc comment in front of each public function declared in
   include/dhmath/*.h has at most MAX_LINES lines (a contract a user reads
   in one screen; methods and proofs belong in src/ or docs/design.md).
2. No history markers and no citations of documents outside the repository
   in src/, include/, docs/, README.md, tools/, bench/, port/, examples/ and
   fuzz/: the word issue followed by a number (also with a hash sign or a
   hyphen), or seed followed by a three-digit number from 000 (any case). Literature is cited by name (docs/references.md).

Usage: tools/check_contracts.py [--report] [--max N] [ROOT]
  --report  print every function's comment length, longest first.
Exit status 0 when both checks pass, 1 otherwise.
"""
import glob
import os
import re
import sys

MAX_LINES = 30
HISTORY = re.compile(r"issues?[ -]#?[0-9]|issues? #|seed 00[0-9]", re.IGNORECASE)
# where the history check looks (directories walked, plus single files)
HISTORY_DIRS = ("src", "include", "docs", "tools", "bench", "port", "examples", "fuzz")
HISTORY_FILES = ("README.md",)
# A function declaration at file scope: return type, name, '(' ... ');'
DECL = re.compile(r"^[A-Za-z_][\w \*]*?\b(dh_\w+)\s*\(")


def function_comments(path):
    """Yield (name, comment_lines, line_no) for each function declaration."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    i = 0
    while i < len(lines):
        line = lines[i]
        m = DECL.match(line)
        if m and not line.startswith(("typedef", "#")):
            # the declaration may span lines; it must end with ");"
            j = i
            while j < len(lines) and ";" not in lines[j] and "{" not in lines[j]:
                j += 1
            if j < len(lines) and ";" in lines[j]:
                # preceding doc comment: the block ending on line i-1 with */
                k = i - 1
                n = 0
                if k >= 0 and lines[k].rstrip().endswith("*/"):
                    start = k
                    while start >= 0 and "/**" not in lines[start]:
                        start -= 1
                    if start >= 0:
                        n = k - start + 1
                yield m.group(1), n, i + 1
            i = j + 1
            continue
        i += 1


def main(argv):
    report = "--report" in argv
    args = [a for a in argv if a != "--report"]
    limit = MAX_LINES
    if "--max" in args:
        k = args.index("--max")
        limit = int(args[k + 1])
        del args[k:k + 2]
    root = args[0] if args else os.path.join(os.path.dirname(__file__), "..")
    ok = True
    rows = []
    for h in sorted(glob.glob(os.path.join(root, "include", "dhmath", "*.h"))):
        rel = os.path.relpath(h, root)
        for name, n, ln in function_comments(h):
            rows.append((n, rel, ln, name))
            if n == 0:
                print(f"{rel}:{ln}: {name}: no doc comment directly before the declaration")
                ok = False
            elif n > limit:
                print(f"{rel}:{ln}: {name}: doc comment {n} lines (limit {limit})")
                ok = False
    if report:
        for n, rel, ln, name in sorted(rows, reverse=True):
            print(f"{n:4d}  {rel}:{ln}  {name}")
    paths = [os.path.join(root, f) for f in HISTORY_FILES]
    for top in HISTORY_DIRS:
        for dirpath, dirs, files in os.walk(os.path.join(root, top)):
            dirs.sort()
            paths.extend(os.path.join(dirpath, fn) for fn in sorted(files))
    for p in paths:
        try:
            with open(p, encoding="utf-8", errors="replace") as f:
                for ln, text in enumerate(f, 1):
                    if HISTORY.search(text):
                        print(f"{os.path.relpath(p, root)}:{ln}: history marker: {text.strip()}")
                        ok = False
        except OSError:
            continue
    print(f"check_contracts: {len(rows)} public functions, "
          f"longest comment {max((r[0] for r in rows), default=0)} lines: "
          + ("passed" if ok else "FAILED"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
