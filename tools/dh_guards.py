#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Symbol and section guards on a cross-compiled libdhmath.a (driven by
tools/check_guards.sh, which also runs the stack guard tools/dh_stack.py).

  dh_guards.py <libdhmath.a> <soft|vfp>

soft: the library was built without an FPU, so every float/double operation
      is a call to a libgcc helper and shows up as an undefined symbol;
vfp:  hard-float build: the fixed-point objects are also disassembled and
      must contain no VFP instruction.

Checks (exit status 1 if any fails):
  1. no object has .data/.bss (or small-data) sections with non-zero size,
     or data/bss/common symbols: no mutable globals;
  2. no object references the heap, stdio, exit/abort or assert;
  3. fixed-point objects (*_q.c.obj) reference only integer helpers (an
     allow-list) and no *_f32 function: no float, no libm, no 64-bit
     division.
"""
import re
import subprocess
import sys
import tempfile
import os

NM = "arm-none-eabi-nm"
OBJDUMP = "arm-none-eabi-objdump"

FORBID_ALL = re.compile(
    r"^(malloc|calloc|realloc|free|_malloc_r|_calloc_r|_realloc_r|_free_r|aligned_alloc|"
    r"posix_memalign|memalign|printf|fprintf|sprintf|snprintf|vprintf|vfprintf|vsprintf|"
    r"vsnprintf|iprintf|siprintf|puts|fputs|putchar|fputc|fwrite|perror|exit|_exit|abort|"
    r"atexit|__assert_func|__assert|_impure_ptr|__errno|stdout|stderr)$")

# Allowed undefined references of fixed-point objects: integer libgcc
# helpers (32-bit division is fine: the rule is no 64-bit division), mem*
# and other dh_ functions/tables that are not float.
ALLOW_Q = re.compile(
    r"^(memcpy|memset|memmove|memcmp|"
    r"__aeabi_mem(cpy|cpy4|cpy8|set|set4|set8|clr|clr4|clr8|move|move4|move8)|"
    r"__aeabi_lmul|__aeabi_llsl|__aeabi_llsr|__aeabi_lasr|__aeabi_lcmp|__aeabi_ulcmp|"
    r"__aeabi_idiv|__aeabi_uidiv|__aeabi_idivmod|__aeabi_uidivmod|"
    r"__muldi3|__ashldi3|__ashrdi3|__lshrdi3|__cmpdi2|__ucmpdi2|"
    r"__clzsi2|__clzdi2|__ctzsi2|__ctzdi2|__popcountsi2|"
    r"__gnu_thumb1_case_(sqi|uqi|shi|uhi|si)|"
    r"dh_[A-Za-z0-9_]+)$")
FLOATY_DH = re.compile(r"_f32($|_)|_f64($|_)|float|double")


def run(args):
    return subprocess.run(args, check=True, capture_output=True, text=True).stdout


def members(lib):
    return [m for m in run(["arm-none-eabi-ar", "t", lib]).split() if m.endswith(".obj") or m.endswith(".o")]


def undefined(lib):
    """object -> [undefined symbols]"""
    res = {}
    cur = None
    for line in run([NM, "-u", lib]).splitlines():
        if line.endswith(":") and not line.startswith(" "):
            cur = line[:-1]
            res.setdefault(cur, [])
            continue
        parts = line.split()
        if cur and len(parts) == 2 and parts[0] == "U":
            res[cur].append(parts[1])
    return res


def main(argv):
    if len(argv) != 3 or argv[2] not in ("soft", "vfp"):
        print(__doc__)
        return 2
    lib, mode = argv[1], argv[2]
    errors = []
    objs = members(lib)

    # 1. mutable globals
    cur = None
    for line in run([OBJDUMP, "-h", lib]).splitlines():
        m = re.match(r"^(\S+):\s+file format", line)
        if m:
            cur = m.group(1)
            continue
        p = line.split()
        if len(p) >= 3 and p[0].isdigit() and re.match(r"^\.(s?data|s?bss|tbss|tdata)", p[1]):
            if int(p[2], 16) > 0:
                errors.append("%s: section %s has %d bytes (mutable data)" % (cur, p[1], int(p[2], 16)))
    cur = None
    for line in run([NM, lib]).splitlines():
        if line.endswith(":"):
            cur = line[:-1]
            continue
        p = line.split()
        if len(p) >= 2 and p[-2] in ("d", "D", "b", "B", "C", "S", "s", "G", "g"):
            errors.append("%s: data symbol %s (type %s)" % (cur, p[-1], p[-2]))
    if not any("mutable" in e or "data symbol" in e for e in errors):
        print("ok: no .data/.bss/COMMON in any of the %d objects" % len(objs))

    # 2. heap / stdio / exit
    und = undefined(lib)
    n_before = len(errors)
    for obj, syms in sorted(und.items()):
        for s in syms:
            if FORBID_ALL.match(s):
                errors.append("%s references %s" % (obj, s))
    if len(errors) == n_before:
        print("ok: no heap, stdio, errno, exit/abort/assert references")

    # 3. fixed-point objects
    qobjs = sorted(o for o in objs if re.search(r"_q\.c\.(obj|o)$", o))
    n_before = len(errors)
    if not qobjs:
        errors.append("no fixed-point objects (*_q.c.obj) in %s" % lib)
    for q in qobjs:
        for s in und.get(q, []):
            if not ALLOW_Q.match(s) or FLOATY_DH.search(s):
                errors.append("%s (fixed point) references %s" % (q, s))
    if mode == "vfp" and qobjs:
        with tempfile.TemporaryDirectory() as tmp:
            subprocess.run(["arm-none-eabi-ar", "x", os.path.abspath(lib)] + qobjs, cwd=tmp, check=True)
            for q in qobjs:
                vfp = {}
                for line in run([OBJDUMP, "-d", "--no-show-raw-insn", os.path.join(tmp, q)]).splitlines():
                    f = line.split("\t")
                    if len(f) >= 2 and re.match(r"^\s*[0-9a-f]+:$", f[0]) and f[1].startswith("v"):
                        mn = f[1].split()[0]
                        vfp[mn] = vfp.get(mn, 0) + 1
                if vfp:
                    errors.append("%s (fixed point) contains VFP instructions: %s" % (
                        q, ", ".join("%s x%d" % kv for kv in sorted(vfp.items()))))
    if len(errors) == n_before:
        print("ok: integer-only fixed-point objects (no float, libm, 64-bit division%s): %s" % (
            ", no VFP instruction" if mode == "vfp" else "",
            " ".join(re.sub(r"\.c\.(obj|o)$", "", q) for q in qobjs)))

    for e in errors:
        print("GUARD FAILED: " + e)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
