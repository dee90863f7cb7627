#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Runs a firmware example (under QEMU) and checks its output against an
independent double-precision computation with numpy.

  check_output.py --robot ROBOT.dh --kind fixed|fixedkin|float [--qpos-frac N] -- CMD...

The reference never uses the library: the robot is read from its .dh file
(the published DH table), the FK is the product of standard DH link
transforms Rz(theta) Tz(d) Tx(a) Rx(alpha) in double precision, and Euler
angles come from the closed-form Z-Y-X formulas. Tolerances are the error
bounds named below (contracts in include/dhmath/), not fitted to the output.
"""
import argparse
import math
import subprocess
import sys

import numpy as np

# dh_fk_q (include/dhmath/robot.h): example robots in mm, DH_QPOS_FRAC 16
FIXED_TOL_MM = 5e-4
FIXED_TOL_Q30_LSB = 64
# dh_fk_f32: measured 3.0e-7 m / 3.1e-7 per entry for the example robots in
# metres; the check allows about 3 times that
FLOAT_FK_TOL = 1e-6
# dh_mat3_to_euler_f32: angles within 2.5e-5 deg of the exact ones (middle
# angle >= 1 deg from a pole), plus what the FK's rotation error moves them
EULER_ALGO_TOL_DEG = 2.5e-5
# fw_float_ik sets tol_pos 1e-6 m; tol_rot 1e-5 rad is the default (met against the
# float FK, which differs from the exact one by FLOAT_FK_TOL)
IK_TOL_POS = 1e-6
IK_TOL_ROT = 1e-5
# dh_ikc_q (include/dhmath/ikc.h): every solution within 5e-3 mm and
# 5e-6 rad of the target; the generating configuration within 2e-3 deg
IKC_Q_TOL_MM = 5e-3
IKC_Q_TOL_RAD = 5e-6
IKC_Q_TOL_DEG = 2e-3
# dh_frame_to_euler_q (include/dhmath/rot.h): 2e-5 deg (middle angle >= 1
# deg from a pole) plus 1 LSB of Q16.16
EULER_Q_TOL_DEG = 2e-5 + 1.0 / 65536.0


def read_dh(path):
    rows = []
    with open(path) as f:
        for line in f:
            words = line.split('#', 1)[0].split()
            if not words:
                continue
            if words[0] == 'convention':
                if words[1] != 'standard':
                    sys.exit('check_output.py: only standard DH tables are supported')
                continue
            if words[0] != 'joint' or words[1] != 'R':
                sys.exit('check_output.py: unexpected line in %s: %s' % (path, line.strip()))
            kv = dict(w.split('=', 1) for w in words[2:])
            rows.append({k: float(v) for k, v in kv.items()})
    return rows


def fk(rows, q_deg):
    T = np.eye(4)
    for row, q in zip(rows, q_deg):
        th = math.radians(q + row.get('theta', 0.0))
        al = math.radians(row.get('alpha', 0.0))
        ct, st, ca, sa = math.cos(th), math.sin(th), math.cos(al), math.sin(al)
        A = np.array([[ct, -st * ca, st * sa, row.get('a', 0.0) * ct],
                      [st, ct * ca, -ct * sa, row.get('a', 0.0) * st],
                      [0.0, sa, ca, row.get('d', 0.0)],
                      [0.0, 0.0, 0.0, 1.0]])
        T = T @ A
    return T


def zyx_deg(R):
    """Intrinsic Z-Y-X angles (yaw, pitch, roll) of R = Rz Ry Rx."""
    return [math.degrees(math.atan2(R[1, 0], R[0, 0])),
            math.degrees(math.asin(max(-1.0, min(1.0, -R[2, 0])))),
            math.degrees(math.atan2(R[2, 1], R[2, 2]))]


def rot_angle(Ra, Rb):
    c = (np.trace(Ra.T @ Rb) - 1.0) / 2.0
    return math.acos(max(-1.0, min(1.0, c)))


class Checker:
    def __init__(self):
        self.failures = 0
        self.checks = 0

    def near(self, what, got, want, tol):
        got, want = np.asarray(got, float), np.asarray(want, float)
        err = float(np.max(np.abs(got - want))) if got.size else 0.0
        self.checks += 1
        ok = got.shape == want.shape and err <= tol
        print('%-4s %s: max |err| %.3g (tol %.3g)' % ('ok' if ok else 'FAIL', what, err, tol))
        if not ok:
            print('     got  %s\n     want %s' % (got.tolist(), want.tolist()))
            self.failures += 1

    def true(self, what, cond):
        self.checks += 1
        print('%-4s %s' % ('ok' if cond else 'FAIL', what))
        if not cond:
            self.failures += 1


def parse(out):
    lines = []
    for line in out.splitlines():
        if ':' in line:
            key, rest = line.split(':', 1)
            lines.append((key.strip(), rest.split()))
    return lines


def check_fixed(rows, lines, frac, c, qkey='q_deg', qone=1.0):
    one_pos, one_rot = float(1 << frac), float(1 << 30)
    n = 0
    for i, (key, vals) in enumerate(lines):
        if key != qkey:
            continue
        q = [float(v) / qone for v in vals]
        T = fk(rows, q)
        (pk, pv), (rk, rv) = (lines[i + 1:i + 3] + [('', []), ('', [])])[:2]
        c.true('lines after %s %s are p_qpos and r_q30' % (qkey, vals), pk == 'p_qpos' and rk == 'r_q30')
        if pk != 'p_qpos' or rk != 'r_q30':
            continue
        p = [int(v) / one_pos for v in pv]
        r = [int(v) / one_rot for v in rv]
        c.near('q %s position (mm)' % vals, p, T[:3, 3], FIXED_TOL_MM)
        c.near('q %s rotation (Q2.30 LSB)' % vals, np.array(r) * one_rot,
               T[:3, :3].reshape(9) * one_rot, FIXED_TOL_Q30_LSB)
        n += 1
    c.true('%d configurations printed' % n, n == 3)


def check_fixed_kin(rows, lines, frac, c):
    one_pos, one_rot, one_deg = float(1 << frac), float(1 << 30), 65536.0
    check_fixed(rows, lines, frac, c, 'q_q16', one_deg)
    d = {}
    for key, vals in lines:
        d.setdefault(key, []).append([int(v) for v in vals])
    need = ['q_q16', 'euler_zyx_q16', 'ikc_sol_q16', 'ikc_nearest', 'ikq_status', 'ikq_q16', 'ikq_tol']
    missing = [k for k in need if k not in d]
    c.true('every output line present (missing: %s)' % (missing or 'none'), not missing)
    if missing or len(d['q_q16']) < 2:
        return
    q_goal = [v / one_deg for v in d['q_q16'][1]]
    T = fk(rows, q_goal)
    ref = zyx_deg(T[:3, :3])
    tol = EULER_Q_TOL_DEG + math.degrees(2.0 * FIXED_TOL_Q30_LSB / one_rot / math.cos(math.radians(ref[1])))
    c.near('Euler ZYX of the FK pose (deg)', [v / one_deg for v in d['euler_zyx_q16'][0]], ref, tol)

    def reaches(what, q, tol_mm, tol_rad):
        Tq = fk(rows, q)
        c.near('%s reaches the target position (mm)' % what, Tq[:3, 3], T[:3, 3], tol_mm)
        c.near('%s reaches the target orientation (rad)' % what, [rot_angle(T[:3, :3], Tq[:3, :3])], [0.0],
               tol_rad)
        c.true('%s within the joint limits of the .dh file' % what,
               all(row['min'] <= qi <= row['max'] for row, qi in zip(rows, q)))

    # the target is dh_fk_q's frame: its error (FIXED_TOL_MM, 64 LSB per
    # entry, at most about 2 x 64 LSB in angle) adds to every bound
    fk_rad = 2.0 * FIXED_TOL_Q30_LSB / one_rot
    sols = [[v / one_deg for v in s_] for s_ in d['ikc_sol_q16']]
    for k, q in enumerate(sols):
        reaches('closed-form solution %d' % k, q, IKC_Q_TOL_MM + FIXED_TOL_MM, IKC_Q_TOL_RAD + fk_rad)
    near = d['ikc_nearest'][0][0]
    c.true('nearest solution index %d valid' % near, 0 <= near < len(sols))
    if 0 <= near < len(sols):
        c.near('nearest closed-form solution is the generating configuration (deg)', sols[near], q_goal,
               IKC_Q_TOL_DEG)
    c.true('numerical IK status DH_OK (got %d)' % d['ikq_status'][0][0], d['ikq_status'][0][0] == 0)
    tol_pos, tol_rot = d['ikq_tol'][0][0] / one_pos, d['ikq_tol'][0][1] / one_rot
    reaches('numerical IK solution', [v / one_deg for v in d['ikq_q16'][0]],
            tol_pos + 2.0 * FIXED_TOL_MM, tol_rot + 2.0 * fk_rad)


def check_float(rows, lines, c):
    d = {}
    for key, vals in lines:
        d[key] = vals
    need = ['fk_q', 'fk_p', 'fk_r', 'euler_zyx', 'ik_goal_q', 'ik_target_p', 'ik_target_zyx', 'ik_status', 'ik_q']
    missing = [k for k in need if k not in d]
    c.true('every output line present (missing: %s)' % (missing or 'none'), not missing)
    if missing:
        return
    num = {k: [float(v) for v in d[k]] for k in need if k != 'ik_status'}
    T = fk(rows, num['fk_q'])
    c.near('FK position (m)', num['fk_p'], T[:3, 3], FLOAT_FK_TOL)
    c.near('FK rotation', num['fk_r'], T[:3, :3].reshape(9), FLOAT_FK_TOL)
    ref = zyx_deg(T[:3, :3])
    cp = math.cos(math.radians(ref[1]))
    tol = EULER_ALGO_TOL_DEG + math.degrees(2.0 * FLOAT_FK_TOL / cp)
    c.near('Euler ZYX of the FK pose (deg)', num['euler_zyx'], ref, tol)
    # IK: the target is the FK of ik_goal_q (a reachable pose)
    Tgoal = fk(rows, num['ik_goal_q'])
    c.near('IK target position (m)', num['ik_target_p'], Tgoal[:3, 3], FLOAT_FK_TOL)
    ref = zyx_deg(Tgoal[:3, :3])
    tol = EULER_ALGO_TOL_DEG + math.degrees(2.0 * FLOAT_FK_TOL / math.cos(math.radians(ref[1])))
    c.near('Euler ZYX of the IK target (deg)', num['ik_target_zyx'], ref, tol)
    Tik = fk(rows, num['ik_q'])
    c.near('FK of the IK solution reaches the target position (m)', Tik[:3, 3], Tgoal[:3, 3],
           IK_TOL_POS + 2.0 * FLOAT_FK_TOL)
    # rotation angle between two rotations whose entries differ by e is at
    # most about 2 e (entry errors of both float FKs: 2 FLOAT_FK_TOL each)
    c.near('FK of the IK solution reaches the target orientation (rad)',
           [rot_angle(Tgoal[:3, :3], Tik[:3, :3])], [0.0], IK_TOL_ROT + 4.0 * FLOAT_FK_TOL)
    inside = all(row['min'] <= qi <= row['max'] for row, qi in zip(rows, num['ik_q']))
    c.true('IK solution within the joint limits of the .dh file', inside)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--robot', required=True)
    ap.add_argument('--kind', choices=['fixed', 'fixedkin', 'float'], required=True)
    ap.add_argument('--qpos-frac', type=int, default=16)
    ap.add_argument('cmd', nargs=argparse.REMAINDER)
    a = ap.parse_args()
    cmd = [w for w in a.cmd if w != '--']
    try:
        run = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             timeout=300, universal_newlines=True)
    except subprocess.TimeoutExpired:
        sys.exit('check_output.py: %s timed out' % cmd[-1])
    print(run.stdout)
    c = Checker()
    c.true('exit status 0 (got %d)' % run.returncode, run.returncode == 0)
    rows = read_dh(a.robot)
    lines = parse(run.stdout)
    if a.kind == 'fixed':
        check_fixed(rows, lines, a.qpos_frac, c)
    elif a.kind == 'fixedkin':
        check_fixed_kin(rows, lines, a.qpos_frac, c)
    else:
        check_float(rows, lines, c)
    print('%d of %d checks passed' % (c.checks - c.failures, c.checks))
    return 1 if c.failures else 0


if __name__ == '__main__':
    sys.exit(main())
