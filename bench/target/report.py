#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""report.py - turn the logs of the on-target benchmark firmware
(bench/target/bench_target.c, run by tools/target_bench.sh) into
docs/generated/performance_target.md.

usage: report.py OUT.md META.txt LOG=ELF...

META.txt holds "key=value" lines written by tools/target_bench.sh
(versions, command lines). Each LOG is the semihosting output of one run;
its file name is <core>-<opt>.log; ELF is the firmware image that
produced it (its disassembly gives the size of the null twins). Exits non-zero if a log is incomplete,
a sanity check failed, the counter did not behave like QEMU's icount clock
or the firmware's stack came near its reserve.
"""
import os
import re
import subprocess
import sys
from fractions import Fraction

CORES = [("m0", "Cortex-M0 (microbit)"), ("m4f", "Cortex-M4F (mps2-an386)"),
         ("m7", "Cortex-M7 (mps2-an500)")]
OPTS = ["O2", "Os", "Os-small"]
OPT_LABEL = {"O2": "-O2", "Os": "-Os", "Os-small": "-Os DH_SMALL"}

# Speed goals with a fixed limit (docs/performance.md): (core key, op name, limit, label)
TARGETS = [
    ("m4f", "dh_fk_q (Puma 560, mm)", 1500, "6-joint Puma FK, fixed, Cortex-M4"),
    ("m4f", "dh_fk_f32 (Puma 560, m)", 1000, "6-joint Puma FK, float, Cortex-M4F"),
    ("m0", "dh_fk_q (Puma 560, mm)", 5000, "6-joint Puma FK, fixed, Cortex-M0"),
    ("m4f", "dh_dls_step_f32 (Puma 560, m)", 6000, "6-joint damped least-squares step, float, Cortex-M4F"),
    ("m0", "dh_dls_step_q (Puma 560, mm)", 40000, "6-joint damped least-squares step, fixed, Cortex-M0"),
]

# Tracking and motion goals (docs/performance.md): (core key, timed call, limit,
# label); the limit is a number of instructions, or (the name of the
# closed-form solve measured on the same targets in the same run, margin)
TRACK_MARGIN = 1000
PERIOD_MARGIN = 1500
TRACK_TARGETS = [
    ("m4f", "dh_track_step_f32 (UR5, m)", ("dh_ikc_f32 (UR5, m)", TRACK_MARGIN),
     "tracker call, float, UR5, Cortex-M4F"),
    ("m4f", "dh_track_step_f32 (Puma 560, m)", ("dh_ikc_f32 (Puma 560, m)", TRACK_MARGIN),
     "tracker call, float, Puma 560, Cortex-M4F"),
    ("m0", "dh_track_step_q (UR5, mm)", 40000, "tracker call, fixed, UR5, Cortex-M0"),
    ("m0", "dh_track_step_q (Puma 560, mm)", 40000, "tracker call, fixed, Puma 560, Cortex-M0"),
    ("m4f", "move period f32 (UR5, m)", ("dh_ikc_f32 line (UR5, m)", PERIOD_MARGIN),
     "period of a line move, float, UR5, Cortex-M4F"),
    ("m4f", "move period f32 (Puma 560, m)", ("dh_ikc_f32 line (Puma 560, m)", PERIOD_MARGIN),
     "period of a line move, float, Puma 560, Cortex-M4F"),
    ("m0", "move period q (UR5, mm)", 45000, "period of a line move, fixed, UR5, Cortex-M0"),
    ("m0", "move period q (Puma 560, mm)", 45000, "period of a line move, fixed, Puma 560, Cortex-M0"),
    ("m0", "queue period q (UR5, mm)", 45000, "period of a queued line, stopped and resumed, fixed, UR5, Cortex-M0"),
    ("m0", "queue period q (Puma 560, mm)", 45000,
     "period of a queued line, stopped and resumed, fixed, Puma 560, Cortex-M0"),
    ("m4f", "jerk period f32 (UR5, m)", ("dh_ikc_f32 jerk line (UR5, m)", PERIOD_MARGIN),
     "period of a jerk-limited line move, float, UR5, Cortex-M4F"),
    ("m4f", "jerk period f32 (Puma 560, m)", ("dh_ikc_f32 jerk line (Puma 560, m)", PERIOD_MARGIN),
     "period of a jerk-limited line move, float, Puma 560, Cortex-M4F"),
    ("m0", "jerk period q (UR5, mm)", 45000, "period of a jerk-limited line move, fixed, UR5, Cortex-M0"),
    ("m0", "jerk period q (Puma 560, mm)", 45000, "period of a jerk-limited line move, fixed, Puma 560, Cortex-M0"),
    ("m4f", "queue blend period f32 (UR5, m)", ("dh_ikc_f32 queue blend (UR5, m)", PERIOD_MARGIN),
     "period of two queued lines with a blended corner, stopped and resumed, float, UR5, Cortex-M4F"),
    ("m4f", "queue blend period f32 (Puma 560, m)", ("dh_ikc_f32 queue blend (Puma 560, m)", PERIOD_MARGIN),
     "period of two queued lines with a blended corner, stopped and resumed, float, Puma 560, Cortex-M4F"),
    ("m0", "queue blend period q (UR5, mm)", 45000,
     "period of two queued lines with a blended corner, stopped and resumed, fixed, UR5, Cortex-M0"),
    ("m0", "queue blend period q (Puma 560, mm)", 45000,
     "period of two queued lines with a blended corner, stopped and resumed, fixed, Puma 560, Cortex-M0"),
]

# dhmath operation -> peer operation
PEERS = [
    ("dh_sincos_f32", "sinf + cosf (from degrees)"),
    ("dh_mat4_mul_affine_f32", "glm_mul (affine product)"),
    ("dh_mat4_mul_f32", "glm_mat4_mul (general product)"),
    ("dh_mat4_inv_rigid_f32", "glm_mat4_copy + glm_inv_tr (rigid inverse, out of place)"),
    ("dh_mat4_inv_rigid_f32 (in place)", "glm_inv_tr (rigid inverse, in place)"),
    ("dh_mat4_inv_f32", "glm_mat4_inv (general inverse)"),
    ("dh_mat4_apply_point_f32", "glm_mat4_mulv3 (point, w = 1)"),
]

STATUS = {0: "ok", 1: "arg", 2: "nan", 3: "singular", 4: "not rigid", 5: "zero axis",
          6: "domain", 7: "overflow", 8: "no convergence", 9: "unreachable", 10: "limit"}


def fail(msg):
    sys.stderr.write("report.py: %s\n" % msg)
    sys.exit(1)


class Run:
    def __init__(self, path, elf):
        self.path = path
        self.elf = elf
        self.disasm = None
        self.ops = []        # (group, name, n, per_call)
        self.ik = []         # (k, status, iterations, instructions, err_nm)
        self.ikq = []        # (k, status, iterations, instructions, err_pos LSB)
        self.ikc = []        # (name, instructions per call, solutions per call)
        self.opw = []        # KR6 R700: (name, instructions per call, solutions per call)
        self.opw_peer = None # True: opw row present; False: built without opw; None: no KR6 section (M0)
        self.opw_check = None  # (targets, count mismatches, unmatched, opw solutions in limits, worst deg)
        self.track = {}      # name -> (calls, mean per call, largest call, ok, lagging, unreachable)
        self.checks = []
        self.core = self.opt = self.gcc = self.counter = self.unit = "?"
        self.scale = None
        self.calib = None
        self.stack = None
        self.xchecks = 0
        ended = False
        with open(path) as f:
            for line in f:
                line = line.rstrip("\n")
                if not line.startswith("BT "):
                    continue
                p = line[3:].split("|")
                kind = p[0]
                if kind == "core":
                    self.core, self.opt, self.gcc = p[1], p[2], p[3]
                elif kind == "calib":
                    self.counter = p[1]
                    self.calib = (int(p[2]), int(p[3]))
                elif kind == "unit":
                    self.unit = p[1]
                    self.scale = self.snap(Fraction(int(p[2]), int(p[3])))
                elif kind == "op":
                    n, t, base, tz, zsym = int(p[3]), int(p[4]), int(p[5]), int(p[6]), p[7]
                    call = float((t - base) * self.scale) / n
                    body = None
                    if zsym:
                        zfun, zwrap = zsym.split()
                        body = float((t - tz) * self.scale) / n + self.null_len(zfun)
                        # Cross-check of the counter on every run: the loop with
                        # the null wrapper executes straight-line code whose
                        # length the disassembly gives exactly.
                        expect = self.null_len(zwrap) + self.null_len(zfun) - self.null_len("op_empty")
                        got = float((tz - base) * self.scale) / n
                        tol = 2.0 * float(self.scale) / n + 1e-9
                        if abs(got - expect) > tol:
                            fail("%s: %s: the counter measured %.3f instructions for straight-line "
                                 "code of %d" % (path, zwrap, got, expect))
                        self.xchecks += 1
                    self.ops.append((p[1], p[2], n, body, call))
                elif kind == "ik":
                    ticks = int(p[4]) - int(p[5])
                    self.ik.append((int(p[1]), int(p[2]), int(p[3]),
                                    float(ticks * self.scale), int(p[6])))
                elif kind == "ikq":
                    ticks = int(p[4]) - int(p[5])
                    self.ikq.append((int(p[1]), int(p[2]), int(p[3]),
                                     float(ticks * self.scale), int(p[6])))
                elif kind in ("ikc", "opw"):
                    # name|calls|ticks|empty-loop ticks|solutions|status
                    n = int(p[2])
                    ticks = int(p[3]) - int(p[4])
                    if int(p[6]) != 0:
                        fail("%s: %s returned status %s" % (path, p[1], p[6]))
                    (self.ikc if kind == "ikc" else self.opw).append(
                        (p[1], float(ticks * self.scale) / n, int(p[5]) / n))
                    if kind == "opw" and p[1].startswith("opw_kinematics"):
                        self.opw_peer = True
                    elif kind == "opw" and self.opw_peer is None:
                        self.opw_peer = False
                elif kind == "opwpeer":
                    self.opw_peer = False
                elif kind == "opwcheck":
                    self.opw_check = (int(p[1]), int(p[2]), int(p[3]), int(p[4]), int(p[5]) * 1e-6)
                elif kind == "track":
                    n, ticks, null, mx = int(p[2]), int(p[3]), int(p[4]), int(p[5])
                    if int(p[9]) != 0:
                        fail("%s: %s returned status %s" % (path, p[1], p[9]))
                    per_null = float(null * self.scale) / n
                    self.track[p[1]] = (n, float((ticks - null) * self.scale) / n,
                                        float(mx * self.scale) - per_null, int(p[6]), int(p[7]), int(p[8]))
                elif kind == "check":
                    self.checks.append((p[1], p[2]))
                elif kind == "stack":
                    self.stack = (int(p[1]), int(p[2]))
                elif kind == "error":
                    fail("%s: firmware error: %s" % (path, p[1]))
                elif kind == "end":
                    ended = True
        if not ended:
            fail("%s: incomplete log (no 'BT end')" % path)
        bad = [c for c, r in self.checks if r != "ok"]
        if bad:
            fail("%s: sanity check failed: %s" % (path, "; ".join(bad)))
        if self.unit != "instructions":
            fail("%s: counter counts %s, not instructions: was QEMU run with -icount shift=0?"
                 % (path, self.unit))
        if self.stack is None or self.stack[0] > self.stack[1] * 3 // 4:
            fail("%s: stack high-water mark %s too close to the reserve" % (path, self.stack))

    @staticmethod
    def snap(ratio):
        """Instructions per tick = ns per tick under icount shift=0: the
        board's clock period (40 ns at 25 MHz, 62.5 ns at 16 MHz). The
        calibration is +-1 tick off; round to the nearest 1/8 ns when
        within 0.01 %, else refuse."""
        snapped = Fraction(round(ratio * 8), 8)
        if abs(ratio - snapped) > ratio / 10000:
            fail("calibration ratio %s is not a clock period in ns: not an icount clock?"
                 % float(ratio))
        return snapped

    def null_len(self, sym):
        """Instructions of the null twin `sym` (straight-line code ending in
        a return), from the disassembly of the firmware."""
        if self.disasm is None:
            self.disasm = subprocess.run(["arm-none-eabi-objdump", "-d", self.elf], check=True,
                                         capture_output=True, text=True).stdout
        m = re.search(r"^[0-9a-f]+ <%s>:\n((?:.+\n)+?)\n" % re.escape(sym), self.disasm, re.M)
        if not m:
            fail("%s: no symbol %s in %s" % (self.path, sym, self.elf))
        ins = []
        for ln in m.group(1).splitlines():
            f = ln.split("\t")
            if len(f) < 3 or f[2].startswith("."):
                continue
            mn = f[2].split()[0]
            # a load of pc from the stack is the return (GCC's form of
            # pop {pc} after stack arguments: ldr.w pc, [sp], #4)
            if mn.startswith("ldr") and len(f) > 3 and f[3].replace(" ", "").startswith("pc,[sp]"):
                mn = "pop"
            ins.append(mn)
        while ins and ins[-1] == "nop":     # alignment padding after the return
            ins.pop()
        # straight line: calls (bl) allowed, no other branch before the return
        # or the tail call (b/b.w/b.n, into another straight-line function)
        if not ins or ins[-1] not in ("bx", "pop", "b", "b.w", "b.n") or any(
                x.startswith("b") and x not in ("bl", "bic", "bics", "bfi", "bfc")
                for x in ins[:-1]):
            fail("%s: null twin %s is not straight-line code: %s" % (self.path, sym, ins))
        return len(ins)

    def op(self, name, call=False):
        """Instructions per call of `name`: the function's own (default) or
        the whole call from the benchmark loop (call=True; the only figure
        for inline peers)."""
        for g, nm, n, body, whole in self.ops:
            if nm == name:
                return whole if call or body is None else body
        return None

    def n_of(self, name):
        for g, nm, n, body, whole in self.ops:
            if nm == name:
                return n
        return None


def fmt(v):
    if v is None:
        return "-"
    return "%.1f" % v if v < 100 else "%.0f" % v


def main():
    if len(sys.argv) < 4:
        fail(__doc__)
    out, meta_path, logs = sys.argv[1], sys.argv[2], sys.argv[3:]
    meta = {}
    with open(meta_path) as f:
        for line in f:
            if "=" in line:
                k, v = line.rstrip("\n").split("=", 1)
                meta[k] = v
    runs = {}
    for arg in logs:
        path, elf = arg.split("=", 1)
        key = os.path.basename(path)[:-4]     # <core>-<opt>
        runs[key] = Run(path, elf)
    cols = [(c, o) for c, _ in CORES for o in OPTS if "%s-%s" % (c, o) in runs]
    core_name = dict(CORES)

    def get(c, o, name, call=False):
        r = runs.get("%s-%s" % (c, o))
        return r.op(name, call) if r else None

    def overhead_range():
        vals = []
        for r in runs.values():
            for g, nm, n, body, whole in r.ops:
                if body is not None:
                    vals.append(whole - body)
        return "%.0f-%.0f" % (min(vals), max(vals)) if vals else "?"

    def fk_overhead():
        vals = []
        for c, name, lim, label in TARGETS:
            for o in OPTS:
                a, b = get(c, o, name, True), get(c, o, name)
                if a is not None and b is not None:
                    vals.append(a - b)
        return "%.0f-%.0f instructions" % (min(vals), max(vals)) if vals else "a few instructions"

    L = []
    w = L.append
    w("# dhmath on target: instructions per call on Cortex-M0, M4F and M7")
    w("")
    w("Generated by `tools/target_bench.sh` (do not edit by hand; rerun the script). "
      "Firmware: `bench/target/` (the budgets and goals of docs/performance.md and docs/design.md).")
    w("")
    w("Every figure is the number of **executed instructions** per call, counted by QEMU "
      "with `-icount shift=0` (one nanosecond of virtual time per guest instruction) through "
      "the core's SysTick timer: exact and repeatable, but not cycles (see "
      "[What the numbers are](#what-the-numbers-are)).")
    w("")
    w("## Setup")
    w("")
    w("| item | value |")
    w("|---|---|")
    for k in ("library", "compiler", "newlib", "qemu", "cglm", "opw"):
        if k in meta:
            w("| %s | %s |" % (k, meta[k]))
    w("| library flags | as in a normal build: `-std=c99 -ffunction-sections -fdata-sections` plus "
      "the core flags of `port/cortex-*.cmake`; `-O2` = CMake `RelWithDebInfo`, `-Os` = "
      "`MinSizeRel`; default configuration (`DH_MAX_JOINTS` 8, `DH_QPOS_FRAC` 16, "
      "`DH_CHECK_ARGS` on, `DH_USE_INTRINSICS` on, `DH_SMALL` off) except `-Os DH_SMALL` = "
      "`MinSizeRel` with `DH_SMALL` on (the size-first build of the size goal) |")
    w("| cores | " + "; ".join(
        "%s: `%s`" % (core_name[c], meta.get("flags-" + c, "?")) for c, _ in CORES
        if any(cc == c for cc, _ in cols)) + " |")
    w("| QEMU command | `%s` |" % meta.get("qemu-cmd", "?"))
    w("")
    w("## Targets")
    w("")
    w("| goal | limit | -O2 | -Os | -Os DH_SMALL | met at -O2 |")
    w("|---|---:|---:|---:|---:|---|")
    for c, name, lim, label in TARGETS:
        v2, vs, vk = get(c, "O2", name), get(c, "Os", name), get(c, "Os-small", name)
        met = "-" if v2 is None else ("yes (%.0f %% of the limit)" % (100.0 * v2 / lim)
                                      if v2 <= lim else "**no** (+%.0f %%)" % (100.0 * (v2 / lim - 1)))
        w("| %s (`%s`) | %d | %s | %s | %s | %s |" % (label, name.split()[0], lim, fmt(v2), fmt(vs),
                                                      fmt(vk), met))
    w("")
    w("Figures: the function's own instructions per call (see below); the caller's "
      "argument set-up and `BL` add %s. The fixed-point figures for \"Cortex-M4\" come "
      "from the M4F build: the `*_q` code is integer-only (checked by "
      "`tools/check_guards.sh`), so a Cortex-M4 without FPU executes the same "
      "instructions. The FK figures include the six `dh_sincos_*` calls, the base/tool "
      "handling and the argument checks of the public function." % fk_overhead())
    w("")
    w("## Instructions per call")
    w("")
    hdr = "| operation | calls (N) | " + " | ".join(
        "%s %s" % (core_name[c].split(" ")[0], OPT_LABEL[o]) for c, o in cols) + " |"
    w(hdr)
    w("|---|---:|" + "---:|" * len(cols))
    names = []
    for r in runs.values():
        for g, nm, n, body, whole in r.ops:
            if (g, nm) not in names:
                names.append((g, nm))
    first = runs[min(runs)]
    for g, nm in names:
        if g != "dhmath":
            continue
        w("| `%s` | %s | %s |" % (nm, first.n_of(nm) or "?", " | ".join(
            fmt(get(c, o, nm)) for c, o in cols)))
    w("")
    w("Each figure is the function's own instructions per call (from its first instruction "
      "through its return), averaged over N calls on varied inputs: the loop calling the "
      "function minus the same loop calling a null twin with the same prototype (which "
      "executes `bx lr`, or `movs r0, #0` + `bx lr`, counted in the disassembly and added "
      "back). The caller's side of a call (argument set-up, `BL`, using the status) "
      "comes on top: %s instructions in the benchmark's wrappers." % overhead_range())
    w("")
    w("Inputs (generated once by a seeded xorshift32 generator on the target): angles uniform in "
      "+-720 deg (%d different on M4F/M7, 64 on M0); rigid transforms with a random axis, "
      "angle in +-180 deg and translation in +-1 m (float) or +-1000 mm (fixed, from "
      "`dh_frame_from_mat4_q`); points in +-1 m / +-1000 mm; products run over all pairs of "
      "16 (M0: 8) matrices or frames; FK and Jacobian over 16 (M0: 8) Puma 560 configurations "
      "uniform within the joint limits. `dh_mat4_inv_f32` gets rigid transforms (its fast "
      "adjugate path with the certificate). Every timed call returned `DH_OK`." % 256)
    w("")
    w("### Size-first build against the default build")
    w("")
    w("Instructions of the `-Os DH_SMALL` build over those of the default `-Os` build "
      "on the same core (goal: at most 3x for every public function).")
    w("")
    score = [c for c in sorted(set(k.split("-")[0] for k in runs))
             if "%s-Os" % c in runs and "%s-Os-small" % c in runs]
    if score:
        w("| operation | " + " | ".join("%s" % core_name[c].split(" ")[0] for c in score) + " |")
        w("|---|" + "---:|" * len(score))
        for g, nm in names:
            if g != "dhmath":
                continue
            cells = []
            for c in score:
                a, b = get(c, "Os", nm), get(c, "Os-small", nm)
                if a is None or b is None or a <= 0:
                    cells.append("-")
                else:
                    x = b / a
                    # over the goal when above 3.00 at the printed precision
                    # (the figures are +-0.12 instructions per call)
                    cells.append(("**%.2fx**" if round(x, 2) > 3.0 else "%.2fx") % x)
            w("| `%s` | %s |" % (nm, " | ".join(cells)))
        w("")
    w("### Peers")
    w("")
    w("Same inputs, same loop. cglm (%s; header-only, its plain C paths: a Cortex-M has "
      "neither SSE nor NEON) compiled with the same core flags and `-ffp-contract=off` like dhmath's "
      "ISO C build (in a GNU mode GCC would fuse multiply-adds into VFMA in cglm only; same "
      "IEEE operations on both sides this way). newlib's `sinf` + `cosf` of `deg * pi/180` "
      "(the float-from-degrees peer of `dh_sincos_f32`; newlib's libm as shipped, "
      "precompiled)." % meta.get("cglm", ""))
    w("")
    w("Both sides are measured the same way: each cglm operation is compiled (cglm's "
      "inline code) into an out-of-line function with the prototype of the dhmath function "
      "it is compared with, called from a `noinline` wrapper with the same index arithmetic "
      "as dhmath's, and timed against a null twin with the same prototype. The first table "
      "counts each function's own instructions (first instruction through return); the "
      "second the whole call from the benchmark loop (wrapper, argument set-up, `BL`), "
      "which adds the same few instructions to both sides.")
    w("")
    for title, whole in (("Own instructions", False), ("Whole calls", True)):
        w("%s:" % title)
        w("")
        w("| dhmath | peer | " + " | ".join(
            "%s %s" % (core_name[c].split(" ")[0], OPT_LABEL[o]) for c, o in cols) + " |")
        w("|---|---|" + "---|" * len(cols))
        for dh, peer in PEERS:
            cells = []
            for c, o in cols:
                a, b = get(c, o, dh, whole), get(c, o, peer, whole)
                if a is None or b is None:
                    cells.append("-")
                else:
                    cells.append("%s vs %s (%.2fx)" % (fmt(a), fmt(b), a / b))
            w("| `%s` | `%s` | %s |" % (dh, peer, " | ".join(cells)))
        w("")
    worse, better = [], []
    for dh, peer in PEERS:
        a, b = get("m4f", "O2", dh), get("m4f", "O2", peer)
        if a is not None and b is not None:
            # compared at the resolution of the figures (+-0.12 per call)
            (worse if round(a) > round(b) else better).append("`%s` %.2fx" % (dh, a / b))
    if worse or better:
        w("On the Cortex-M4F at -O2 (own instructions) dhmath executes at most as many "
          "instructions as its peer for %s, and more for %s." % (", ".join(better) or "none", ", ".join(worse) or "none"))
        w("")
    w("(x = dhmath / peer instructions; below 1 dhmath executes fewer.) What the rows "
      "compute differs in places: `dh_sincos_f32` reduces any float angle exactly and "
      "checks for NaN/Inf; `glm_inv_tr` inverts in place (no output copy) while "
      "`dh_mat4_inv_rigid_f32` writes a separate output; `dh_mat4_inv_f32` certifies "
      "singularity (condition estimate and residual check, see `include/dhmath/mat4.h`) "
      "where `glm_mat4_inv` divides by the determinant without any check; "
      "`dh_mat4_mul_f32` is a full 4x4 product like `glm_mat4_mul`.")
    w("")
    w("## Closed-form inverse kinematics (Puma 560, all solutions)")
    w("")
    w("Per call: all solutions of `dh_ikc_f32` (metres, float cores only) and `dh_ikc_q` (mm) for "
      "targets = FK of random configurations within the joint limits (computed untimed; 4 on "
      "the Cortex-M0 for its 16 KiB of RAM, 16 elsewhere); the loop over the targets is timed as a whole, minus the "
      "same loop without the call.")
    w("")
    w("| core | operation | instructions per call | solutions per call |")
    w("|---|---|---:|---:|")
    for c, o in cols:
        r = runs["%s-%s" % (c, o)]
        for name, ins, ns in r.ikc:
            w("| %s -%s | `%s` | %.0f | %.2f |" % (core_name[c], o, name, ins, ns))
    w("")
    w("## Closed-form inverse kinematics against opw_kinematics (KUKA KR6 R700 sixx)")
    w("")
    w("Per call, on the cores with an FPU: `dh_ikc_f32` (metres) and `dh_ikc_q` (mm), every solution "
      "within joint limits of +-170 deg with q_ref = (0, -90, 90, 0, 0, 0) deg, and "
      "`opw_kinematics::inverse<float>` (its 8 raw solutions, NaN where none, no limits; the "
      "parameters of opw's example `makeKukaKR6_R700_sixx`, include/opw_kinematics/"
      "opw_parameters_examples.h; C++ gnu++17 with Eigen and newlib's libstdc++, NDEBUG, "
      "-ffp-contract=off) on the same %d targets: FK of random configurations within the limits, "
      "computed untimed (`bt_opw` in bench/target/bench_target.c, bench/target/bench_opw.cpp). "
      "Each loop over the targets is timed as a whole, minus the same loop without the call. "
      "Check (untimed): opw's finite solutions, mapped to the DH table's joint values "
      "(q_dh = (-1, 1, 1, -1, 1, -1) * q_opw, degrees), wrapped to (-180, 180] and kept within "
      "the limits, against dhmath's float ones: the count per target, and each matched by one "
      "within 1e-3 deg on every joint. opw_kinematics: %s."
      % (16, meta.get("opw", "not given")))
    w("")
    opw_rows = [(c, o) for c, o in cols if runs["%s-%s" % (c, o)].opw_peer is not None]
    if not any(runs["%s-%s" % (c, o)].opw_peer for c, o in opw_rows):
        w("This run had no opw_kinematics: `git clone --branch 0.5.5 "
          "https://github.com/Jmeyer1292/opw_kinematics /path/to/opw`, then "
          "`OPW_DIR=/path/to/opw tools/target_bench.sh` (needs libeigen3-dev and "
          "libstdc++-arm-none-eabi-newlib).")
        w("")
    w("| core | operation | instructions per call | solutions per call | dhmath / opw |")
    w("|---|---|---:|---:|---:|")
    for c, o in opw_rows:
        r = runs["%s-%s" % (c, o)]
        peer = [ins for name, ins, ns in r.opw if name.startswith("opw_kinematics")]
        for name, ins, ns in r.opw:
            ratio = "-"
            if peer and not name.startswith("opw_kinematics") and peer[0] > 0:
                ratio = "%.2f" % (ins / peer[0])
            w("| %s -%s | `%s` | %.0f | %.2f | %s |" % (core_name[c], o, name, ins, ns, ratio))
    w("")
    checks = [(c, o, runs["%s-%s" % (c, o)].opw_check) for c, o in opw_rows
              if runs["%s-%s" % (c, o)].opw_check is not None]
    if checks:
        w("| core | targets | with a different solution count | opw solutions in the limits | "
          "without a dhmath one within 1e-3 deg | largest joint difference to the nearest (deg) |")
        w("|---|---:|---:|---:|---:|---:|")
        for c, o, k in checks:
            w("| %s -%s | %d | %d | %d | %d | %.2e |" % (core_name[c], o, k[0], k[1], k[3], k[2], k[4]))
        w("")
    w("## Tracking")
    w("")
    w("One tracker call per control period of 1 ms along a smooth move: the targets are the FK of "
      "a minimum-jerk joint move of 256 periods (12-20 deg per joint, peak speed below the rate "
      "limit of 180 deg/s set on every joint, the UR5's published joint speed) from "
      "(20, -110, 95, -75, 60, 30) deg on the UR5 and (10, -40, 30, 20, 45, -30) deg on the "
      "Puma 560, computed untimed between the calls; consecutive targets as a controller "
      "sends them, not one target repeated. Each call is timed on its own: the counter "
      "around it minus its own cost (the same number of empty intervals). Beside each tracker, "
      "the closed-form solve of the same targets (`dh_ikc_*` with the tracker's configuration "
      "as q_ref and `DH_IKC_KEEP_OUT_OF_LIMITS`, as the tracker calls it) and the public Jacobian and singularity measures "
      "at the tracker's output (`dh_jacobian_*` + `dh_manipulability_*`, what the tracker's "
      "report computes on every call), in the same run. Float trackers on the FPU cores "
      "only; the trackers' settings are the defaults of `dh_track_init_*`. "
      "The move periods: a line move (`dh_move_path_f32`, 0.25 m/s, 2 m/s^2, 90 deg/s, "
      "360 deg/s^2) from the FK of the same start to the FK of the tracking move's middle, "
      "run to its end; each period timed whole (`dh_move_target_f32`, `dh_track_step_f32` on "
      "its frame, `dh_move_advance_f32` with the tracker's state), beside the closed-form "
      "solve of the period's frame as the tracker calls it (`dh_ikc_f32 line`). Its fixed twin on every core "
      "(`dh_move_path_q`, the robots in mm: 250 mm/s, 2000 mm/s^2), each period timed whole "
      "(`dh_move_target_q`, `dh_track_step_q`, `dh_move_advance_q`) and its tracker call on its "
      "own in the same periods (`dh_track_step_q line`). The jerk-limited periods: the same line "
      "as a seven-phase move within 20 m/s^3 (20,000 mm/s^3) and 3,600 deg/s^3 "
      "(`dh_move_path_jerk_f32`, `dh_move_path_jerk_q`), the same calls per period "
      "(`dh_ikc_f32 jerk line`, `dh_track_step_q jerk line` beside them). The queue periods "
      "(`dh_queue_target_*`, the tracker call on its frame, `dh_queue_advance_*`, timed whole; "
      "the queue stopped at the 100th period and resumed at rest, so the brake's and the resume's "
      "periods are among them): the fixed line alone (`queue period q`), and that line followed by "
      "a second one to the FK of the tracking move's end, appended by `dh_queue_add_path_blend_*` "
      "with their corner blended within 20 mm (`queue blend period`), beside the closed-form "
      "solve of each period's frame with the tracker's configuration before the period as q_ref "
      "(`dh_ikc_f32 queue blend`, after the period, untimed for it).")
    w("")
    w("| goal | limit | -O2 | -Os | -Os DH_SMALL | met at -O2 (mean) | met at -O2 (largest call) |")
    w("|---|---|---:|---:|---:|---|---|")

    def track_get(c, o, name):
        r = runs.get("%s-%s" % (c, o))
        return r.track.get(name) if r else None

    def verdict(v, lim):
        if v is None or lim is None:
            return "-"
        return ("yes (%.0f %% of the limit)" % (100.0 * v / lim) if v <= lim
                else "**no** (+%.0f %%)" % (100.0 * (v / lim - 1)))

    for c, name, ref, label in TRACK_TARGETS:
        cells, lim2 = [], None
        for o in OPTS:
            t = track_get(c, o, name)
            if isinstance(ref, tuple):
                rr = track_get(c, o, ref[0])
                lim = None if rr is None else rr[1] + ref[1]
            else:
                lim = ref
            if o == "O2":
                lim2 = lim
            cells.append("-" if t is None else ("%s (limit %s)" % (fmt(t[1]), fmt(lim))
                                                 if isinstance(ref, tuple) and lim is not None else fmt(t[1])))
        t2 = track_get(c, "O2", name)
        lim_txt = ("`%s` + %d" % (ref[0].split()[0], ref[1])) if isinstance(ref, tuple) else "%d" % ref
        kind, ty = ("queue" if name.startswith("queue ") else "move"), ("f32" if " f32 " in name else "q")
        code = (name.split()[0] if name.startswith("dh_")
                else "dh_%s_target_%s` + `dh_track_step_%s` + `dh_%s_advance_%s" % (kind, ty, ty, kind, ty))
        w("| %s (`%s`) | %s | %s | %s | %s |" % (label, code, lim_txt, " | ".join(cells),
                                                verdict(None if t2 is None else t2[1], lim2),
                                                verdict(None if t2 is None else t2[2], lim2)))
    w("")
    w("Figures: mean instructions per call over the move (the closed-form limits: the mean of "
      "`dh_ikc_*` on the same targets plus %d for a tracker call, %d for a move period). "
      "\"largest call\": the most expensive single call "
      "of the move, which bounds the period a control loop must allow (+-1 counter tick, 40 or "
      "62.5 instructions)." % (TRACK_MARGIN, PERIOD_MARGIN))
    w("")
    w("| core | operation | calls | mean per call | largest call | ok / lagging / unreachable |")
    w("|---|---|---:|---:|---:|---|")
    for c, o in cols:
        r = runs["%s-%s" % (c, o)]
        for name, (n, mean, mx, ok, lag, unr) in r.track.items():
            st = ("%d / %d / %d" % (ok, lag, unr) if name.startswith(("dh_track", "move period", "jerk period",
                                                                     "blend period", "queue")) and " line (" not in name
                  else "")
            w("| %s -%s | `%s` | %d | %.0f | %.0f | %s |" % (core_name[c], o, name, n, mean, mx, st))
    w("")
    w("## Inverse kinematics (`dh_ik_f32`, Puma 560 in metres)")
    w("")
    w("Per solve: target = `dh_fk_f32` of a random configuration within 80 % of the joint "
      "limits, start 10-20 deg away on every joint, `dh_ik_params_default_f32(robot)` with tol_pos set to 1e-6 m "
      "(full pose, 1e-6 m / 1e-5 rad, w_rot L/4 = 0.43 m/rad). Instructions of the whole `dh_ik_f32` call.")
    w("")
    w("| core | solves | converged | iterations mean (min-max) | instructions per solve mean (min-max) | per iteration |")
    w("|---|---:|---:|---|---|---:|")
    for c, o in cols:
        r = runs["%s-%s" % (c, o)]
        if not r.ik:
            continue
        its = [x[2] for x in r.ik]
        ins = [x[3] for x in r.ik]
        conv = sum(1 for x in r.ik if x[1] == 0)
        w("| %s -%s | %d | %d | %.1f (%d-%d) | %.0f (%.0f-%.0f) | %.0f |" % (
            core_name[c], o, len(r.ik), conv, sum(its) / len(its), min(its), max(its),
            sum(ins) / len(ins), min(ins), max(ins), sum(ins) / sum(its)))
    w("")
    w("\"per iteration\" divides the total instructions by the total iterations, so it "
      "includes the set-up and final evaluation of each solve. The targets and starts are "
      "the same on every core, yet the M0 takes different iteration counts than the "
      "M4F/M7: the float results are not bit-identical between the soft-float and the "
      "FPU builds. The library itself is compiled as ISO C (no contraction into fused "
      "multiply-adds), but it calls newlib's libm (`atan2f` in the orientation error, "
      "`sqrtf`), and newlib's precompiled FPU variants contain VFMA instructions (seen in "
      "the disassembly of `atanf`, `__kernel_sinf`, `__kernel_cosf`), which round "
      "differently from the soft-float code; this is the likely cause.")
    w("")
    w("## Inverse kinematics in fixed point (`dh_ik_q`, Puma 560 in mm)")
    w("")
    w("Per solve: target = `dh_fk_q` of a random Q configuration within 80 % of the joint "
      "limits, start 10-20 deg away on every joint, `dh_ik_params_default_q(robot)` with tolerances "
      "0.9e-3 mm / 0.9e-5 rad (full pose, w_rot L/4; 0.9 of the 1e-3 mm / 1e-5 rad verified by "
      "test/kin/test_ik_q.c, room for the fixed FK's error). Instructions of the whole "
      "`dh_ik_q` call (integer only).")
    w("")
    w("| core | solves | converged | iterations mean (min-max) | instructions per solve mean (min-max) | per iteration |")
    w("|---|---:|---:|---|---|---:|")
    for c, o in cols:
        r = runs["%s-%s" % (c, o)]
        if not r.ikq:
            continue
        its = [x[2] for x in r.ikq]
        ins = [x[3] for x in r.ikq]
        conv = sum(1 for x in r.ikq if x[1] == 0)
        w("| %s -%s | %d | %d | %.1f (%d-%d) | %.0f (%.0f-%.0f) | %.0f |" % (
            core_name[c], o, len(r.ikq), conv, sum(its) / len(its), min(its), max(its),
            sum(ins) / len(ins), min(ins), max(ins), sum(ins) / max(1, sum(its))))
    w("")
    w("## What the numbers are")
    w("")
    w("* **Counter.** QEMU's `-icount shift=0` advances virtual time by exactly 1 ns per "
      "executed guest instruction; SysTick runs on the board's processor clock (MPS2: "
      "25 MHz, 40 ns per tick; micro:bit: 16 MHz, 62.5 ns per tick), its interrupt "
      "extends it to 64 bits. The firmware calibrates itself with a loop of exactly "
      "2 x 10^7 instructions (`SUBS`/`BNE`):")
    w("")
    w("  | run | counter | ticks for 2e7 instructions | instructions per tick | stack used / reserve (bytes) |")
    w("  |---|---|---:|---:|---:|")
    for c, o in cols:
        r = runs["%s-%s" % (c, o)]
        w("  | %s -%s | %s | %d | %s | %d / %d |" % (core_name[c], o, r.counter, r.calib[1],
                                                 float(r.scale), r.stack[0], r.stack[1]))
    w("")
    w("* **Instructions are not cycles.** QEMU models no pipeline, no flash wait states, no "
      "caches and no dual issue. On a real Cortex-M4 most instructions take one cycle, "
      "loads/stores 2 (pipelined back to back), taken branches 2-4, `VDIV`/`VSQRT` 14, "
      "plus flash wait states above ~30 MHz; a Cortex-M7 can issue two instructions per "
      "cycle; a Cortex-M0 multiply takes 1 or 32 cycles depending on the "
      "implementation. The M0 figures are for ARMv6-M code compiled for "
      "`-mcpu=cortex-m0plus` (QEMU has no M0+ model; the instructions are the same).")
    w("* **On hardware** the same firmware measures cycles: on ARMv7-M it enables "
      "`DWT->CYCCNT` and uses it when it advances (under QEMU it reads 0), on ARMv6-M "
      "SysTick counts core clocks; the calibration loop then gives fewer than 1.5 "
      "instructions per tick and the firmware reports `cycles` instead of `instructions` "
      "(this report generator accepts only instruction counts).")
    w("* **Checked on every run.** The loop with a null twin executes straight-line code "
      "(wrapper, `BL`, `movs r0, #0`/`bx lr`, status store) whose length the disassembly "
      "gives exactly; `report.py` compares the counter's figure with it for every "
      "operation (%d checks in this run) and fails on a difference beyond the resolution. "
      "The counts are deterministic: two runs of the same image print identical logs."
      % sum(r.xchecks for r in runs.values()))
    w("* **Resolution.** A figure is the difference of two measurements of +-1 tick "
      "(40 or 62.5 instructions) each, over N calls: +-0.03 instructions per call at "
      "N = 4096, +-0.12 at 1024, +-0.25 at 512, +-1 at 128 (Jacobian).")
    w("* **micro:bit counter.** QEMU 7.2's `microbit` machine (nRF51, Cortex-M0) has the "
      "ARMv6-M SysTick on the 16 MHz system clock, so the same counter works there "
      "(62.5 instructions per tick, confirmed by the calibration); no nRF51 timer is "
      "needed. Its 16 KiB of RAM hold the inputs with a 2 KiB stack reserve "
      "(`bench/target/microbit_bench.ld`); the high-water mark is in the table above.")
    w("* **Re-running.** `tools/target_bench.sh [output.md]` rebuilds the firmware for "
      "every core at -O2, -Os and -Os with `DH_SMALL` (`Os-small`) in `build/tbench-<core>-<opt>/`, runs it and rewrites this "
      "page; it fails if a sanity check in the firmware fails (statuses, "
      "`dh_sincos_f32` vs `sinf`, `dh_fk_q` vs `dh_fk_f32`, cglm vs dhmath product), if "
      "the counter does not behave like the icount clock or if the firmware's stack "
      "high-water mark passes 3/4 of its reserve. Raw logs: "
      "`build/tbench-logs/<core>-<opt>.log`. "
      "`TBENCH_CORES=\"m4f\" TBENCH_OPTS=\"O2\"` restricts the run.")
    w("")
    with open(out, "w") as f:
        f.write("\n".join(L))


if __name__ == "__main__":
    main()
