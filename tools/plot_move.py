#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Plots of a `dhmath move` run: joint positions, joint velocities (finite
differences of the CSV) and the tool path (FK in double here, from the DH
table of the robot file), one PNG per run.

Usage (from the repository root):
    /usr/bin/python3 tools/plot_move.py CSV ROBOT OUT.png [--title TEXT]
        draws the CSV that `dhmath move ROBOT ...` printed into OUT.png
    /usr/bin/python3 tools/plot_move.py --docs [--cli PATH]
        runs the examples of docs/motion.md through the CLI (PATH, default
        build/host/cli/dhmath, built there with the host preset if missing),
        draws docs/generated/img/move_*.png and writes
        docs/generated/motion_plots.md (the commands, their exit status and
        period counts), stamped by tools/stamp.sh (tools/gen_docs.sh motion)

The figure has four panels: joint positions (deg or length unit) against
t; joint velocities (q_k - q_{k-1}) / dt against t, with the rate limits
when the CSV's command gave them; the tool path projected on the XY and the
XZ planes of the base frame, periods that were not `ok` in red.

The robot file is read here (convention, joint, base and tool statements;
base and tool EXPRs with the terms trans, rotx, roty, rotz, rot, ident and
inv(...)), and FK is computed as robot.h defines it: standard DH
A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i), modified DH
A_i = Rx(alpha_{i-1}) Tx(a_{i-1}) Rz(theta_i) Tz(d_i), T = base A_1 ... A_n tool.
Needs matplotlib and numpy (Debian: python3-matplotlib, python3-numpy).
"""
import argparse
import csv
import math
import os
import re
import shlex
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))

# The examples of docs/motion.md: (image name, title, arguments after `dhmath move`).
UR5 = "examples/robots/ur5.dh"
PUMA = "examples/robots/puma560.dh"
UR5_Q0 = "10,-60,70,20,40,30"
UR5_ROT = "rot(0.755650103,-0.632537484,0.169968486,111.143417)"
UR5_LIMITS = ["--dt", "0.004", "--vmax", "180", "--amax", "720"]
UR5_CART = ["--speed", "0.25", "--accel", "1", "--rspeed", "60", "--raccel", "240"]
EXAMPLES = [
    ("move_ur5_line", "UR5: a line (0.25 m/s, 1 m/s^2)",
     [UR5, "--q0", UR5_Q0] + UR5_LIMITS + UR5_CART + ["--line", "trans(-0.4,-0.35,0.35) " + UR5_ROT]),
    ("move_ur5_arc", "UR5: an arc through a via point, turning the tool 40 deg",
     [UR5, "--q0", UR5_Q0] + UR5_LIMITS + UR5_CART +
     ["--arc", "trans(-0.45,-0.15,0.40)", "trans(-0.40,-0.35,0.35) " + UR5_ROT + " rotz(40)"]),
    ("move_ur5_joint", "UR5: joint moves, trapezoidal (--jerk absent)",
     [UR5, "--q0", UR5_Q0] + UR5_LIMITS + ["--joint", "40,-80,90,0,60,10", "--joint", UR5_Q0]),
    ("move_ur5_jerk", "UR5: the same joint moves, jerk-limited (--jerk 3000 deg/s^3)",
     [UR5, "--q0", UR5_Q0] + UR5_LIMITS + ["--jerk", "3000", "--joint", "40,-80,90,0,60,10", "--joint", UR5_Q0]),
    ("move_ur5_blend", "UR5: a square, its corners blended within 3 cm (--blend 0.03)",
     [UR5, "--q0", UR5_Q0] + UR5_LIMITS + UR5_CART + ["--blend", "0.03"] +
     [a for c in ("-0.408,-0.273", "-0.408,-0.123", "-0.558,-0.123", "-0.558,-0.273")
      for a in ("--line", "trans(%s,0.281) %s" % (c, UR5_ROT))]),
    ("move_ur5_blend_jerk", "UR5: the square jerk-limited, its corners blended within 3 cm (--blend 0.03 --jerk 5)",
     [UR5, "--q0", UR5_Q0] + UR5_LIMITS + UR5_CART + ["--jerk", "5", "--blend", "0.03"] +
     [a for c in ("-0.408,-0.273", "-0.408,-0.123", "-0.558,-0.123", "-0.558,-0.273")
      for a in ("--line", "trans(%s,0.281) %s" % (c, UR5_ROT))]),
    ("move_ur5_blend_arc", "UR5: a line, an arc and a line, their corners blended within 3 cm (--blend 0.03)",
     [UR5, "--q0", UR5_Q0] + UR5_LIMITS + UR5_CART + ["--blend", "0.03",
      "--line", "trans(-0.408,-0.273,0.281) " + UR5_ROT, "--line", "trans(-0.408,-0.123,0.281) " + UR5_ROT,
      "--arc", "trans(-0.483,-0.07,0.281)", "trans(-0.558,-0.123,0.281) " + UR5_ROT,
      "--line", "trans(-0.558,-0.273,0.281) " + UR5_ROT]),
    ("move_puma_line_joint", "Puma 560: a line, then a joint move back",
     [PUMA, "--q0", "10,-30,45,20,35,-60", "--dt", "0.002", "--vmax", "150", "--amax", "600",
      "--speed", "0.3", "--accel", "1.5", "--rspeed", "90", "--raccel", "360",
      "--line", "trans(0.5,-0.03,1.0) rot(0.557190239,-0.684551001,-0.470030785,56.4282417)",
      "--joint", "10,-30,45,20,35,-60"]),
]


# ---- double FK from the robot file ------------------------------------------

def rot_axis(k, deg):
    k = np.asarray(k, dtype=float)
    k = k / np.linalg.norm(k)
    t = math.radians(deg)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    T = np.eye(4)
    T[:3, :3] = np.eye(3) + math.sin(t) * K + (1 - math.cos(t)) * K @ K
    return T


def trans(x, y, z):
    T = np.eye(4)
    T[:3, 3] = (x, y, z)
    return T


TERMS = {
    "trans": lambda a: trans(*a),
    "rotx": lambda a: rot_axis((1, 0, 0), a[0]),
    "roty": lambda a: rot_axis((0, 1, 0), a[0]),
    "rotz": lambda a: rot_axis((0, 0, 1), a[0]),
    "rot": lambda a: rot_axis(a[:3], a[3]),
}


def eval_expr(s):
    """product of the terms of a base/tool EXPR (trans, rotx, roty, rotz, rot, ident, inv(...))"""
    stack, i = [np.eye(4)], 0
    while i < len(s):
        if s[i] in " *\t":
            i += 1
            continue
        if s[i] == ")":
            top = stack.pop()
            stack[-1] = stack[-1] @ np.linalg.inv(top)
            i += 1
            continue
        m = re.match(r"[a-z]+", s[i:])
        if not m:
            raise ValueError("EXPR %r: unexpected %r" % (s, s[i]))
        name = m.group(0)
        i += len(name)
        if name == "ident":
            continue
        if name == "inv":
            i = s.index("(", i) + 1
            stack.append(np.eye(4))
            continue
        if name not in TERMS:
            raise ValueError("EXPR %r: term %s is not drawn by this script" % (s, name))
        j = s.index(")", i)
        args = [float(v) for v in s[s.index("(", i) + 1:j].split(",")]
        stack[-1] = stack[-1] @ TERMS[name](args)
        i = j + 1
    return stack[0]


def read_robot(path):
    rob = {"conv": "standard", "joints": [], "base": np.eye(4), "tool": np.eye(4)}
    with open(path) as f:
        for line in f:
            line = line.split("#")[0].strip()
            if not line:
                continue
            kw, _, rest = line.partition(" ")
            if kw == "convention":
                rob["conv"] = rest.strip()
            elif kw in ("base", "tool"):
                rob[kw] = eval_expr(rest.strip())
            elif kw == "joint":
                tok = rest.split()
                j = {"type": tok[0], "a": 0.0, "d": 0.0, "alpha": 0.0, "theta": 0.0}
                for t in tok[1:]:
                    k, _, v = t.partition("=")
                    j[k] = float(v)
                rob["joints"].append(j)
    return rob


def fk(rob, q):
    T = rob["base"].copy()
    for j, qi in zip(rob["joints"], q):
        theta, d = j["theta"], j["d"]
        if j["type"] == "R":
            theta += qi
        else:
            d += qi
        if rob["conv"] == "standard":
            A = rot_axis((0, 0, 1), theta) @ trans(0, 0, d) @ trans(j["a"], 0, 0) @ rot_axis((1, 0, 0), j["alpha"])
        else:
            A = rot_axis((1, 0, 0), j["alpha"]) @ trans(j["a"], 0, 0) @ rot_axis((0, 0, 1), theta) @ trans(0, 0, d)
        T = T @ A
    return T @ rob["tool"]


# ---- the figure --------------------------------------------------------------

def read_move_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    head = rows[0]
    if len(head) < 3 or head[0] != "t" or head[-1] != "status":
        raise ValueError("%s: not a `dhmath move` CSV (header %r)" % (path, head))
    t = np.array([float(r[0]) for r in rows[1:]])
    q = np.array([[float(v) for v in r[1:-1]] for r in rows[1:]])
    status = [r[-1] for r in rows[1:]]
    return head[1:-1], t, q, status


def option_values(args, name):
    """the values of --name in a move command line (one or per joint), or None"""
    for k, a in enumerate(args):
        if a == name and k + 1 < len(args):
            return [float(v) for v in args[k + 1].split(",")]
        if a.startswith(name + "="):
            return [float(v) for v in a.split("=", 1)[1].split(",")]
    return None


def plot_move(csv_path, robot_path, out, title=None, vmax=None):
    names, t, q, status = read_move_csv(csv_path)
    rob = read_robot(robot_path)
    if len(rob["joints"]) != len(names):
        raise ValueError("%s has %d joints, the CSV %d" % (robot_path, len(rob["joints"]), len(names)))
    dt = t[0] if len(t) else 1.0
    qd = np.diff(q, axis=0) / dt if len(t) > 1 else np.zeros((0, len(names)))
    p = np.array([fk(rob, qk)[:3, 3] for qk in q])
    bad = np.array([s != "ok" for s in status])
    fig, ax = plt.subplots(2, 2, figsize=(11, 8))
    for i, nm in enumerate(names):
        ax[0, 0].plot(t, q[:, i], label=nm)
        if len(qd):
            ax[0, 1].plot(t[1:], qd[:, i], label=nm)
    if vmax:
        for v in sorted(set(vmax)):
            ax[0, 1].axhline(v, color="k", ls="--", lw=0.8)
            ax[0, 1].axhline(-v, color="k", ls="--", lw=0.8)
    ax[0, 0].set_title("joint positions")
    ax[0, 0].set_xlabel("t (s)")
    ax[0, 0].set_ylabel("q (deg / length unit)")
    ax[0, 0].legend(fontsize=7, ncol=2)
    ax[0, 1].set_title("joint velocities (finite differences)" + (", dashed: vmax" if vmax else ""))
    ax[0, 1].set_xlabel("t (s)")
    ax[0, 1].set_ylabel("dq/dt (deg/s / length unit/s)")
    for k, (a, b, lab) in enumerate(((0, 1, "XY"), (0, 2, "XZ"))):
        axp = ax[1, k]
        axp.plot(p[:, a], p[:, b], "-", color="tab:blue", lw=1.2, label="tool path")
        axp.plot(p[:1, a], p[:1, b], "o", color="tab:green", label="start")
        axp.plot(p[-1:, a], p[-1:, b], "s", color="tab:purple", label="end")
        if bad.any():
            axp.plot(p[bad, a], p[bad, b], ".", color="tab:red", ms=3, label="lagging / unreachable")
        axp.set_aspect("equal", adjustable="datalim")
        axp.set_title("tool path, %s projection (base frame)" % lab)
        axp.set_xlabel("xyz"[a])
        axp.set_ylabel("xyz"[b])
        axp.legend(fontsize=7)
    fig.suptitle(title or os.path.basename(csv_path))
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)
    return len(t), int(bad.sum())


# ---- docs ------------------------------------------------------------------------

def run(cmd, **kw):
    print("+", " ".join(shlex.quote(c) for c in cmd), flush=True)
    return subprocess.run(cmd, **kw)


def docs(cli):
    if not os.path.exists(cli):
        build = os.path.join(ROOT, "build", "host")
        run(["cmake", "--preset", "host"], cwd=ROOT, check=True)
        run(["cmake", "--build", build, "-j2", "--target", "dhmath_cli"], cwd=ROOT, check=True)
    img = os.path.join(ROOT, "docs", "generated", "img")
    os.makedirs(img, exist_ok=True)
    page = os.path.join(ROOT, "docs", "generated", "motion_plots.md")
    lines = ["# Motion plots (`dhmath move`)", "",
             "Generated by `/usr/bin/python3 tools/plot_move.py --docs` (or `tools/gen_docs.sh motion`):",
             "each command below ran through the CLI, and its CSV was drawn by `tools/plot_move.py`",
             "(joint positions, joint velocities by finite differences, the tool path by a double FK",
             "of the robot file's DH table). The commands are those of [docs/motion.md](../motion.md).", ""]
    with tempfile.TemporaryDirectory() as tmp:
        for name, title, args in EXAMPLES:
            csv_path = os.path.join(tmp, name + ".csv")
            with open(csv_path, "w") as f:
                r = run([cli, "move"] + args, cwd=ROOT, stdout=f, stderr=subprocess.PIPE, text=True)
            if r.returncode not in (0, 3):
                sys.exit("plot_move.py: dhmath move failed (%d): %s" % (r.returncode, r.stderr))
            periods, bad = plot_move(csv_path, os.path.join(ROOT, args[0]), os.path.join(img, name + ".png"), title,
                                     option_values(args, "--vmax"))
            lines += ["## " + title, "", "```", "$ dhmath move " + " ".join(shlex.quote(a) for a in args), "```", "",
                      "Exit status %d, %d control periods (%.3f s), %d of them lagging or unreachable." %
                      (r.returncode, periods, periods * float(option_values(args, "--dt")[0]), bad), ""]
            if r.stderr:
                lines += ["stderr: `%s`" % r.stderr.strip(), ""]
            lines += ["![%s](img/%s.png)" % (title, name), ""]
    with open(page, "w") as f:
        f.write("\n".join(lines))
    run(["sh", os.path.join(ROOT, "tools", "stamp.sh"), "tools/plot_move.py", page], check=True)
    print("wrote docs/generated/motion_plots.md and docs/generated/img/move_*.png")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("csv", nargs="?")
    ap.add_argument("robot", nargs="?")
    ap.add_argument("out", nargs="?")
    ap.add_argument("--title")
    ap.add_argument("--docs", action="store_true", help="regenerate the plots of docs/motion.md")
    ap.add_argument("--cli", default=os.path.join(ROOT, "build", "host", "cli", "dhmath"))
    a = ap.parse_args()
    if a.docs:
        docs(a.cli)
        return 0
    if not (a.csv and a.robot and a.out):
        ap.error("CSV ROBOT OUT.png (or --docs)")
    periods, bad = plot_move(a.csv, a.robot, a.out, a.title)
    print("%s: %d periods, %d not ok" % (a.out, periods, bad))
    return 0


if __name__ == "__main__":
    sys.exit(main())
