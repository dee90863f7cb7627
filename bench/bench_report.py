#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Turns one tools/bench.sh run into docs/generated/performance_host.md.

Inputs: the timing CSV of bench_host (--csv), the callgrind_annotate
--inclusive=yes output of `bench_host --count N`, N, and the build directory
(for the compile flags). Writes the markdown table of ns/op, instructions/op
and ratios, and checks the speed goals (docs/performance.md) with the numbers of this run.
"""
import argparse
import csv
import datetime
import os
import platform
import re
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

PKGS = ["gcc", "g++", "libc6", "libcglm-dev", "libeigen3-dev", "liborocos-kdl-dev",
        "libfixmath-dev", "valgrind", "cmake"]

# group -> dhmath row that peers in the group are compared with
PRIMARY = {"sincos_f32": "dh_sincos_f32", "sincos_loop": "dh_sincos_f32_loop", "sincos_q": "dh_sincos_q", "compose": "dh_mul_affine",
           "mul4": "dh_mul", "inv_rigid": "dh_inv_rigid", "inv_general": "dh_inv",
           "fk_puma": "dh_fk_f32", "ikc_kr6": "dh_ikc_kr6"}

# (title, dhmath id, peer id, kind, target, peer figure given with the goal)
#  kind "speedup": peer_time / dh_time must be >= target
#  kind "ratio":   dh_time / peer_time must be <= target
GOALS = [
    ("float sincos from degrees vs glibc sinf+cosf", "dh_sincos_f32", "glibc_sinf_cosf", "speedup", 2.0,
     "10.9 ns, 63 instr"),
    ("float sincos from degrees vs glibc sinf+cosf, tight loop of 64 independent calls", "dh_sincos_f32_loop",
     "glibc_sinf_cosf_loop", "speedup", 2.0, "-"),
    ("fixed sincos vs libfixmath fix16_sin+fix16_cos", "dh_sincos_q", "fix16_sin_cos", "speedup", 5.0,
     "72 ns, 679 instr"),
    ("affine/rigid compose vs cglm glm_mul", "dh_mul_affine", "glm_mul", "ratio", 1.2, "2.9 ns, 56 instr"),
    ("rigid inverse vs cglm glm_inv_tr", "dh_inv_rigid", "glm_inv_tr", "ratio", 1.2, "1.9 ns"),
    ("general inverse vs cglm glm_mat4_inv", "dh_inv", "glm_mat4_inv", "ratio", 1.2, "6.4 ns"),
    ("Puma 560 FK (float) vs KDL JntToCart", "dh_fk_f32", "kdl_fk", "ratio", 0.25, "233 ns, 3298 instr"),
    ("Puma 560 FK (float) vs plain double DH FK", "dh_fk_f32", "ref_fk_double", "ratio", 0.5, "131 ns"),
]


def sh(cmd):
    try:
        return subprocess.run(cmd, shell=True, check=True, capture_output=True, text=True).stdout.strip()
    except subprocess.CalledProcessError:
        return ""


def read_times(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def read_callgrind(path, count):
    ir = {}
    pat = re.compile(r"^\s*([\d,]+)\s.*?:(bw_\w+)\b")
    with open(path) as f:
        for line in f:
            m = pat.match(line)
            if m:
                ir[m.group(2)[3:]] = int(m.group(1).replace(",", "")) / count
    return ir


def flags_of(build):
    out = []
    for lang, key in (("C", "CMAKE_C_FLAGS"), ("CXX", "CMAKE_CXX_FLAGS")):
        fl = ""
        rel = ""
        try:
            with open(os.path.join(build, "CMakeCache.txt")) as f:
                for line in f:
                    if line.startswith(key + ":"):
                        fl = line.split("=", 1)[1].strip()
                    if line.startswith(key + "_RELEASE:"):
                        rel = line.split("=", 1)[1].strip()
        except OSError:
            pass
        out.append((lang, (fl + " " + rel).strip()))
    return out


def opw_version(d):
    """Version of the opw_kinematics clone: its package.xml and git commit."""
    if not d:
        return "not given (OPW_DIR unset: rows skipped)"
    v = "?"
    try:
        with open(os.path.join(d, "package.xml")) as f:
            m = re.search(r"<version>([^<]+)</version>", f.read())
            if m:
                v = m.group(1)
    except OSError:
        pass
    c = sh("git -C '%s' describe --tags --always 2>/dev/null" % d) if os.path.exists(os.path.join(d, ".git")) else ""
    return "%s (package.xml)%s" % (v, ", git " + c if c else "")


def fmt(x, nd=2):
    return "-" if x is None else ("%.*f" % (nd, x))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--times", required=True)
    ap.add_argument("--callgrind", required=True)
    ap.add_argument("--count", type=int, required=True)
    ap.add_argument("--build", required=True)
    ap.add_argument("--stdout", required=True, help="bench_host's own output (sanity and skip lines)")
    ap.add_argument("--load", default="", help="load average before/after the run")
    ap.add_argument("--opw", default="", help="the opw_kinematics clone the bench was built with (OPW_DIR)")
    ap.add_argument("--out", required=True)
    args = ap.parse_args()

    rows = read_times(args.times)
    ir = read_callgrind(args.callgrind, args.count)
    t = {r["id"]: r for r in rows}
    net = {k: float(r["net_ns"]) for k, r in t.items()}
    mn = {k: float(r["min_ns"]) for k, r in t.items()}
    med = {k: float(r["median_ns"]) for k, r in t.items()}
    reps = rows[0]["reps"] if rows else "?"
    with open(args.stdout) as f:
        bench_out = f.read()
    notes = [ln for ln in bench_out.splitlines() if ln.startswith("sanity:") or ln.startswith("skipped:")]

    cpu = sh("grep -m1 'model name' /proc/cpuinfo | cut -d: -f2").strip()
    L = []
    a = L.append
    a("# Host performance")
    a("")
    a("Generated by `tools/bench.sh` on %s, commit %s. Regenerate with:"
      % (datetime.date.today().isoformat(), sh("git -C %s rev-parse --short HEAD" % os.path.dirname(args.out)) or "?"))
    a("")
    a("```")
    a("tools/bench.sh            # REPS=31 COUNT=10000 BUILD=build-bench-host by default")
    a("```")
    a("")
    a("It configures `%s` with `-DDH_BUILD_BENCH=ON -DCMAKE_BUILD_TYPE=Release`,"
      % os.path.relpath(args.build, ROOT))
    a("builds `bench_host`, times every operation, runs `bench_host --count N` under")
    a("`valgrind --tool=callgrind` and writes this file (bench/bench_report.py).")
    a("")
    a("## Machine, compiler, packages")
    a("")
    a("* CPU: %s, %s cores; %s" % (cpu or platform.processor(), os.cpu_count(), platform.platform()))
    a("* load average before / after the timing run: %s (the host is shared with other" % (args.load or "?"))
    a("  builds; times are CPU time of the benchmark thread, which excludes time spent")
    a("  preempted but not cache or core sharing: read the instruction counts as the")
    a("  deterministic measure and the times as indicative)")
    for lang, fl in flags_of(args.build):
        a("* %s flags: `%s` (no `-march`: x86-64 baseline, SSE2; cglm and Eigen use SSE2)" % (lang, fl))
    a("* dhmath itself is additionally compiled with `-std=c99 -pedantic -Wall -Wextra -Wconversion"
      " -Wshadow -Wundef -Werror -ffunction-sections -fdata-sections` (its normal flags)")
    a("* %s" % (sh("cc --version | head -1") or "cc ?"))
    dirty = sh("git -C %s status --porcelain --untracked-files=no -- src include | wc -l" % ROOT)
    a("* library sources: commit above%s" % (
        "" if dirty in ("", "0") else
        " plus %s uncommitted modified file(s) in src/ include/ of other engineers' work in progress" % dirty))
    a("")
    a("| package | version |")
    a("|---|---|")
    for p in PKGS:
        v = sh("dpkg-query -W -f='${Version}' %s 2>/dev/null" % p)
        a("| %s | %s |" % (p, v or "not installed"))
    a("| opw_kinematics (no Debian package; the user's clone) | %s |" % opw_version(args.opw))
    a("")
    a("## Method")
    a("")
    a("* Every operation is one non-inlined wrapper `bw_<id>(i)` (bench/bench_host.c,")
    a("  bench/bench_peers.cpp) called through a function pointer; it reads input set")
    a("  i (cycling through random sets: 16384 angles in +-720 degrees, 4096 Puma 560")
    a("  configurations within the joint limits: too many for a branch predictor to")
    a("  learn the sequence; 256 random rigid transforms, whose operations have no")
    a("  data-dependent branches), performs exactly one operation,")
    a("  writes the result to a global array and one value to a volatile sink.")
    a("  Header-only peers (cglm, Eigen) are inlined into their wrapper; compiled")
    a("  libraries (dhmath, glibc, libfixmath, KDL) are called from it.")
    a("* Time: CPU time of the thread (CLOCK_THREAD_CPUTIME_ID) over about 2 ms per")
    a("  sample, %s repetitions interleaved across operations, median (and minimum)." % reps)
    a("  `net` subtracts the median of the `empty` wrapper (the harness alone).")
    a("* Instructions: `valgrind --tool=callgrind bench_host --count %d` runs every" % args.count)
    a("  wrapper exactly %d times; Ir/op is the inclusive count of `bw_<id>`" % args.count)
    a("  (callgrind_annotate --inclusive=yes) divided by %d. It includes the wrapper's" % args.count)
    a("  own %s instructions (the `empty` row)." % fmt(ir.get("empty"), 0))
    a("* The libfixmath input is the angle already in fix16 radians (converted in")
    a("  double, untimed: the most favourable case for the peer); glibc gets")
    a("  `deg * (float)(pi/180)` computed in the wrapper, as a caller with degrees")
    a("  would. KDL works in double, the others in float.")
    a("* Ratio: dhmath time / peer time within a group (below 1: dhmath faster).")
    a("* Closed-form IK against opw_kinematics (group `ikc_kr6`): the KUKA KR6 R700 sixx of")
    a("  opw's own example (`makeKukaKR6_R700_sixx`, include/opw_kinematics/opw_parameters_examples.h)")
    a("  as a standard-DH table with the same base and flange frames (bench/bench_host.c), 256")
    a("  targets = FK of random configurations within +-170 deg on every joint (seeded). dhmath")
    a("  returns the solutions within those limits with q_ref = (0, -90, 90, 0, 0, 0) deg;")
    a("  opw_kinematics::inverse returns its 8 raw solutions (NaN where none) and applies no")
    a("  limits. The sanity lines compare the solution sets on every target: opw's finite")
    a("  solutions mapped to the DH joint values (q_dh = (-1, 1, 1, -1, 1, -1) * q_opw, in")
    a("  degrees), wrapped to (-180, 180] and kept within the limits, against dhmath's: the")
    a("  count, and each matched by a dhmath solution within 1e-3 deg on every joint.")
    if not args.opw:
        a("  This run had no opw_kinematics: `git clone --branch 0.5.5")
        a("  https://github.com/Jmeyer1292/opw_kinematics /path/to/opw` and run")
        a("  `OPW_DIR=/path/to/opw tools/bench.sh` for its rows.")
    a("")
    for n in notes:
        a("`%s`" % n)
        a("")
    a("## Results")
    a("")
    a("| op | group | lib | median ns | min ns | net ns | Ir/op | dhmath / this (net) | dhmath / this (Ir) |")
    a("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        k = r["id"]
        p = PRIMARY.get(r["group"])
        rt = ri = "-"
        if p and p != k and p in net and net[k] > 0:
            rt = "%.2f" % (net[p] / net[k])
            if p in ir and k in ir:
                ri = "%.2f" % (ir[p] / ir[k])
        a("| %s | %s | %s | %s | %s | %s | %s | %s | %s |"
          % (k, r["group"], r["lib"], fmt(med[k]), fmt(float(r["min_ns"])), fmt(net[k]),
             fmt(ir.get(k), 1), rt, ri))
    a("")
    a("Descriptions:")
    a("")
    for r in rows:
        a("* `%s`: %s" % (r["id"], r["desc"]))
    a("")
    a("## Speed goals (this run)")
    a("")
    a("Verdict on the median net times; the ratio of the minimum times (less")
    a("affected by other load on the host) and of the instruction counts are")
    a("given next to it.")
    a("")
    a("| goal | target | dhmath net ns / Ir | peer net ns / Ir | measured (median net) | measured (min) | measured (Ir) | met? | peer figure given with the goal |")
    a("|---|---|---|---|---|---|---|---|---|")
    verdict = {}
    for title, d, p, kind, target, author in GOALS:
        if d not in net or p not in net:
            a("| %s | - | - | peer missing | - | - | - | not measured | %s |" % (title, author))
            continue
        if kind == "speedup":
            mt = net[p] / net[d]
            mi = ir[p] / ir[d] if d in ir and p in ir else None
            ok = mt >= target
            tg = ">= %.1fx faster" % target
            ms = "%.2fx faster" % mt
            mm = "%.2fx faster" % (mn[p] / mn[d])
            mis = "-" if mi is None else "peer/dhmath %.2f" % mi
        else:
            mt = net[d] / net[p]
            mi = ir[d] / ir[p] if d in ir and p in ir else None
            ok = mt <= target
            tg = "<= %.2fx" % target
            ms = "%.2fx" % mt
            mm = "%.2fx" % (mn[d] / mn[p])
            mis = "-" if mi is None else "%.2fx" % mi
        verdict[(d, p)] = ok
        a("| %s | %s | %s / %s | %s / %s | %s | %s | %s | %s | %s |"
          % (title, tg, fmt(net[d]), fmt(ir.get(d), 0), fmt(net[p]), fmt(ir.get(p), 0), ms, mm, mis,
             "yes" if ok else "**no**", author))
    a("")
    with open(args.out, "w") as f:
        f.write("\n".join(L))
    extra = os.path.join(os.path.dirname(os.path.abspath(__file__)), "performance_notes.md")
    if os.path.exists(extra):
        with open(args.out, "a") as f, open(extra) as g:
            f.write("\n" + g.read())
    print("wrote", args.out)


if __name__ == "__main__":
    main()
