#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Accuracy plots of dhmath against glibc and libfixmath (the accuracy goal of
docs/performance.md).

Runs the C data generator (bench/accuracy_data.c, built by the bench
target), draws the PNG figures into docs/generated/img/ and writes
docs/generated/accuracy_plots.md with the numbers of the SAME run, so text and figures
cannot disagree.

Usage (from the repository root):
    /usr/bin/python3 tools/plot_accuracy.py [--build DIR] [--data DIR]

--build: build directory configured with -DDH_BUILD_BENCH=ON (default
         build-bench-host, the one tools/bench.sh uses); accuracy_data is
         built there if missing.
--data:  where the CSV files go (default <build>/accuracy).
Needs matplotlib and numpy (Debian: python3-matplotlib, python3-numpy).
"""
import argparse
import csv
import datetime
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))

LABELS = {
    "dh_f32": "dh_sincos_f32 (float, degrees)",
    "dh_q": "dh_sincos_q (Q16.16 deg -> Q2.30)",
    "glibc": "glibc sinf/cosf of deg*(float)(pi/180)",
    "fix16": "libfixmath fix16_sin/cos (fix16 radians)",
}
COLORS = {"dh_f32": "tab:blue", "dh_q": "tab:green", "glibc": "tab:orange", "fix16": "tab:red"}


def run(cmd, **kw):
    print("+", " ".join(cmd), flush=True)
    return subprocess.run(cmd, check=True, **kw)


def read_cols(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    cols = {}
    for k in rows[0].keys():
        vals = []
        for r in rows:
            v = r[k]
            try:
                vals.append(float(v) if v != "" else np.nan)
            except ValueError:
                vals.append(v)
        cols[k] = vals
    return cols


def read_summary(path):
    with open(path, newline="") as f:
        return {r["key"]: float(r["value"]) for r in csv.DictReader(f)}


def plot_sweep(data, out):
    c = read_cols(os.path.join(data, "trig_sweep.csv"))
    x = np.array(c["deg"])
    fig, ax = plt.subplots(figsize=(9, 4.5))
    for m in ("fix16", "glibc", "dh_f32", "dh_q"):
        y = np.array(c[m], dtype=float)
        if np.all(np.isnan(y)):
            continue
        ax.plot(x, y, lw=0.8, color=COLORS[m], label=LABELS[m])
    ax.set_yscale("log")
    ax.set_xlim(-720, 720)
    ax.set_xticks(np.arange(-720, 721, 180))
    ax.set_xlabel("angle (degrees)")
    ax.set_ylabel("max |error| of sin and cos per 0.25 deg bin")
    ax.set_title("sin/cos error from degrees, every 1/4096 degree in [-720, 720]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="center right", fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def plot_large(data, out):
    c = read_cols(os.path.join(data, "trig_large.csv"))
    x = np.sqrt(np.array(c["deg_lo"]) * np.array(c["deg_hi"]))
    fig, ax = plt.subplots(figsize=(9, 4.5))
    for m in ("fix16", "glibc", "dh_f32", "dh_q"):
        y = np.array(c[m], dtype=float)
        if np.all(np.isnan(y)):
            continue
        ax.plot(x, y, marker=".", ms=3, lw=1, color=COLORS[m], label=LABELS[m])
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("|angle| (degrees)")
    ax.set_ylabel("max |error| per bin (4000 random floats)")
    ax.set_title("Large angles: error vs magnitude (each method within its input range)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def plot_fk(data, out):
    c = read_cols(os.path.join(data, "fk_err.csv"))
    robots = []
    for r in c["robot"]:
        if r not in robots:
            robots.append(r)
    fig, axes = plt.subplots(1, len(robots), figsize=(10, 4), sharey=True)
    rob = np.array(c["robot"])
    path = np.array(c["path"])
    err = np.array(c["err_mm"], dtype=float)
    for ax, r in zip(np.atleast_1d(axes), robots):
        lo = np.log10(max(err[rob == r].min(), 1e-9))
        hi = np.log10(err[rob == r].max())
        bins = np.logspace(lo, hi, 60)
        for p, col in (("float", "tab:blue"), ("fixed", "tab:green")):
            e = err[(rob == r) & (path == p)]
            ax.hist(e, bins=bins, histtype="step", lw=1.3, color=col,
                    label="%s path (max %.2g mm)" % (p, e.max()))
        ax.set_xscale("log")
        ax.set_xlabel("end-frame position error (mm)")
        ax.set_title("%s, %d configurations" % (r, int(np.sum((rob == r) & (path == "float")))))
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    np.atleast_1d(axes)[0].set_ylabel("count")
    fig.suptitle("FK position error vs double reference (nominal DH table, same joint inputs)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def git_rev():
    try:
        return subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], check=True,
                              capture_output=True, text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def write_md(s, out):
    g = s["sweep_max_glibc"]
    f32 = s["sweep_max_dh_f32"]
    fx = s.get("sweep_max_fix16", float("nan"))
    q = s["sweep_max_dh_q"]
    lsb = 2.0 ** -30
    have_fx = s.get("have_fixmath", 0) == 1
    lines = []
    a = lines.append
    a("# Accuracy plots (host)")
    a("")
    a("Generated by `/usr/bin/python3 tools/plot_accuracy.py` on %s (commit %s); the"
      % (datetime.date.today().isoformat(), git_rev()))
    a("figures in `docs/generated/img/` and every number below come from the same run of")
    a("`bench/accuracy_data.c`. References: libm sin/cos in double of the exactly")
    a("reduced angle (`fmod(deg, 360)` is exact). Errors are absolute, in units of 1.0.")
    a("")
    a("## sin/cos from degrees over [-720, 720]")
    a("")
    a("![sin/cos error over +-720 degrees](img/trig_sweep.png)")
    a("")
    a("Every angle k/4096 degree in [-720, 720) (%d angles, exactly representable in"
      % int(s["sweep_points"]))
    a("float, Q16.16 and, up to rounding to fix16, radians); max |error| of sin and cos:")
    a("")
    a("| method | input | max error | vs dh_sincos_f32 |")
    a("|---|---|---|---|")
    a("| dh_sincos_f32 | float degrees | %.3g | 1 |" % f32)
    a("| dh_sincos_q | Q16.16 degrees -> Q2.30 | %.3g (%.3f LSB) | %.3g |" % (q, q / lsb, q / f32))
    a("| glibc sinf/cosf | r = deg * (float)(pi/180) | %.3g | %.1fx larger |" % (g, g / f32))
    if have_fx:
        a("| libfixmath fix16_sin/cos | fix16 radians (rounded in double) | %.3g | %.2gx larger |"
          % (fx, fx / f32))
    a("")
    a("glibc's own sinf is accurate to under an ulp for its radian argument; the")
    a("error shown is that of the usual way of calling it with degrees: rounding")
    a("deg * pi/180 to float loses up to half an ulp of the radian value, which grows")
    a("with the angle (about 5.7e-7 at 720 degrees). dhmath reduces the degrees")
    a("exactly and is %.1fx more accurate on this range (the speed goals of docs/performance.md ask for >= 4x)." % (g / f32))
    if have_fx:
        a("libfixmath reaches %.2g in bands tens of degrees wide (see the plot; its" % fx)
        a("polynomial loses accuracy there) and is near %.1g elsewhere (median of the"
          % s["fix16_bin_median"])
        a("bins), against a fix16 output resolution of 1.5e-5: %.2g times the float"
          % (fx / f32))
        a("error of dhmath and %.2g times the Q2.30 error of dh_sincos_q." % (fx / q))
    a("")
    a("## Large angles")
    a("")
    a("![error vs angle magnitude](img/trig_large.png)")
    a("")
    a("|deg| log-spaced from 1 to 1e7 (20 bins per decade, 4000 random floats of both")
    a("signs per bin). Max |error| over all bins:")
    a("")
    a("| method | range | max error |")
    a("|---|---|---|")
    a("| dh_sincos_f32 | 1 .. 1e7 deg | %.3g |" % s["large_max_dh_f32"])
    a("| dh_sincos_q | 1 .. 32767 deg (Q16.16 range) | %.3g |" % s["large_max_dh_q"])
    a("| glibc sinf/cosf of deg*(float)(pi/180) | 1 .. 1e4 deg | %.3g |"
      % s["large_max_glibc_upto_1e4"])
    a("| glibc sinf/cosf of deg*(float)(pi/180) | 1 .. 1e7 deg | %.3g |" % s["large_max_glibc"])
    if have_fx:
        a("| libfixmath fix16_sin/cos | 1 .. 1.88e6 deg (fix16 radian range) | %.3g |"
          % s["large_max_fix16"])
    a("")
    a("The dhmath error does not depend on the magnitude (exact reduction); the")
    a("radian route's error grows linearly with it.")
    a("")
    a("## Forward kinematics, float vs fixed point (mm)")
    a("")
    a("![FK position error histograms](img/fk_error_hist.png)")
    a("")
    a("Puma 560 and UR5 built in millimetres (`dh_robot_add_joint_f32` with the")
    a("tables of `bench/bench_ref.c`: Corke's RTB Puma560, UR's published UR5")
    a("parameters), %d random configurations within the joint limits; the float path"
      % int(s["fk_configs"]))
    a("gets the angles rounded to float, the fixed path to Q16.16 (lengths with")
    a("DH_QPOS_FRAC = %d). \"End to end\" is against the double FK of the nominal"
      % int(s["fk_qpos_frac"]))
    a("table at exactly the joint values the path received (so it includes the")
    a("rounding of the DH constants to float / Q); \"implementation\" is against the")
    a("double FK of the constants as the `dh_robot` stores them.")
    a("")
    a("| robot | path | max end to end | mean end to end | max implementation |")
    a("|---|---|---|---|---|")
    for r, name in (("puma", "Puma 560"), ("ur5", "UR5")):
        for p in ("float", "fixed"):
            a("| %s | %s | %.3g mm | %.3g mm | %.3g mm |"
              % (name, p, s["fk_%s_%s_max_mm" % (r, p)], s["fk_%s_%s_mean_mm" % (r, p)],
                 s["fk_%s_%s_impl_max_mm" % (r, p)]))
    a("")
    a("In millimetre units the fixed path (Q16 lengths, 1.5e-5 mm steps, Q2.30")
    a("rotations) is more accurate than float, whose 24-bit significand gives")
    a("about 6e-5 mm resolution on a 1 m reach.")
    a("")
    with open(out, "w") as f:
        f.write("\n".join(lines))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build-bench-host"))
    ap.add_argument("--data", default=None)
    args = ap.parse_args()
    build = os.path.abspath(args.build)
    data = os.path.abspath(args.data or os.path.join(build, "accuracy"))
    exe = os.path.join(build, "bench", "accuracy_data")
    if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
        run(["cmake", "-S", ROOT, "-B", build, "-DDH_BUILD_BENCH=ON", "-DDH_BUILD_TESTS=OFF",
             "-DDH_BUILD_TOOLS=OFF", "-DCMAKE_BUILD_TYPE=Release",
             "-DCMAKE_C_FLAGS_RELEASE=-O2 -DNDEBUG", "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG"])
    run(["cmake", "--build", build, "--target", "accuracy_data", "-j2"])
    os.makedirs(data, exist_ok=True)
    run([exe, data])
    img = os.path.join(ROOT, "docs", "generated", "img")
    os.makedirs(img, exist_ok=True)
    plot_sweep(data, os.path.join(img, "trig_sweep.png"))
    plot_large(data, os.path.join(img, "trig_large.png"))
    plot_fk(data, os.path.join(img, "fk_error_hist.png"))
    summ = read_summary(os.path.join(data, "summary.csv"))
    fx_bins = np.array(read_cols(os.path.join(data, "trig_sweep.csv"))["fix16"], dtype=float)
    summ["fix16_bin_median"] = float(np.nanmedian(fx_bins)) if not np.all(np.isnan(fx_bins)) else 0.0
    page = os.path.join(ROOT, "docs", "generated", "accuracy_plots.md")
    write_md(summ, page)
    run(["sh", os.path.join(ROOT, "tools", "stamp.sh"), "tools/plot_accuracy.py", page])
    print("wrote docs/generated/img/trig_sweep.png, docs/generated/img/trig_large.png, docs/generated/img/fk_error_hist.png, "
          "docs/generated/accuracy_plots.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())
