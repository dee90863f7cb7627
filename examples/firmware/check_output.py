#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Runs a firmware example (under QEMU) and checks its output against an
independent double-precision computation with numpy.

  check_output.py --robot ROBOT.dh --kind fixed|fixedkin|fixedtrack|fixedmotion|float|floatmotion [--qpos-frac N]
                  -- CMD...

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
# dh_rot_error_q (include/dhmath/kin.h): within 6.3e-7 rad of the exact
# rotation vector of the frames given
ROT_ERROR_Q_TOL_RAD = 6.3e-7
# fw_fixed_track: the UR5's joint speed (Universal Robots, UR5 technical
# specification), every joint, and the control period
TRACK_VMAX_DEG_S = 180.0
TRACK_DT_US = 1000
# its line passes within this distance of the singular configuration's position
TRACK_SING_DIST_MM = 1.0
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
    """Angle of Ra^T Rb: atan2 of its skew and symmetric parts (acos of the
    trace alone loses the angles below about 1e-7 rad)."""
    M = Ra.T @ Rb
    s = math.sqrt((M[2, 1] - M[1, 2]) ** 2 + (M[0, 2] - M[2, 0]) ** 2 + (M[1, 0] - M[0, 1]) ** 2)
    return math.atan2(s, np.trace(M) - 1.0)


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


def line_dist(a, b, p):
    """Distance from point p to the segment a-b."""
    ab, ap = b - a, p - a
    t = max(0.0, min(1.0, float(ap @ ab) / float(ab @ ab)))
    return float(np.linalg.norm(ap - t * ab))


def check_fixed_track(rows, lines, frac, c):
    """fw_fixed_track: every step within its bound (recomputed here from the
    trace), every OK period within the tolerances of the double FK, the
    line near the wrist singularity, the last target reached."""
    one_pos, one_rot, one_deg = float(1 << frac), float(1 << 30), 65536.0
    d, trace = {}, []
    for key, vals in lines:
        if key == 'k':
            trace.append([int(v) for v in vals])
        else:
            d[key] = [int(v) for v in vals]
    need = ['dt_us', 'vmax_q16', 'bound_q16', 'sing_q16', 'sing_p_qpos', 'line_r_q30', 'line_off_qpos',
            'line_step_qpos', 'line_n', 'max_step_q16', 'periods', 'final']
    missing = [k for k in need if k not in d]
    c.true('every output line present (missing: %s)' % (missing or 'none'), not missing)
    if missing or not trace:
        return
    n = len(rows)
    c.true('control period %d us' % d['dt_us'][0], d['dt_us'][0] == TRACK_DT_US)
    vmax_q = [int(round(TRACK_VMAX_DEG_S * one_deg))] * n
    c.true('vmax %g deg/s on every joint (Q16.16 %s)' % (TRACK_VMAX_DEG_S, d['vmax_q16']), d['vmax_q16'] == vmax_q)
    bound = [v * TRACK_DT_US // 1000000 for v in vmax_q]
    c.true('step bound floor(vmax dt) = %s LSB (%.6f deg)' % (bound, bound[0] / one_deg), d['bound_q16'] == bound)
    # the path: Ts = FK(QS), a line through Ts.p + off with Ts's rotation
    qs = [v / one_deg for v in d['sing_q16']]
    Ts = fk(rows, qs)
    c.near('FK of the configuration near the singularity (mm)', [v / one_pos for v in d['sing_p_qpos']],
           Ts[:3, 3], FIXED_TOL_MM)
    R = np.array(d['line_r_q30'], float).reshape(3, 3) / one_rot
    c.near('rotation of the targets (Q2.30 LSB)', R.reshape(9) * one_rot, Ts[:3, :3].reshape(9) * one_rot,
           FIXED_TOL_Q30_LSB)
    N = d['line_n'][0]
    base = np.array(d['sing_p_qpos'], float) + np.array(d['line_off_qpos'], float)
    step = np.array(d['line_step_qpos'], float)

    def target(k):
        return (base + (min(k, N) - N // 2) * step) / one_pos
    q0 = list(qs)
    q0[4] = 0.0
    S = fk(rows, q0)
    dist = line_dist(target(0), target(N), S[:3, 3])
    c.true('joint 5 of QS %.3g deg from 0' % qs[4], abs(qs[4]) <= 0.5)
    c.true('the line passes %.3f mm (<= %g) from the position of QS with joint 5 at 0 (the wrist '
           'singularity), rotation %.3g deg from it' % (dist, TRACK_SING_DIST_MM,
                                                         math.degrees(rot_angle(R, S[:3, :3]))),
           dist <= TRACK_SING_DIST_MM)
    # the trace: periods 0, 1, ... consecutive
    c.true('periods numbered 0..%d in order' % (len(trace) - 1),
           [t[0] for t in trace] == list(range(len(trace))))
    c.true('the line\'s %d periods all run' % N, len(trace) >= N + 1)
    qk = [[v for v in t[2:]] for t in trace]
    steps = np.abs(np.diff(np.array(qk, dtype=np.int64), axis=0)).max(axis=0).tolist()
    c.true('largest step per joint %s LSB = the printed %s' % (steps, d['max_step_q16']),
           steps == d['max_step_q16'])
    c.true('largest step %d LSB (%.6f deg) <= bound %d LSB (vmax dt)' % (max(steps), max(steps) / one_deg,
                                                                        bound[0]),
           all(s_ <= b for s_, b in zip(steps, bound)))
    c.true('every configuration within the joint limits of the .dh file',
           all(row['min'] <= v / one_deg <= row['max'] for q in qk for row, v in zip(rows, q)))
    states = [t[1] for t in trace[1:]]
    counts = [states.count(0), states.count(1), states.count(2)]
    c.true('ok / lagging / unreachable periods %s = the printed %s' % (counts, d['periods'][:3]),
           counts == d['periods'][:3])
    q5min = min(abs(q[4]) for q in qk) / one_deg
    c.true('joint 5 passes %.4f deg from 0 (<= |QS joint 5|)' % q5min, q5min <= abs(qs[4]))
    pos_tol, rot_tol = d['final'][3] / one_pos, d['final'][4] / float(1 << 29)
    fk_rad = 2.0 * FIXED_TOL_Q30_LSB / one_rot
    worst_p = worst_r = 0.0
    for k, (t, q) in enumerate(zip(trace, qk)):
        if t[1] != 0:
            continue
        T = fk(rows, [v / one_deg for v in q])
        worst_p = max(worst_p, float(np.linalg.norm(T[:3, 3] - target(k))))
        worst_r = max(worst_r, rot_angle(R, T[:3, :3]))
    c.true('every OK period reaches its target in double: position %.2e mm (tol %.2e), rotation %.2e rad '
           '(tol %.2e)' % (worst_p, pos_tol + FIXED_TOL_MM, worst_r, rot_tol + fk_rad),
           worst_p <= pos_tol + FIXED_TOL_MM and worst_r <= rot_tol + fk_rad)
    # the end: the last target reached, the reported errors the double FK's
    c.true('final state OK (got %d), the last period\'s' % d['final'][0],
           d['final'][0] == 0 and trace[-1][1] == 0)
    T = fk(rows, [v / one_deg for v in qk[-1]])
    ep, er = float(np.linalg.norm(T[:3, 3] - target(len(trace) - 1))), rot_angle(R, T[:3, :3])
    if len(d['final']) > 5 and d['final'][5] == 0:
        # not measured: the closed form's bounds (track.h), which the double FK keeps
        c.true('final errors are the closed form\'s bounds %.2e mm, %.2e rad (not measured), the double FK\'s '
               '%.2e mm, %.2e rad within them' % (d['final'][1] / one_pos, d['final'][2] / float(1 << 29), ep, er),
               d['final'][2] == 2685 and ep <= d['final'][1] / one_pos + FIXED_TOL_MM and
               er <= d['final'][2] / float(1 << 29) + fk_rad)
    else:
        c.near('final position error (mm) against the double FK', [d['final'][1] / one_pos], [ep],
               FIXED_TOL_MM + 1.0 / one_pos)
        c.near('final rotation error (rad) against the double FK', [d['final'][2] / float(1 << 29)], [er],
               fk_rad + ROT_ERROR_Q_TOL_RAD + 1.0 / (1 << 29))


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


# fw_float_motion: the path's own error (dh_path_eval_f32, dh_blend_seq_eval_f32:
# within 4 FLT_EPSILON S of the line, S the largest position magnitude, here
# below 1 m), the acceleration window (periods) the firmware prints
MOTION_PATH_TOL = 4.0 * 2.0 ** -23
MOTION_W = 4


def square_devs(p, corners, ovl, end):
    """the largest distances of the tool points p[1..end] from the square's
    outline outside the overlaps ovl (corner, first, last period) and from
    the corner inside them"""
    inside = {}
    for i, k0, k1 in ovl:
        for k in range(k0, k1 + 1):
            inside[k] = i
    line_dev = blend_dev = 0.0
    for k in range(1, end + 1):
        if k in inside:
            blend_dev = max(blend_dev, float(np.linalg.norm(p[k] - corners[inside[k]])))
        else:
            line_dev = max(line_dev, min(line_dist(corners[i], corners[i + 1], p[k]) for i in range(4)))
    return line_dev, blend_dev


def check_float_motion(rows, lines, c):
    """fw_float_motion: every period's configuration, FK in double."""
    one, qs, corners, ovl = {}, [], {}, []
    for key, vals in lines:
        if key == 'q':
            qs.append((int(vals[0]), int(vals[1]), [float(v) for v in vals[2:]]))
        elif key == 'corner':
            corners[int(vals[0])] = np.array([float(v) for v in vals[1:]])
        elif key == 'overlap':
            ovl.append((int(vals[0]), int(vals[1]), int(vals[2])))
        else:
            one[key] = vals
    need = ['dt', 'vmax', 'amax', 'pos_tol', 'lim', 'radius', 'q0', 'p0', 'circle', 'square_end', 'line_dev',
            'blend_dev', 'circle_dev', 'peak_rate', 'peak_accel', 'periods']
    missing = [k for k in need if k not in one]
    c.true('every summary line present (missing: %s)' % (missing or 'none'), not missing)
    c.true('corners 0..4 and three overlaps printed', sorted(corners) == [0, 1, 2, 3, 4] and len(ovl) == 3)
    if missing or len(corners) != 5 or len(ovl) != 3:
        return
    f = {k: [float(v) for v in one[k]] for k in need}
    dt, vmax, amax, pos_tol, radius = f['dt'][0], f['vmax'][0], f['amax'][0], f['pos_tol'][0], f['radius'][0]
    c.true('periods numbered 0, 1, 2, ... (%d printed)' % len(qs), [k for k, _, _ in qs] == list(range(len(qs))))
    c.true('every period ok (periods: %s)' % ' '.join(one['periods']),
           all(s == 0 for _, s, _ in qs) and f['periods'] == [len(qs), 0, 0])
    q = np.array([v for _, _, v in qs])
    c.near('period 0 is q0', q[0], f['q0'], 0.0)
    p = np.array([fk(rows, qi)[:3, 3] for qi in q])
    c.near('p0 is the FK of q0 (m)', f['p0'], p[0], FLOAT_FK_TOL)
    p0 = np.array(f['p0'])
    side = float(corners[1][0] - corners[0][0])
    want = [p0 + np.array(o) for o in ((0, 0, 0), (side, 0, 0), (side, side, 0), (0, side, 0), (0, 0, 0))]
    c.near('the corners: a square of side %.9g m from p0' % side, [corners[i] for i in range(5)], want, 1e-7)
    # tracked within the tracker's tolerance (against its float FK), which is
    # within FLOAT_FK_TOL of this exact FK, of a path point within MOTION_PATH_TOL
    tol = pos_tol + FLOAT_FK_TOL + MOTION_PATH_TOL
    end = int(f['square_end'][0])
    line_dev, blend_dev = square_devs(p, corners, ovl, end)
    circle_dev = 0.0
    ctr, rad = np.array(f['circle'][:3]), f['circle'][3]
    c.near('the circle: centre p0 + (R, 0, 0) (m)', ctr, p0 + np.array([rad, 0.0, 0.0]), 1e-7)
    for k in range(end + 1, len(qs)):
        u = p[k] - ctr
        circle_dev = max(circle_dev, math.hypot(math.hypot(u[0], u[1]) - rad, u[2]))
    c.near('square outside the overlaps: on its outline (m)', [line_dev], [0.0], tol)
    c.true('square inside the overlaps: within the blend radius of the corner (%.3g m <= %.3g m + %.3g m)'
           % (blend_dev, radius, tol), blend_dev <= radius + tol)
    c.near('circle: on it (m)', [circle_dev], [0.0], tol)
    c.near('the end: back at p0 (m)', p[-1], p0, tol)
    # the firmware's own figures (float FK) against these (double FK)
    c.near('printed line_dev, blend_dev, circle_dev against the double FK (m)',
           [f['line_dev'][0], f['blend_dev'][0], f['circle_dev'][0]], [line_dev, blend_dev, circle_dev],
           2.0 * FLOAT_FK_TOL)
    # rates: every step within vmax dt; acceleration over windows of
    # MOTION_W periods within amax, plus what the rounding of the float
    # joints (half an ulp each, at most 2W of them) adds to the window's
    # second difference
    dq = np.abs(np.diff(q, axis=0))
    rate = float(np.max(dq)) / dt
    c.true('peak joint rate %.6g deg/s within vmax %.6g deg/s' % (rate, vmax), rate <= vmax * (1.0 + 1e-6))
    c.near('printed peak_rate (deg/s)', [f['peak_rate'][0]], [rate], 1e-5 * vmax)
    w = MOTION_W
    acc = np.abs(q[2 * w:] - 2.0 * q[w:-w] + q[:-2 * w]) / (w * dt) ** 2
    ulp = 2.0 ** (math.floor(math.log2(float(np.max(np.abs(q))))) - 23)
    peak = float(np.max(acc))
    c.true('peak joint acceleration %.6g deg/s^2 (windows of %d periods) within amax %.6g deg/s^2 + rounding %.3g'
           % (peak, w, amax, ulp / (w * dt * dt)), peak <= amax * (1.0 + 1e-6) + ulp / (w * dt * dt))
    c.near('printed peak_accel (deg/s^2)', [f['peak_accel'][0]], [peak], 1e-4 * amax)


# fw_fixed_motion: the fixed paths' own error (dh_blend_seq_eval_q: 1 LSB off
# its line, 2 LSB + 32 2^-30 (L_k + L_k+1) beyond the plan's dev in an
# overlap; dh_path_eval_q on the arc: 4 LSB + 2^-26 R), at most this in mm
# for these moves (lines of 100 mm, a circle of 50 mm) at Q16.16 and finer
FIXED_MOTION_PATH_TOL_MM = 1e-3
# the acceleration window (periods) the firmware prints
FIXED_MOTION_W = 4


def check_fixed_motion(rows, lines, frac, c):
    """fw_fixed_motion: every period's configuration, FK in double."""
    one_pos, one_deg = float(1 << frac), 65536.0
    one, qs, corners, ovl, devs = {}, [], {}, [], {}
    for key, vals in lines:
        v = [int(x) for x in vals]
        if key == 'q':
            qs.append((v[0], v[1], [x / one_deg for x in v[2:]], v[2:]))
        elif key == 'corner':
            corners[v[0]] = np.array(v[1:], float) / one_pos
        elif key == 'overlap':
            ovl.append((v[0], v[1], v[2]))
        elif key == 'dev_qpos':
            devs[v[0]] = v[1] / one_pos
        else:
            one[key] = v
    need = ['dt_us', 'vmax_q16', 'amax_q16', 'bound_q16', 'pos_tol_qpos', 'lim_qpos', 'radius_qpos', 'q0_q16',
            'p0_qpos', 'circle', 'square_end', 'line_dev_qpos', 'blend_dev_qpos', 'circle_dev_qpos', 'peak_step_q16',
            'peak_acc_q16', 'periods']
    missing = [k for k in need if k not in one]
    c.true('every summary line present (missing: %s)' % (missing or 'none'), not missing)
    c.true('corners 0..4, three overlaps and their dev printed',
           sorted(corners) == [0, 1, 2, 3, 4] and len(ovl) == 3 and sorted(devs) == [1, 2, 3])
    if missing or len(corners) != 5 or len(ovl) != 3 or sorted(devs) != [1, 2, 3]:
        return
    dt = one['dt_us'][0] * 1e-6
    vmax, amax = one['vmax_q16'][0] / one_deg, one['amax_q16'][0] / one_deg
    radius, pos_tol = one['radius_qpos'][0] / one_pos, one['pos_tol_qpos'][0] / one_pos
    c.true('periods numbered 0, 1, 2, ... (%d printed)' % len(qs), [k for k, _, _, _ in qs] == list(range(len(qs))))
    c.true('every period ok (periods: %s)' % one['periods'],
           all(s_ == 0 for _, s_, _, _ in qs) and one['periods'] == [len(qs), 0, 0])
    qi = np.array([r for _, _, _, r in qs], dtype=np.int64)
    q = np.array([r for _, _, r, _ in qs])
    c.true('period 0 is q0', list(qi[0]) == one['q0_q16'])
    p = np.array([fk(rows, x)[:3, 3] for x in q])
    p0 = np.array(one['p0_qpos'], float) / one_pos
    c.near('p0 is the FK of q0 (mm)', p0, p[0], FIXED_TOL_MM)
    side = float(corners[1][0] - corners[0][0])
    want = [p0 + np.array(o) for o in ((0, 0, 0), (side, 0, 0), (side, side, 0), (0, side, 0), (0, 0, 0))]
    c.near('the corners: a square of side %.9g mm from p0' % side, [corners[i] for i in range(5)], want, 0.0)
    c.true('each corner\'s planned deviation within the radius (%s mm <= %g mm)' %
           ([devs[i] for i in (1, 2, 3)], radius), all(devs[i] <= radius for i in (1, 2, 3)))
    # tracked within the tracker's tolerance (against its fixed FK, within
    # FIXED_TOL_MM of this exact FK) of a path point within the path's error
    tol = pos_tol + FIXED_TOL_MM + FIXED_MOTION_PATH_TOL_MM
    end = one['square_end'][0]
    line_dev, blend_dev = square_devs(p, corners, ovl, end)
    circle_dev = 0.0
    ctr, rad = np.array(one['circle'][:3], float) / one_pos, one['circle'][3] / one_pos
    c.near('the circle: centre p0 + (R, 0, 0) (mm)', ctr, p0 + np.array([rad, 0.0, 0.0]), 0.0)
    for k in range(end + 1, len(qs)):
        u = p[k] - ctr
        circle_dev = max(circle_dev, math.hypot(math.hypot(u[0], u[1]) - rad, u[2]))
    c.near('square outside the overlaps: on its outline (mm)', [line_dev], [0.0], tol)
    c.true('square inside the overlaps: within the blend radius of the corner (%.4g mm <= %.4g mm + %.3g mm)'
           % (blend_dev, radius, tol), blend_dev <= radius + tol)
    c.near('circle: on it (mm)', [circle_dev], [0.0], tol)
    c.near('the end: back at p0 (mm)', p[-1], p0, tol)
    # the firmware's own figures (fixed FK, integer square roots rounded up)
    c.near('printed line_dev, blend_dev, circle_dev against the double FK (mm)',
           [one['line_dev_qpos'][0] / one_pos, one['blend_dev_qpos'][0] / one_pos,
            one['circle_dev_qpos'][0] / one_pos], [line_dev, blend_dev, circle_dev], 2.0 * FIXED_TOL_MM)
    # rates: every step within the tracker's bound floor(vmax dt); the
    # acceleration over windows of W periods within amax (the fixed
    # tracker's acceleration bound per period, floor(floor(amax dt) dt),
    # holds each period; a window's second difference is the sum of W
    # periods' changes of step, so also within amax (W dt)^2)
    bound = one['bound_q16']
    steps = np.abs(np.diff(qi, axis=0))
    peak = int(steps.max())
    c.true('peak step %d LSB (%.6g deg/s) within the bound %d LSB = floor(vmax dt) (vmax %.6g deg/s)'
           % (peak, peak / one_deg / dt, bound[0], vmax), all(int(steps[:, j].max()) <= bound[j] for j in range(6))
           and bound[0] <= vmax * one_deg * dt)
    c.true('printed peak_step %d LSB = the largest step' % one['peak_step_q16'][0], one['peak_step_q16'][0] == peak)
    w = FIXED_MOTION_W
    acc = np.abs(qi[2 * w:] - 2 * qi[w:-w] + qi[:-2 * w])
    pa = int(acc.max())
    c.true('peak joint acceleration %.6g deg/s^2 (windows of %d periods) within amax %.6g deg/s^2'
           % (pa / one_deg / (w * dt) ** 2, w, amax), pa / one_deg <= amax * (w * dt) ** 2)
    c.true('printed peak_acc %d LSB = the largest windowed second difference' % one['peak_acc_q16'][0],
           one['peak_acc_q16'][0] == pa)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--robot', required=True)
    ap.add_argument('--kind', choices=['fixed', 'fixedkin', 'fixedtrack', 'fixedmotion', 'float', 'floatmotion'],
                    required=True)
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
    elif a.kind == 'fixedtrack':
        check_fixed_track(rows, lines, a.qpos_frac, c)
    elif a.kind == 'floatmotion':
        check_float_motion(rows, lines, c)
    elif a.kind == 'fixedmotion':
        check_fixed_motion(rows, lines, a.qpos_frac, c)
    else:
        check_float(rows, lines, c)
    print('%d of %d checks passed' % (c.checks - c.failures, c.checks))
    return 1 if c.failures else 0


if __name__ == '__main__':
    sys.exit(main())
