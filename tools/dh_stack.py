#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Worst-case stack depth of every public dhmath function on a Cortex-M build.

Inputs: a CMake build directory of the library compiled with
``-fstack-usage -fcallgraph-info=su`` (GCC writes <object>.su and <object>.ci
next to each object file), the compiler flags of that build (to find the
multilib libgcc.a / libm.a / libc.a the firmware would link), and the
library archive.

Method:
  * library functions: the frame size GCC reports (.ci node label
    "N bytes (static)"); "dynamic" frames (VLA, alloca) are errors;
  * call edges: from the .ci files; a callee is resolved first inside the
    same translation unit (static functions), then among the library's
    global functions, else it is external (libgcc soft-float helpers,
    libm, libc);
  * external functions: their frames are measured from the disassembly of
    the multilib archives (push/stmdb register lists, vpush, sub sp), and
    their own calls (bl / b.w / tail calls) are followed the same way;
  * worst case of a function = own frame + max over callees, computed on
    the call graph; a cycle in the library part is recursion (an error).
    Indirect calls (function pointers) cannot be bounded and are errors.

Used by tools/check_guards.sh (limit check) and tools/footprint.py (table).
"""
import glob
import os
import re
import subprocess
import sys
from functools import lru_cache

NODE_RE = re.compile(r'node: \{ title: "([^"]+)" label: "([^"]*)"')
EDGE_RE = re.compile(r'edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"')
BYTES_RE = re.compile(r'\\n(\d+) bytes \(([a-z,]+)\)')


def public_functions(archive, nm="arm-none-eabi-nm"):
    """Global text symbols (T) of the archive with the dh_ prefix."""
    out = subprocess.run([nm, "-g", "--defined-only", archive], check=True,
                         capture_output=True, text=True).stdout
    funcs = set()
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[1] == "T" and parts[2].startswith("dh_"):
            funcs.add(parts[2])
    return funcs


class LibraryGraph:
    """Frames and call edges of the library from GCC's .ci files."""

    def __init__(self, objdir):
        self.frames = {}      # (tu, name) -> bytes
        self.qual = {}        # (tu, name) -> "static" / "dynamic,..."
        self.edges = {}       # (tu, name) -> [callee name]
        self.globals = {}     # name -> (tu, name) for non-static definitions
        self.errors = []
        cis = sorted(glob.glob(os.path.join(objdir, "**", "*.ci"), recursive=True))
        if not cis:
            raise SystemExit("dh_stack: no .ci files under %s (build with "
                             "-fstack-usage -fcallgraph-info=su)" % objdir)
        for ci in cis:
            tu = os.path.basename(ci)[:-3]
            defined = {}
            edges = []
            with open(ci) as f:
                text = f.read()
            for m in NODE_RE.finditer(text):
                title, label = m.group(1), m.group(2)
                b = BYTES_RE.search(label)
                if b:
                    defined[title] = (int(b.group(1)), b.group(2))
            for m in EDGE_RE.finditer(text):
                edges.append((m.group(1), m.group(2)))
            for name, (nbytes, q) in defined.items():
                key = (tu, name)
                self.frames[key] = nbytes
                self.qual[key] = q
                self.edges.setdefault(key, [])
                if "dynamic" in q:
                    self.errors.append("%s (%s): dynamic stack frame (%s)" % (name, tu, q))
            for src, dst in edges:
                if src in defined:
                    self.edges[(tu, src)].append((tu, dst))
        # globals: names defined in exactly one TU are resolvable from others
        count = {}
        for (tu, name) in self.frames:
            count.setdefault(name, []).append((tu, name))
        for name, keys in count.items():
            if len(keys) == 1:
                self.globals[name] = keys[0]

    def resolve(self, tu, name):
        if (tu, name) in self.frames:
            return ("lib", (tu, name))
        if name in self.globals:
            return ("lib", self.globals[name])
        return ("ext", name)


class ExternalFrames:
    """Stack use of libgcc/libm/libc functions from their disassembly."""

    PUSH_RE = re.compile(r'\b(push|stmdb\s+sp!,|stmfd\s+sp!,)\s*(?:\.w\s*)?\{([^}]*)\}')
    VPUSH_RE = re.compile(r'\b(vpush|vstmdb\s+sp!,)\s*\{([^}]*)\}')
    SUBSP_RE = re.compile(r'\bsub(?:\.w|w|s)?\s+sp,\s*(?:sp,\s*)?#(\d+)')
    CALL_RE = re.compile(r'\b(?:bl|blx|b\.w|b)\s+[0-9a-f]+\s+<([^>+]+)>')

    def __init__(self, cflags, objdump="arm-none-eabi-objdump", cc="arm-none-eabi-gcc"):
        self.funcs = {}   # name -> (own bytes, [callees])
        libs = []
        for lib in ("libgcc.a", "libm.a", "libc.a"):
            path = subprocess.run([cc] + cflags + ["-print-file-name=" + lib],
                                  check=True, capture_output=True, text=True).stdout.strip()
            if os.path.isabs(path) and os.path.exists(path):
                libs.append(path)
        for lib in libs:
            out = subprocess.run([objdump, "-d", "--no-show-raw-insn", lib],
                                 capture_output=True, text=True).stdout
            self._parse(out)

    @staticmethod
    def _count_regs(reglist):
        n = 0
        for part in reglist.split(","):
            part = part.strip()
            if not part:
                continue
            if "-" in part:
                a, b = part.split("-")
                n += int(re.sub(r"\D", "", b)) - int(re.sub(r"\D", "", a)) + 1
            else:
                n += 1
        return n

    def _parse(self, text):
        cur = None
        own = 0
        calls = []
        for line in text.splitlines():
            m = re.match(r'^[0-9a-f]+ <([^>]+)>:$', line)
            if m:
                if cur is not None and cur not in self.funcs:
                    self.funcs[cur] = (own, calls)
                cur, own, calls = m.group(1), 0, []
                continue
            if cur is None or "\t" not in line:
                continue
            ins = line.split("\t", 1)[1]
            p = self.PUSH_RE.search(ins)
            if p:
                own += 4 * self._count_regs(p.group(2))
            v = self.VPUSH_RE.search(ins)
            if v:
                regs = v.group(2)
                size = 8 if "d" in regs else 4
                own += size * self._count_regs(regs)
            s = self.SUBSP_RE.search(ins)
            if s:
                own += int(s.group(1))
            c = self.CALL_RE.search(ins)
            if c and c.group(1) != cur:
                calls.append(c.group(1))
        if cur is not None and cur not in self.funcs:
            self.funcs[cur] = (own, calls)

    def worst(self, name, _seen=None):
        """Worst-case stack of an external function (0 if unknown)."""
        return self._worst(name, frozenset())

    def _worst(self, name, seen):
        if name not in self.funcs or name in seen:
            return 0
        own, calls = self.funcs[name]
        best = 0
        for c in set(calls):
            best = max(best, self._worst(c, seen | {name}))
        return own + best


def short(name):
    """GCC names a static function "<path>/file.c:func": keep file.c:func."""
    return os.path.basename(name) if ":" in name else name


def analyse(objdir, archive, cflags):
    """Returns (results, errors): results[name] = (worst bytes, call path)."""
    g = LibraryGraph(objdir)
    ext = ExternalFrames(cflags)
    errors = list(g.errors)
    ext_cache = {}

    def ext_worst(name):
        if name not in ext_cache:
            ext_cache[name] = ext.worst(name)
        return ext_cache[name]

    memo = {}
    state = {}

    def worst(key, stack):
        """(bytes, path) for library function key; detects cycles."""
        if key in memo:
            return memo[key]
        if state.get(key) == "active":
            cyc = " -> ".join(k[1] for k in stack[stack.index(key):] + [key])
            errors.append("recursion: " + " -> ".join(short(k) for k in cyc.split(" -> ")))
            return (0, [])
        state[key] = "active"
        best, best_path = 0, []
        for (tu, callee) in g.edges.get(key, []):
            if callee == "__indirect_call":
                errors.append("%s: indirect call (stack not bounded)" % key[1])
                continue
            kind, ck = g.resolve(tu, callee)
            if kind == "lib":
                b, p = worst(ck, stack + [key])
            else:
                b, p = ext_worst(ck), [ck + "*"]
            if b > best:
                best, best_path = b, p
        state[key] = "done"
        memo[key] = (g.frames[key] + best, [short(key[1])] + best_path)
        return memo[key]

    results = {}
    for name in sorted(public_functions(archive)):
        if name not in g.globals:
            errors.append("%s: no call-graph node (not compiled with -fcallgraph-info?)" % name)
            continue
        results[name] = worst(g.globals[name], [])
    # also walk every function so recursion among internal helpers is seen
    for key in list(g.frames):
        worst(key, [])
    return results, sorted(set(errors))


def main(argv):
    if len(argv) < 4:
        print("usage: dh_stack.py <objdir> <libdhmath.a> <limit bytes> -- <cflags...>")
        return 2
    objdir, archive, limit = argv[1], argv[2], int(argv[3])
    cflags = argv[5:] if len(argv) > 4 and argv[4] == "--" else []
    results, errors = analyse(objdir, archive, cflags)
    bad = 0
    for name, (b, path) in sorted(results.items(), key=lambda kv: -kv[1][0]):
        flag = "" if b <= limit else "  OVER LIMIT"
        if b > limit:
            bad += 1
        print("%6d  %-40s %s%s" % (b, name, " > ".join(path[1:]) or "-", flag))
    for e in errors:
        print("ERROR: " + e)
    print("(* = libgcc/libm/libc function, frames from its disassembly)")
    return 1 if bad or errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
