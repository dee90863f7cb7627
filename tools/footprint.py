#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Writes docs/generated/footprint.md: flash and stack of dhmath on Cortex-M0+ and
Cortex-M4F at -Os and -O2 (driven by tools/footprint.sh, which builds the
libraries).

  footprint.py <out.md> [--src=DIR] [--desc=TEXT] [--cmd=TEXT] <label>=<builddir>=<cflags> ...
  footprint.py --budget <builddir> <cflags>

  --budget: links only the size-goal core (profile (k)) against the
          library in <builddir> (built for Cortex-M4F -Os DH_SMALL) and
          exits 1 when its flash exceeds the budget (tools/check_guards.sh);

  --src:  source tree the libraries were built from (its include/ is used
          to list the public functions; default: this script's tree);
  --desc: what was measured (commit, working tree), for the report;
  --cmd:  the command that regenerates the report, for the report.

For every configuration (a library-only build with -fstack-usage
-fcallgraph-info=su):
  * own:    bytes of the function's own code (its .text.<name> section);
  * linked: bytes of flash (text + rodata + initialised data) of a firmware
            that calls only this function: linked with --gc-sections and the
            function as entry point, so it includes every library helper,
            table, libgcc soft-float routine and libm function it pulls in
            (newlib-nano's libc for errno, as a small firmware would use);
  * stack:  worst case including callees (tools/dh_stack.py);
  * modules: text + rodata of every object of libdhmath.a;
  * tables: every read-only data object of the library.

Firmware profiles (the size goal of docs/design.md: the whole float + fixed
core fits in <= 8 KiB of flash on Cortex-M4F at -Os, tables included): for each profile
a C file with a table of pointers to its entry points is generated from the
public headers (gcc -aux-info lists every function they declare, so the
profiles follow the headers), compiled with the configuration's flags and
linked like the per-function firmwares (--gc-sections, newlib-nano libc,
libm, libgcc) with a map file; the map attributes every byte of flash
(text + rodata + initialised data) to dhmath, libgcc or libm+libc. The
generated table and its accessor are not counted.
"""
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dh_stack  # noqa: E402

NM = "arm-none-eabi-nm"
CC = "arm-none-eabi-gcc"


def run(args, **kw):
    return subprocess.run(args, check=True, capture_output=True, text=True, **kw).stdout


def own_sizes(lib):
    """global function -> bytes of its code; object -> module sizes."""
    funcs = {}
    for line in run([NM, "-S", "--defined-only", "-g", lib]).splitlines():
        p = line.split()
        if len(p) == 4 and p[2] in ("T", "t"):
            funcs[p[3]] = int(p[1], 16)
    return funcs


def module_sizes(lib):
    """object -> (text bytes, rodata bytes)"""
    res = {}
    cur = None
    for line in run(["arm-none-eabi-size", "-A", "-d", lib]).splitlines():
        m = re.match(r"^(\S+)\s+\(ex .*\):$", line)
        if m:
            cur = m.group(1)
            res[cur] = [0, 0]
            continue
        p = line.split()
        if cur and len(p) >= 2 and p[1].isdigit():
            if p[0].startswith(".text"):
                res[cur][0] += int(p[1])
            elif p[0].startswith(".rodata"):
                res[cur][1] += int(p[1])
    return res


def tables(lib):
    """(object, symbol, bytes) of read-only data objects."""
    res = []
    cur = None
    for line in run([NM, "-S", "--defined-only", lib]).splitlines():
        if line.endswith(":"):
            cur = line[:-1]
            continue
        p = line.split()
        if len(p) == 4 and p[2] in ("r", "R"):
            res.append((cur, p[3], int(p[1], 16)))
    return res


def linked_size(lib, func, cflags, tmp):
    elf = os.path.join(tmp, "fp.elf")
    # an (empty) object compiled with the same flags first, so the output
    # gets the right build attributes (hard-float ABI) before libm is merged
    anchor = os.path.join(tmp, "anchor_%d.o" % (hash(tuple(cflags)) & 0xffffff))
    if not os.path.exists(anchor):
        src = os.path.join(tmp, "anchor.c")
        with open(src, "w") as f:
            f.write("float dh_footprint_anchor(float x);\nfloat dh_footprint_anchor(float x) { return x; }\n")
        subprocess.run([CC] + cflags + ["-c", src, "-o", anchor], check=True)
    subprocess.run([CC] + cflags + ["-nostartfiles", "-nostdlib", "-Wl,--gc-sections",
                                    "-Wl,-e," + func, "-Wl,-u," + func, anchor, lib,
                                    "-lm", "-lc_nano", "-lgcc", "-o", elf],
                   check=True, capture_output=True, text=True)
    total = 0
    for line in run(["arm-none-eabi-size", "-A", "-d", elf]).splitlines():
        p = line.split()
        if len(p) >= 3 and p[1].isdigit() and re.match(
                r"^\.(text|rodata|data|ARM\.exidx|ARM\.extab|init_array|fini_array)", p[0]):
            total += int(p[1])
    return total


# ---- firmware profiles ------------------------------------------------------

INCLUDE_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "include")
FLASH_OUT_RE = re.compile(r"^\.(text|rodata|data|ARM\.exidx|ARM\.extab|init_array|fini_array|init|fini)\b")
AUX_RE = re.compile(r"^/\* (\S+):(\d+):(\w+) \*/ (.*)$")
CORE_LIMIT = 8192
ISSUE5_CONFIG = "M4F -Os DH_SMALL"
ISSUE5_DEFAULT = "M4F -Os"
# headers that hold the size-goal core, and more (profile (a))
CORE_HEADERS = ("trig.h", "mat4.h", "frame.h", "robot.h")
# The size-goal core, function by function: "trig, transforms, inverses, DH
# FK, no IK", each in float and fixed point. Transforms: every constructor
# of Paul 1981's transforms (translation, rotation about x/y/z and about any
# axis, scaling, perspective), composition, and application to points,
# directions, homogeneous points and planes. Inverses: rigid, general, the
# automatic choice, fixed-point rigid. DH FK: the robot description with
# base and tool, link matrices, FK to the end and to every frame. Left out
# (they are in (a)): angle-axis extraction (a topic of its own), validation
# and repair helpers (rotation/rigidity checks, re-orthonormalisation),
# conversions between float and fixed frames, joint limits (used by IK).
CORE_FUNCS = (
    # trig
    "dh_sincos_f32", "dh_sin_f32", "dh_cos_f32", "dh_sincos_q", "dh_sin_q", "dh_cos_q",
    # float transforms
    "dh_mat4_identity_f32", "dh_mat4_trans_f32", "dh_mat4_rotx_f32", "dh_mat4_roty_f32",
    "dh_mat4_rotz_f32", "dh_mat4_rot_axis_f32", "dh_mat4_scale_f32", "dh_mat4_persp_f32",
    "dh_mat4_mul_f32", "dh_mat4_mul_affine_f32", "dh_mat4_premul_f32", "dh_mat4_postmul_f32",
    "dh_mat4_apply_point_f32", "dh_mat4_apply_dir_f32", "dh_mat4_apply_point_h_f32",
    "dh_mat4_apply_plane_f32",
    # fixed-point transforms
    "dh_frame_identity_q", "dh_frame_trans_q", "dh_frame_rotx_q", "dh_frame_roty_q",
    "dh_frame_rotz_q", "dh_frame_rot_axis_q", "dh_frame_mul_q", "dh_frame_apply_point_q",
    "dh_frame_apply_dir_q",
    # inverses
    "dh_mat4_inv_rigid_f32", "dh_mat4_inv_f32", "dh_frame_inv_q",
    # DH forward kinematics
    "dh_robot_init", "dh_robot_add_joint_f32", "dh_robot_add_joint_q",
    "dh_robot_set_base_f32", "dh_robot_set_tool_f32", "dh_robot_set_base_q",
    "dh_robot_set_tool_q", "dh_link_f32", "dh_fk_f32", "dh_fk_frames_f32",
    "dh_link_q", "dh_fk_q", "dh_fk_frames_q",
)


def header_functions(cflags, tmp):
    """header basename -> functions it declares (in header order), from
    gcc -aux-info on a file that includes the umbrella header."""
    src = os.path.join(tmp, "aux.c")
    aux = os.path.join(tmp, "aux.txt")
    with open(src, "w") as f:
        f.write('#include "dhmath/dhmath.h"\n')
    subprocess.run([CC] + cflags + ["-std=c99", "-I", INCLUDE_DIR, "-fsyntax-only",
                                    "-aux-info", aux, src], check=True)
    res = {}
    seen = set()
    with open(aux) as f:
        for line in f:
            m = AUX_RE.match(line.strip())
            if not m or "/include/dhmath/" not in m.group(1).replace(os.sep, "/"):
                continue
            # C = declaration (prototype); definitions would be inline functions
            decl = m.group(4)
            if not m.group(3).endswith("C") or not decl.startswith("extern"):
                continue
            n = re.search(r"\b(dh_\w+)\s*\(", decl)
            if n and n.group(1) not in seen:
                seen.add(n.group(1))
                res.setdefault(os.path.basename(m.group(1)), []).append(n.group(1))
    return res


def profile_defs(decl):
    """[(key, title, [functions])] of the firmware profiles."""
    allf = [f for h in sorted(decl) for f in decl[h]]
    core = [f for h in CORE_HEADERS for f in decl.get(h, [])]
    robot = decl.get("robot.h", [])
    setup_f = [f for f in robot if f == "dh_robot_init" or (f.startswith("dh_robot_") and f.endswith("_f32"))]
    setup_q = [f for f in robot if f == "dh_robot_init" or (f.startswith("dh_robot_") and f.endswith("_q"))]
    fk_f = setup_f + ["dh_fk_f32", "dh_mat4_inv_rigid_f32", "dh_mat4_mul_affine_f32",
                      "dh_mat4_apply_point_f32"]
    fk_q = setup_q + ["dh_fk_q", "dh_frame_inv_q", "dh_frame_mul_q", "dh_frame_apply_point_q"]
    declared = set(allf)
    return [
        ("k", "(k) size-goal core: trig, transforms, inverses, DH FK, float and fixed",
         [f for f in CORE_FUNCS if f in declared]),
        ("a", "(a) every function of %s" % ", ".join(CORE_HEADERS), core),
        ("b", "(b) float FK firmware", fk_f),
        ("c", "(c) fixed FK firmware", fk_q),
        ("bc", "(b+c) float + fixed FK firmware: the functions of (b) and (c) together",
         fk_f + [f for f in fk_q if f not in fk_f]),
        ("d", "(d) trig only: every function of trig.h", list(decl.get("trig.h", []))),
        ("e", "(e) everything: every function of every public header", allf),
    ]


# what (a) costs without some of its parts: measured by linking (a) minus a
# set of public functions (key, title, predicate on the function name)
CORE_VARIANTS = [
    ("k-float", "(k) float only: without every `_q` function",
     lambda f: f.endswith("_q")),
    ("k-fixed", "(k) fixed only: without every `_f32` function",
     lambda f: f.endswith("_f32")),
    ("k-noinv", "(k) without general inverse: without `dh_mat4_inv_f32` and "
     "`dh_mat4_apply_plane_f32` (the functions that reach the general 4x4 inverse)",
     lambda f: f in ("dh_mat4_inv_f32", "dh_mat4_inv_auto_f32", "dh_mat4_apply_plane_f32")),
]


def map_sections(path):
    """(output section, input section, bytes, origin) of every allocated
    input section and fill of a GNU ld map file."""
    res = []
    out = None
    pending = None
    started = False
    with open(path) as f:
        for line in f:
            line = line.rstrip("\n")
            if not started:
                started = line.startswith("Linker script and memory map")
                continue
            if line and not line[0].isspace():
                out = line.split()[0]
                pending = None
                continue
            m = re.match(r"^ (\S+)(?:\s+0x([0-9a-fA-F]+)\s+0x([0-9a-fA-F]+)(?:\s+(.*))?)?$", line)
            if m and not m.group(1).startswith("*("):
                if m.group(2):
                    res.append((out, m.group(1), int(m.group(3), 16), (m.group(4) or "").strip()))
                    pending = None
                else:
                    pending = m.group(1)
                continue
            if pending:
                m = re.match(r"^\s+0x([0-9a-fA-F]+)\s+0x([0-9a-fA-F]+)\s+(.*)$", line)
                if m:
                    res.append((out, pending, int(m.group(2), 16), m.group(3).strip()))
            pending = None
    return res


def origin_kind(origin, name):
    """('dhmath', member) / ('libgcc', member) / ('libm+libc', member) /
    ('other', ...) for an input section of the map."""
    if name == "*fill*":
        return "other", "padding"
    m = re.search(r"([^/\\]+)\.a\(([^)]*)\)$", origin)
    if not m:
        return "other", os.path.basename(origin)
    lib, member = m.group(1), m.group(2)
    if lib == "libdhmath":
        return "dhmath", member
    if lib == "libgcc":
        return "libgcc", member
    if lib in ("libm", "libc", "libc_nano", "libg", "libg_nano"):
        return "libm+libc", "%s(%s)" % (lib, member)
    return "other", "%s(%s)" % (lib, member)


def section_func(name):
    """.text.dh_fk_q -> dh_fk_q; .rodata.tab -> tab (rodata)"""
    m = re.match(r"^\.(text|rodata|data)(?:\.unlikely|\.hot|\.startup)?\.(.+)$", name)
    if not m:
        return name
    return m.group(2) if m.group(1) == "text" else "%s (%s)" % (m.group(2), m.group(1))


def link_profile(lib, funcs, cflags, tmp, key):
    """Links a firmware that references `funcs`; returns the flash
    breakdown from its map file."""
    src = os.path.join(tmp, "prof_%s.c" % key)
    obj = src[:-2] + ".o"
    elf = src[:-2] + ".elf"
    mapf = src[:-2] + ".map"
    body = ["#include \"dhmath/dhmath.h\"",
            "/* generated by tools/footprint.py: entry points of a firmware profile */",
            "typedef void (*dh_fp_fn)(void);",
            "static const dh_fp_fn dh_fp_table[] = {"]
    body += ["    (dh_fp_fn)%s," % f for f in funcs] or ["    (dh_fp_fn)0,"]
    body += ["};",
             "const void *dh_fp_entry(void);",
             "const void *dh_fp_entry(void) { return dh_fp_table; }", ""]
    with open(src, "w") as f:
        f.write("\n".join(body))
    subprocess.run([CC] + cflags + ["-std=c99", "-I", INCLUDE_DIR, "-ffunction-sections",
                                    "-fdata-sections", "-c", src, "-o", obj], check=True)
    subprocess.run([CC] + cflags + ["-nostartfiles", "-nostdlib", "-Wl,--gc-sections",
                                    "-Wl,-e,dh_fp_entry", "-Wl,-Map," + mapf, obj, lib,
                                    "-lm", "-lc_nano", "-lgcc", "-o", elf],
                   check=True, capture_output=True, text=True)
    kinds = {"dhmath": 0, "libgcc": 0, "libm+libc": 0, "other": 0}
    rodata = 0
    members = {}
    funcs_sz = {}
    extern = {}
    mapped = 0
    for out, name, size, origin in map_sections(mapf):
        if not FLASH_OUT_RE.match(out) or size == 0:
            continue
        mapped += size
        kind, member = origin_kind(origin, name)
        kinds[kind] += size
        if kind == "dhmath":
            members[member] = members.get(member, 0) + size
            fkey = (member, section_func(name))
            funcs_sz[fkey] = funcs_sz.get(fkey, 0) + size
            if out.startswith(".rodata"):
                rodata += size
        elif kind in ("libgcc", "libm+libc"):
            extern[(kind, member)] = extern.get((kind, member), 0) + size
    # the map must account for every byte the ELF puts in flash
    total = 0
    for line in run(["arm-none-eabi-size", "-A", "-d", elf]).splitlines():
        p = line.split()
        if len(p) >= 3 and p[1].isdigit() and FLASH_OUT_RE.match(p[0]):
            total += int(p[1])
    if total != mapped:
        raise SystemExit("footprint: map of profile %s accounts for %d of %d flash bytes"
                         % (key, mapped, total))
    return dict(kinds=kinds, lib=kinds["dhmath"] + kinds["libgcc"] + kinds["libm+libc"],
                rodata=rodata, members=members, sections=funcs_sz, extern=extern)


def profiles_for(lib, flags, tmp, tag):
    """Links every profile and core variant of one configuration."""
    decl = header_functions(flags, tmp)
    defined = dh_stack.public_functions(lib)
    res = {}
    missing = set()
    defs = profile_defs(decl)
    core = next(p[2] for p in defs if p[0] == "k")
    for key, title, funcs in defs + [(k, t, [f for f in core if not pred(f)])
                                     for k, t, pred in CORE_VARIANTS]:
        have = [f for f in funcs if f in defined]
        missing.update(f for f in funcs if f not in defined)
        res[key] = dict(title=title, funcs=have, **link_profile(lib, have, flags, tmp, tag + key))
    return res, decl, sorted(missing)


def extern_name(x):
    """('libm+libc', 'libm(lib_a-sf_atan.o)') -> 'libm sf_atan'"""
    m = re.match(r"^(\w+)\((?:lib_a-)?(.*?)(?:\.o)?\)$", x[1])
    if m:
        return "%s %s" % (m.group(1), m.group(2))
    return "libgcc " + re.sub(r"\.o$", "", x[1])


def kib(n):
    return "%.2f KiB" % (n / 1024.0)


def profile_sections(data, labels):
    """Markdown of the size-goal summary (first) and the profile sections (second)."""
    P = {l: data[l]["profiles"] for l in labels}
    ref = ISSUE5_CONFIG if ISSUE5_CONFIG in P else labels[0]
    dflt = ISSUE5_DEFAULT if ISSUE5_DEFAULT in P else labels[0]
    k = P[ref]["k"]
    a = P[ref]["a"]
    decl = data[ref]["decl"]
    S = []
    S.append("## Size goal: flash of the float + fixed core")
    S.append("")
    S.append("Target (the size goal of docs/design.md, \"Size-first build\"): the whole float + fixed core (trig, transforms, "
             "inverses, DH FK, no IK) fits in **<= 8 KiB (%d bytes) of flash on "
             "Cortex-M4F at -Os, tables included**." % CORE_LIMIT)
    S.append("")
    S.append("The core is profile (k) below, %d public functions: sine/cosine; every "
             "constructor of Paul 1981's transforms (translation, rotation about x/y/z and any "
             "axis, scaling, perspective), composition, application to points, "
             "directions, homogeneous points and planes; the rigid, general and "
             "fixed-point inverses; the robot description with base and tool, link "
             "matrices and FK to the end and to every frame; each in float and in "
             "fixed point. It is measured with the library built for size: `-Os` and "
             "`DH_SMALL=1` (`include/dhmath/config.h`: the same contracts from loops "
             "and one general code path instead of unrolled code and fast paths; "
             "`docs/design.md`)." % len(k["funcs"]))
    S.append("")
    met = k["lib"] <= CORE_LIMIT
    S.append("Measured (%s): **%d bytes (%s)** = %d dhmath (of which %d read-only tables "
             "and constants) + %d libgcc + %d libm/libc. **Target %s**%s." % (
                 ref, k["lib"], kib(k["lib"]), k["kinds"]["dhmath"], k["rodata"],
                 k["kinds"]["libgcc"], k["kinds"]["libm+libc"], "met" if met else "NOT met",
                 (" (%d bytes to spare)" % (CORE_LIMIT - k["lib"])) if met else
                 " (%.2f times the target, %d bytes over)" % (
                     k["lib"] / float(CORE_LIMIT), k["lib"] - CORE_LIMIT)))
    S.append("")
    if dflt != ref:
        S.append("The same core from the default build (speed first, `DH_SMALL=0`) at "
                 "%s: %d bytes (%s). Every public function of the four core headers "
                 "(profile (a), %d functions, adding angle-axis extraction, checks, "
                 "re-orthonormalisation, float/fixed conversions and joint limits): "
                 "%d bytes with `DH_SMALL=1`, %d bytes without." % (
                     dflt, P[dflt]["k"]["lib"], kib(P[dflt]["k"]["lib"]), len(a["funcs"]),
                     a["lib"], P[dflt]["a"]["lib"]))
        S.append("")
    S.append("Smaller firmware (%s): float FK firmware (b) %d bytes, fixed FK firmware "
             "(c) %d bytes, both (b+c) %d bytes, trig only (d) %d bytes; the whole "
             "library (e, with IK and rotations) %d bytes." % (
                 ref, P[ref]["b"]["lib"], P[ref]["c"]["lib"], P[ref]["bc"]["lib"],
                 P[ref]["d"]["lib"], P[ref]["e"]["lib"]))
    S.append("")
    mods = sorted(k["members"].items(), key=lambda kv: -kv[1])
    S.append("Largest contributors to (k) on %s (bytes of flash each module adds; "
             "the full breakdown is in *Per-module breakdown of (k)*):" % ref)
    S.append("")
    for m, n in mods[:6]:
        S.append("* `%s`: %d bytes (%.0f %%)" % (module_name(m), n, 100.0 * n / k["lib"]))
    ext = k["kinds"]["libgcc"] + k["kinds"]["libm+libc"]
    if ext:
        S.append("* libgcc + libm/libc: %d bytes (%s)" % (ext, ", ".join(
            "%s %d" % (extern_name(x), n) for x, n in sorted(k["extern"].items(), key=lambda kv: -kv[1]))))
    S.append("")
    S.append("What the measured variants of (k) show (each linked like (k) without the "
             "named functions; the difference is what those functions and everything "
             "only they use cost):")
    S.append("")
    for vk, t, _ in CORE_VARIANTS:
        v = P[ref][vk]
        S.append("* %s: %d bytes (%s), %d less than (k)." % (
            t, v["lib"], kib(v["lib"]), k["lib"] - v["lib"]))
    S.append("")
    summary = S

    L = []
    L.append("## Firmware profiles")
    L.append("")
    L.append("Each profile is a firmware whose only references into the library are "
             "the listed public functions: `tools/footprint.py` generates a table of "
             "pointers to them (from the functions the public headers declare, via "
             "`gcc -aux-info`, so the profiles follow the headers), links it with "
             "`--gc-sections` against `libdhmath.a`, newlib-nano libc, libm and libgcc, "
             "and splits the flash (text + rodata + initialised data, from the map "
             "file) by origin. The generated table, its accessor and the linker's "
             "alignment padding (together 4 bytes per function plus a few) are not counted. "
             "A real firmware adds its own code, startup and vector table.")
    L.append("")
    for key, title, funcs in profile_defs(decl):
        got = P[ref][key]["funcs"]
        if key in ("k", "a", "bc", "d", "e"):
            L.append("* **%s** (%d functions)." % (title, len(got)))
        else:
            L.append("* **%s**: %s." % (title, ", ".join("`%s`" % f for f in got)))
    L.append("")
    L.append("In (a), not in (k): %s." % ", ".join(
        "`%s`" % f for f in P[ref]["a"]["funcs"] if f not in P[ref]["k"]["funcs"]))
    L.append("")
    L.append("Not in (a): `dh_status_str` (`common.h`; %d bytes linked alone on %s, "
             "see the per-function table), `kin.h` (Jacobian, IK) and `rot.h` "
             "(Euler angles, quaternions, rotation vectors)." % (
                 data[ref]["linked"].get("dh_status_str", 0), ref))
    missing = sorted(set(f for l in labels for f in data[l]["profile_missing"]))
    if missing:
        L.append("")
        L.append("Declared in a header but not defined in `libdhmath.a` (left out of the "
                 "profiles): %s." % ", ".join("`%s`" % f for f in missing))
    L.append("")
    L.append("Bytes of flash; *total* = dhmath + libgcc + libm/libc; *rodata* = the "
             "read-only data of dhmath (tables and constants), part of the dhmath figure.")
    L.append("")
    L.append("| profile | configuration | total | dhmath | rodata | libgcc | libm/libc |")
    L.append("|---|---|---:|---:|---:|---:|---:|")
    for key, title, _ in profile_defs(decl) + CORE_VARIANTS:
        for l in labels:
            v = P[l][key]
            L.append("| %s | %s | %s%d%s | %d | %d | %d | %d |" % (
                title.split(":")[0], l,
                "**" if key == "k" else "", v["lib"], "**" if key == "k" else "",
                v["kinds"]["dhmath"], v["rodata"], v["kinds"]["libgcc"], v["kinds"]["libm+libc"]))
    L.append("")
    L.append("## Per-module breakdown of (k)")
    L.append("")
    L.append("Bytes of flash each object contributes to the core firmware (k): only the "
             "functions and tables it links, unlike *Flash per module* below, which "
             "counts whole objects.")
    L.append("")
    L.append("| module |" + "".join(" %s |" % l for l in labels))
    L.append("|---|" + "---:|" * len(labels))
    allm = sorted(set(m for l in labels for m in P[l]["k"]["members"]),
                  key=lambda m: -P[ref]["k"]["members"].get(m, 0))
    for m in allm:
        L.append("| %s |" % module_name(m) + "".join(
            " %d |" % P[l]["k"]["members"].get(m, 0) for l in labels))
    for k in ("libgcc", "libm+libc"):
        L.append("| *%s* |" % k + "".join(" %d |" % P[l]["k"]["kinds"][k] for l in labels))
    L.append("| **total** |" + "".join(" **%d** |" % P[l]["k"]["lib"] for l in labels))
    L.append("")
    L.append("libgcc and libm/libc objects linked into (k):")
    L.append("")
    L.append("| library object |" + "".join(" %s |" % l for l in labels))
    L.append("|---|" + "---:|" * len(labels))
    allx = sorted(set(x for l in labels for x in P[l]["k"]["extern"]))
    for x in allx:
        L.append("| %s: %s |" % x + "".join(" %s |" % P[l]["k"]["extern"].get(x, "-") for l in labels))
    L.append("")
    L.append("## Largest functions of (k)")
    L.append("")
    L.append("Input sections of dhmath linked into (k) on %s, largest first (code "
             "includes its literal pool; `static` helpers included; `.constprop`/`.isra` "
             "are GCC's specialised copies), covering the largest modules." % ref)
    L.append("")
    L.append("| module | function or table | bytes |")
    L.append("|---|---|---:|")
    top = set(m for m, _ in mods[:4])
    for (m, fn), n in sorted(P[ref]["k"]["sections"].items(), key=lambda kv: (-kv[1], kv[0])):
        if m in top and n >= 64:
            L.append("| %s | `%s` | %d |" % (module_name(m), fn, n))
    L.append("")
    return summary, L


def module_name(obj):
    return re.sub(r"\.c\.(obj|o)$", "", obj)


def budget(bdir, flags):
    """Flash of profile (k) linked against bdir's library; 0 within the
    budget, 1 over it."""
    lib = os.path.join(bdir, "libdhmath.a")
    with tempfile.TemporaryDirectory() as tmp:
        defs = profile_defs(header_functions(flags, tmp))
        core = next(p[2] for p in defs if p[0] == "k")
        defined = dh_stack.public_functions(lib)
        missing = [f for f in core if f not in defined]
        if missing:
            print("footprint: core functions missing from %s: %s" % (lib, " ".join(missing)))
            return 1
        k = link_profile(lib, core, flags, tmp, "budget")
    print("%s: size-first core (%d functions) %d bytes of flash, budget %d" %
          ("ok" if k["lib"] <= CORE_LIMIT else "OVER BUDGET", len(core), k["lib"], CORE_LIMIT))
    return 0 if k["lib"] <= CORE_LIMIT else 1


def main(argv):
    if len(argv) == 4 and argv[1] == "--budget":
        return budget(argv[2], argv[3].split())
    if len(argv) < 3:
        print(__doc__)
        return 2
    global INCLUDE_DIR
    out = argv[1]
    configs = []
    desc = None
    cmd = "tools/footprint.sh"
    for spec in argv[2:]:
        if spec.startswith("--src="):
            INCLUDE_DIR = os.path.join(spec[6:], "include")
            continue
        if spec.startswith("--desc="):
            desc = spec[7:]
            continue
        if spec.startswith("--cmd="):
            cmd = spec[6:]
            continue
        label, bdir, flags = spec.split("=", 2)
        configs.append((label, bdir, flags.split()))

    data = {}
    allfuncs = set()
    with tempfile.TemporaryDirectory() as tmp:
        for label, bdir, flags in configs:
            lib = os.path.join(bdir, "libdhmath.a")
            pub = sorted(dh_stack.public_functions(lib))
            allfuncs.update(pub)
            own = own_sizes(lib)
            linked = {f: linked_size(lib, f, flags, tmp) for f in pub}
            stack, errors = dh_stack.analyse(os.path.join(bdir, "CMakeFiles", "dhmath.dir"), lib, flags)
            profiles, decl, missing = profiles_for(lib, flags, tmp, "%d_" % len(data))
            data[label] = dict(own=own, linked=linked, stack=stack, errors=errors,
                               modules=module_sizes(lib), tables=tables(lib), flags=flags,
                               profiles=profiles, decl=decl, profile_missing=missing)

    labels = [c[0] for c in configs]
    L = []
    L.append("# dhmath footprint on Cortex-M")
    L.append("")
    L.append("Generated by `%s` (do not edit by hand). Compiler: %s." %
             (cmd, run([CC, "--version"]).splitlines()[0]))
    if desc:
        L.append("")
        L.append("Measured source: %s." % desc)
    L.append("")
    for label, bdir, flags in configs:
        L.append("* **%s**: `%s`" % (label, " ".join(flags)))
    L.append("")
    L.append("Library configuration: the defaults of `include/dhmath/config.h` "
             "(DH_MAX_JOINTS 8, DH_QPOS_FRAC 16, DH_CHECK_ARGS 1, DH_USE_INTRINSICS 1, "
             "DH_SMALL 0), except `DH_SMALL=1` in the configurations named DH_SMALL.")
    L.append("")
    summary, prof = profile_sections(data, labels)
    L.extend(summary)
    L.extend(prof)
    L.append("## Flash per public function")
    L.append("")
    L.append("*own*: the function's own code. *linked*: flash of a firmware that "
             "calls only this function (`--gc-sections`, the function as entry): "
             "its code plus every library helper, table, libgcc soft-float "
             "routine and libm function it pulls in (newlib-nano libc for errno). "
             "This is what the function costs a firmware that uses nothing else "
             "of dhmath; functions used together share helpers and tables, so "
             "linked sizes do not add up.")
    L.append("")
    hdr = "| function |" + "".join(" %s own | %s linked |" % (l, l) for l in labels)
    L.append(hdr)
    L.append("|---|" + "---:|---:|" * len(labels))
    for f in sorted(allfuncs):
        row = "| `%s` |" % f
        for l in labels:
            d = data[l]
            row += " %s | %s |" % (d["own"].get(f, "-"), d["linked"].get(f, "-"))
        L.append(row)
    L.append("")
    L.append("## Worst-case stack per public function (bytes)")
    L.append("")
    L.append("Own frame plus the deepest chain of callees, libgcc/libm/libc included "
             "(frames of library code from GCC's `-fstack-usage`/`-fcallgraph-info`, "
             "of libgcc/libm/libc from their disassembly; `tools/dh_stack.py`). "
             "The project limit is 256 bytes (checked by `tools/check_guards.sh`); "
             "**bold** entries exceed it. The deepest chain is shown for the "
             "first configuration (`*` = libgcc/libm/libc function).")
    L.append("")
    L.append("| function |" + "".join(" %s |" % l for l in labels) + " deepest chain (%s) |" % labels[0])
    L.append("|---|" + "---:|" * len(labels) + "---|")
    for f in sorted(allfuncs):
        row = "| `%s` |" % f
        for l in labels:
            s = data[l]["stack"].get(f)
            if s is None:
                row += " - |"
            else:
                row += (" **%d** |" % s[0]) if s[0] > 256 else (" %d |" % s[0])
        s0 = data[labels[0]]["stack"].get(f)
        row += " %s |" % (" > ".join(s0[1][1:]) if s0 and len(s0[1]) > 1 else "-")
        L.append(row)
    errs = sorted(set(e for l in labels for e in data[l]["errors"]))
    if errs:
        L.append("")
        L.append("Stack analysis problems: " + "; ".join(errs))
    L.append("")
    L.append("## Flash per module (text + rodata of each object, bytes)")
    L.append("")
    L.append("Everything in a module, used or not; a firmware links only what it "
             "calls (`-ffunction-sections -fdata-sections` + `--gc-sections`).")
    L.append("")
    L.append("| module |" + "".join(" %s text | %s rodata |" % (l, l) for l in labels))
    L.append("|---|" + "---:|---:|" * len(labels))
    mods = sorted(set(m for l in labels for m in data[l]["modules"]))
    tot = {l: [0, 0] for l in labels}
    for m in mods:
        row = "| %s |" % module_name(m)
        for l in labels:
            t, r = data[l]["modules"].get(m, (0, 0))
            tot[l][0] += t
            tot[l][1] += r
            row += " %d | %d |" % (t, r)
        L.append(row)
    L.append("| **total** |" + "".join(" **%d** | **%d** |" % tuple(tot[l]) for l in labels))
    L.append("")
    L.append("## Tables (read-only data objects, bytes)")
    L.append("")
    L.append("Identical in every configuration (the sizes below are from %s)." % labels[0])
    L.append("")
    L.append("| module | object | bytes |")
    L.append("|---|---|---:|")
    tsum = 0
    for obj, sym, size in sorted(data[labels[0]]["tables"]):
        L.append("| %s | `%s` | %d |" % (module_name(obj), sym, size))
        tsum += size
    L.append("| | **total** | **%d** |" % tsum)
    L.append("")
    with open(out, "w") as f:
        f.write("\n".join(L))
    print("footprint: wrote %s (%d public functions, %d configurations)" % (out, len(allfuncs), len(labels)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
