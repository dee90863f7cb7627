#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""CLI tests of the dhmath host tool (standard library only).

usage: run_cli_tests.py DHMATH_EXE REPO_ROOT GROUP [--seed N]

Groups:
  seed      every worked example of Paul 1981 ch. 1 through the CLI (exact output)
  errors    EXPR / usage error table: exit 2, empty stdout, message naming
            the problem and its column
  random    seeded random EXPRs vs a double-precision reference written here
            (float and --fixed); prints the measured max errors
  robotfile robot-file error table (file:line) and random robots: fk,
            fk --frames, fk --fixed, jacobian vs double references here
  rot       euler (24 sequences) and quat against angles/axes chosen here
  fixed     jacobian --fixed, euler --fixed, quat --fixed against the same
            references, next to the float path; robots without a fixed path
  examples  fk on examples/robots/puma560.dh at 0,...,0 and the other
            shipped robots; ik round trips
  help      help/usage behaviour, --version
  numbers   floats printed with %.9g read back as the same float through
            the CLI (FLT_MAX, FLT_MIN, subnormals, a strided sample)
  ikc       ik --all (closed form) on the shipped wrist robots: every line a
            solution (double FK here), the generating configuration among
            them, exit 3 unreachable / outside the limits, exit 2 and the
            reason for a robot without a closed form; a calibrated UR5
            and Puma 560 (the summary says the solutions were refined); ik --all
            --fixed on puma560_mm and ur5_mm (the fixed path, within 5e-3
            mm), its exit 3 and exit 2 cases
  move      move: a joint move (trapezoids and --jerk), a line, an arc and
            a joint move back on the UR5, a Puma line: the header, the
            period count against the planned duration (computed here), every
            step within vmax dt and every change of step within amax dt^2 by
            finite differences here, the tool on the line and within one
            period's travel, each end reached (double FK here); exit 3 and
            the period cap for a line beyond reach; exit 2, empty stdout and
            the message for each bad argument; move --fixed (the fixed
            queue): the UR5 against the float run, a blended square, the
            Puma's lagging line and a joint move back (exit 3)
  messages  the messages that name a cause: ik robot size and --w-rot,
            non-rigid tool/base/target, fk --fixed constants, projective
            EXPR in axis/euler/quat, --q0 clamping, '-' for stdin

The references below share no code with the library: plain 4x4 double
matrices with math.sin/cos of radians and Gauss-Jordan inversion.
"""
import math
import os
import random
import re
import struct
import subprocess
import sys
import tempfile

EXE = None
ROOT = None
FAILS = []
CHECKS = [0]


def run(args, stdin=None):
    # no input: an empty standard input (never the caller's terminal)
    p = subprocess.run([EXE] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       input=stdin if stdin is not None else b'', timeout=60)
    return p.returncode, p.stdout.decode('utf-8', 'replace'), p.stderr.decode('utf-8', 'replace')


def seg_dist(p, a, b):
    """distance of point p from the segment a b"""
    d = [b[i] - a[i] for i in range(3)]
    u = max(0.0, min(1.0, sum((p[i] - a[i]) * d[i] for i in range(3)) / sum(x * x for x in d)))
    return math.sqrt(sum((p[i] - a[i] - u * d[i]) ** 2 for i in range(3)))


def window_rates(pts, w, dt):
    """largest speed and acceleration of the points by finite differences over w periods of dt"""
    vw, aw = 0.0, 0.0
    for k in range(len(pts) - 2 * w):
        d1 = [pts[k + w][i] - pts[k][i] for i in range(3)]
        d2 = [pts[k + 2 * w][i] - 2 * pts[k + w][i] + pts[k][i] for i in range(3)]
        vw = max(vw, math.sqrt(sum(x * x for x in d1)) / (w * dt))
        aw = max(aw, math.sqrt(sum(x * x for x in d2)) / (w * dt) ** 2)
    return vw, aw


def window_jerk(pts, w, dt):
    """largest jerk of the points by third differences over w periods of dt"""
    jw = 0.0
    for k in range(len(pts) - 3 * w):
        d3 = [pts[k + 3 * w][i] - 3 * pts[k + 2 * w][i] + 3 * pts[k + w][i] - pts[k][i] for i in range(3)]
        jw = max(jw, math.sqrt(sum(x * x for x in d3)) / (w * dt) ** 3)
    return jw


def check_rates(what, pts, dt, speed, accel, w=20):
    """the speed and acceleration of the points over w periods within speed
    and accel (1e-3 relative, plus the rounding of positions 2e-6 apart)"""
    vw, aw = window_rates(pts, w, dt)
    check(vw <= speed * (1 + 1e-3) + 4e-6 / (w * dt) and aw <= accel * (1 + 1e-3) + 8e-6 / (w * dt) ** 2,
          '%s: speed %.6g, acceleration %.6g over %d periods' % (what, vw, aw, w))
    return vw, aw, w


def blend_dist(pts, path_dist, inner, tol):
    """the largest distance path_dist(p) of the points from their paths, and
    among the points off them (by more than tol) the largest distance from
    the nearest of the inner corners"""
    worst, off = 0.0, 0.0
    for p in pts:
        ds = path_dist(p)
        dc = min(math.sqrt(sum((p[i] - c[i]) ** 2 for i in range(3))) for c in inner)
        off = max(off, ds)
        if ds > tol:
            worst = max(worst, dc)
    return off, worst


def polyline_dist(pts, corners, inner):
    """the largest distance of the points from the polyline through corners,
    and among the points off it (by more than 1e-5) the largest distance
    from the nearest of the inner corners"""
    return blend_dist(pts, lambda p: min(seg_dist(p, corners[k], corners[k + 1]) for k in range(len(corners) - 1)),
                      inner, 1e-5)


def check(cond, what):
    CHECKS[0] += 1
    if not cond:
        FAILS.append(what)
        print('FAIL:', what)


def nums(text):
    return [[float(x) for x in line.split(' ')] for line in text.strip('\n').split('\n')]


# ---- double reference ------------------------------------------------------

def ident():
    return [[1.0 if r == c else 0.0 for c in range(4)] for r in range(4)]


def mul(A, B):
    return [[sum(A[r][k] * B[k][c] for k in range(4)) for c in range(4)] for r in range(4)]


def trans(x, y, z):
    T = ident()
    T[0][3], T[1][3], T[2][3] = x, y, z
    return T


def rot_axis(kx, ky, kz, deg):
    n = math.sqrt(kx * kx + ky * ky + kz * kz)
    kx, ky, kz = kx / n, ky / n, kz / n
    t = math.radians(deg)
    c, s, v = math.cos(t), math.sin(t), 1.0 - math.cos(t)
    # Paul 1981 eq. 1.70
    return [[kx * kx * v + c, ky * kx * v - kz * s, kz * kx * v + ky * s, 0.0],
            [kx * ky * v + kz * s, ky * ky * v + c, kz * ky * v - kx * s, 0.0],
            [kx * kz * v - ky * s, ky * kz * v + kx * s, kz * kz * v + c, 0.0],
            [0.0, 0.0, 0.0, 1.0]]


def rotx(d):
    t = math.radians(d)
    return [[1, 0, 0, 0], [0, math.cos(t), -math.sin(t), 0], [0, math.sin(t), math.cos(t), 0], [0, 0, 0, 1.0]]


def roty(d):
    t = math.radians(d)
    return [[math.cos(t), 0, math.sin(t), 0], [0, 1, 0, 0], [-math.sin(t), 0, math.cos(t), 0], [0, 0, 0, 1.0]]


def rotz(d):
    t = math.radians(d)
    return [[math.cos(t), -math.sin(t), 0, 0], [math.sin(t), math.cos(t), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]]


def scale(a, b, c):
    return [[a, 0, 0, 0], [0, b, 0, 0], [0, 0, c, 0], [0, 0, 0, 1.0]]


def persp(axis, f):
    T = ident()
    T[3]['xyz'.index(axis)] = -1.0 / f   # eq. 1.127 (y) generalised
    return T


def inverse(A):
    M = [row[:] + [1.0 if r == c else 0.0 for c in range(4)] for r, row in enumerate(A)]
    for c in range(4):
        p = max(range(c, 4), key=lambda r: abs(M[r][c]))
        M[c], M[p] = M[p], M[c]
        pv = M[c][c]
        M[c] = [x / pv for x in M[c]]
        for r in range(4):
            if r != c:
                f = M[r][c]
                M[r] = [x - f * y for x, y in zip(M[r], M[c])]
    return [row[4:] for row in M]


def dh_link(conv, jtype, a, d, alpha, theta, q):
    if jtype == 'R':
        theta = theta + q
    else:
        d = d + q
    if conv == 'standard':
        return mul(mul(mul(rotz(theta), trans(0, 0, d)), trans(a, 0, 0)), rotx(alpha))
    return mul(mul(mul(rotx(alpha), trans(a, 0, 0)), rotz(theta)), trans(0, 0, d))


# ---- python model of a robot file (independent reading of the format) ------

def read_robot(text):
    rob = {'conv': 'standard', 'joints': [], 'base': 'ident', 'tool': 'ident'}
    for line in text.split('\n'):
        line = line.split('#')[0].strip()
        if not line:
            continue
        kw, _, rest = line.partition(' ')
        if kw == 'convention':
            rob['conv'] = rest.strip()
        elif kw in ('base', 'tool'):
            rob[kw] = rest.strip()
        elif kw == 'joint':
            toks = rest.split()
            j = {'type': toks[0], 'a': 0.0, 'd': 0.0, 'alpha': 0.0, 'theta': 0.0}
            for t in toks[1:]:
                k, _, v = t.partition('=')
                j[k] = float(v)
            rob['joints'].append(j)
    return rob


def ref_expr(s):
    """Double evaluation of a (well-formed) EXPR written by these tests."""
    stack = [ident()]
    i = 0
    while i < len(s):
        if s[i] in ' *':
            i += 1
            continue
        if s[i] == ')':
            top = stack.pop()
            stack[-1] = mul(stack[-1], inverse(top))
            i += 1
            continue
        m = re.match(r'([a-z]+)', s[i:])
        name = m.group(1)
        i += len(name)
        if name == 'inv':
            i += 1
            stack.append(ident())
            continue
        if name == 'ident':
            continue
        j = s.index(')', i)
        args = s[i + 1:j].split(',')
        i = j + 1
        if name == 'persp':
            T = persp(args[0], float(args[1]))
        else:
            v = [float(a) for a in args]
            T = {'trans': trans, 'rotx': rotx, 'roty': roty, 'rotz': rotz, 'rot': rot_axis,
                 'scale': scale}[name](*v)
        stack[-1] = mul(stack[-1], T)
    return stack[0]


def ref_fk(rob, q, frames=False):
    T = ref_expr(rob['base'])
    out = []
    for j, qi in zip(rob['joints'], q):
        T = mul(T, dh_link(rob['conv'], j['type'], j['a'], j['d'], j['alpha'], j['theta'], qi))
        out.append(T)
    end = mul(T, ref_expr(rob['tool']))
    return out + [end] if frames else end


def maxdiff(A, B):
    return max(abs(a - b) for ra, rb in zip(A, B) for a, b in zip(ra, rb))


def to_expr(T):
    """trans(p) rot(k, theta) for a rigid double matrix (test-side conversion)."""
    R = [row[:3] for row in T[:3]]
    c = max(-1.0, min(1.0, (R[0][0] + R[1][1] + R[2][2] - 1.0) / 2.0))
    th = math.acos(c)
    if th < 1e-9:
        k = (0.0, 0.0, 1.0)
    elif math.pi - th < 1e-6:
        d = [math.sqrt(max(0.0, (R[i][i] + 1.0) / 2.0)) for i in range(3)]
        i = d.index(max(d))
        k = [0.0, 0.0, 0.0]
        k[i] = d[i]
        for j in range(3):
            if j != i:
                k[j] = (R[i][j] + R[j][i]) / (4.0 * d[i])
        k = tuple(k)
    else:
        k = ((R[2][1] - R[1][2]) / (2 * math.sin(th)), (R[0][2] - R[2][0]) / (2 * math.sin(th)),
             (R[1][0] - R[0][1]) / (2 * math.sin(th)))
    return 'trans(%.17g,%.17g,%.17g) rot(%.17g,%.17g,%.17g,%.17g)' % (
        T[0][3], T[1][3], T[2][3], k[0], k[1], k[2], math.degrees(th))


# ---- groups ---------------------------------------------------------------

SEED_CASES = [
    # (what, args, expected stdout)
    ('eq. 1.27 point', ['point', 'trans(4,-3,7)', '2', '3', '2'], '6 0 9 1\n'),
    # eq. 1.28 multiplies H by -5 (not expressible in EXPR) and gets
    # (-60, 0, -90, -10): the same homogeneous point as (12, 0, 18, 2) = -1/5 of it
    ('eq. 1.28 point with w = 2 (seed: -5 H, same point)', ['point', 'trans(4,-3,7)', '4', '6', '4', '2'],
     '12 0 18 2\n'),
    ('eq. 1.35 point', ['point', 'rotz(90)', '7', '3', '2'], '-3 7 2 1\n'),
    ('eq. 1.36 point', ['point', 'roty(90)', '-3', '7', '2'], '2 7 3 1\n'),
    ('eq. 1.30 plane', ['plane', 'trans(4,-3,7)', '1', '0', '0', '-2'], '1 0 0 -6\n'),
    ('eq. 1.41', ['eval', 'roty(90) rotz(90)'], '0 0 1 0\n1 0 0 0\n0 1 0 0\n0 0 0 1\n'),
    ('eq. 1.42 point', ['point', 'roty(90) rotz(90)', '7', '3', '2'], '2 7 3 1\n'),
    ('eq. 1.43', ['eval', 'rotz(90)*roty(90)'], '0 -1 0 0\n0 0 1 0\n-1 0 0 0\n0 0 0 1\n'),
    ('eq. 1.44 point', ['point', 'rotz(90) roty(90)', '7', '3', '2'], '-3 2 -7 1\n'),
    # eq. 1.45: (eq. 1.41) (eq. 1.43)^-1 is not the identity, so AB != BA
    ('eq. 1.45 AB != BA (eq. 1.41 vs 1.43)', ['eval', 'roty(90) rotz(90) inv(rotz(90) roty(90))'],
     '0 1 0 0\n0 0 -1 0\n-1 0 0 0\n0 0 0 1\n'),
    ('eq. 1.46', ['eval', 'trans(4,-3,7) roty(90) rotz(90)'], '0 0 1 4\n1 0 0 -3\n0 1 0 7\n0 0 0 1\n'),
    ('eq. 1.47 point', ['point', 'trans(4,-3,7) roty(90) rotz(90)', '7', '3', '2'], '6 4 10 1\n'),
    ('eq. 1.48 origin', ['point', 'trans(4,-3,7) roty(90) rotz(90)', '0', '0', '0'], '4 -3 7 1\n'),
    ('eq. 1.50 X = T C', ['eval', 'trans(10,0,0) rotz(90) trans(20,10,0) rotx(90)'],
     '0 0 1 0\n1 0 0 20\n0 1 0 0\n0 0 0 1\n'),
    ('eq. 1.51 Y = C T', ['eval', 'trans(20,10,0) rotx(90) trans(10,0,0) rotz(90)'],
     '0 -1 0 30\n0 0 -1 10\n1 0 0 0\n0 0 0 1\n'),
    ('eq. 1.52', ['eval', 'trans(4,0,0) roty(90) rotz(90)'], '0 0 1 4\n1 0 0 0\n0 1 0 0\n0 0 0 1\n'),
    ('eq. 1.54 inverse', ['eval', 'inv(trans(4,0,0) roty(90) rotz(90))'],
     '0 1 0 0\n0 0 1 0\n1 0 0 -4\n0 0 0 1\n'),
    ('eq. 1.55 T^-1 T = I', ['eval', 'inv(trans(4,0,0) roty(90) rotz(90)) trans(4,0,0) roty(90) rotz(90)'],
     '1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n'),
    ('eq. 1.46 fixed', ['eval', '--fixed', 'trans(4,-3,7) roty(90) rotz(90)'],
     '0 0 1 4\n1 0 0 -3\n0 1 0 7\n0 0 0 1\n'),
    ('eq. 1.54 fixed', ['eval', '--fixed', 'inv(trans(4,0,0) roty(90) rotz(90))'],
     '0 1 0 0\n0 0 1 0\n1 0 0 -4\n0 0 0 1\n'),
    ('eq. 1.128 persp', ['point', 'persp(y,10)', '1', '5', '2'], '1 5 2 0.5\n'),
]
# eq. 1.53: the six object points
for col_in, col_out in zip([(1, 0, 0), (-1, 0, 0), (-1, 0, 2), (1, 0, 2), (1, 4, 0), (-1, 4, 0)],
                           [(4, 1, 0), (4, -1, 0), (6, -1, 0), (6, 1, 0), (4, 1, 4), (4, -1, 4)]):
    SEED_CASES.append(('eq. 1.53 point %s' % (col_in,), ['point', 'trans(4,0,0) roty(90) rotz(90)'] +
                      [str(v) for v in col_in], '%d %d %d 1\n' % col_out))


def group_seed():
    for what, args, want in SEED_CASES:
        rc, out, err = run(args)
        check(rc == 0 and out == want and err == '',
              '%s: dhmath %s -> rc %d out %r err %r (want %r)' % (what, args, rc, out, err, want))
    # Example 1.1 (eq. 1.104-1.112): k = (1,1,1)/sqrt(3), theta = 120
    rc, out, err = run(['axis', 'roty(90) rotz(90)'])
    check(rc == 0, 'Example 1.1 axis rc %d %r' % (rc, err))
    if rc == 0:
        # 0.577350259 is 1/sqrt(3) rounded to float and printed with %.9g
        check(out == '0.577350259 0.577350259 0.577350259 120\n', 'Example 1.1 axis: %r' % out)


ERROR_CASES = [
    # (args, regex the stderr must match)
    (['eval', 'rotw(3)'], r'column 1 of EXPR: unknown term .rotw.'),
    (['eval', 'rotx(30) rotw(3)'], r'column 10 of EXPR: unknown term .rotw.'),
    (['eval', 'rotx(abc)'], r'column 6 of EXPR: bad number .abc.'),
    (['eval', 'rotx(1.2.3)'], r'column 6 of EXPR: bad number .1\.2\.3.'),
    (['eval', 'rotx(1e)'], r'column 6 of EXPR: bad number .1e.*exponent'),
    (['eval', 'rotx(0x10)'], r'column 6 of EXPR: bad number .0x10.'),
    (['eval', 'rotx( 5 6)'], r"column 9 of EXPR: .*expected ',' or '\)'"),
    (['eval', 'rotx(nan)'], r'column 6 of EXPR: .*NaN'),
    (['eval', 'rotx(-inf)'], r'column 6 of EXPR: .*Inf'),
    (['eval', 'trans(1,Infinity,0)'], r'column 9 of EXPR: .*Inf'),
    (['eval', 'rotx(1e39)'], r'column 6 of EXPR: .*out of float range'),
    (['eval', 'trans(1e-45,0,0)'], r'column 7 of EXPR: .*out of float range'),
    (['eval', 'trans(1e400,0,0)'], r'column 7 of EXPR: .*out of float range'),
    (['eval', 'rotx(30,2)'], r'column 1 of EXPR: .rotx. takes 1 argument.*got 2'),
    (['eval', 'trans(1,2)'], r'column 1 of EXPR: .trans. takes 3 arguments.*got 2'),
    (['eval', 'rot(1,0,0)'], r'column 1 of EXPR: .rot. takes 4 arguments.*got 3'),
    (['eval', 'rotx()'], r'column 1 of EXPR: .rotx. takes 1 argument.*got 0'),
    (['eval', 'trans(1,,2)'], r'column 9 of EXPR: .*missing argument 2'),
    (['eval', 'ident(3)'], r'column 1 of EXPR: .ident. takes no arguments'),
    (['eval', 'rotx'], r'column 1 of EXPR: .rotx. needs an argument list'),
    (['eval', 'rotx(30) junk'], r'column 10 of EXPR: unknown term .junk.'),
    (['eval', 'rotx(30) 5'], r'column 10 of EXPR: unexpected number'),
    (['eval', 'rotx(30);'], r"column 9 of EXPR: unexpected character ';'"),
    (['eval', 'rotx(30)rotz(3)'], r'column 9 of EXPR: missing space or .\*.'),
    (['eval', 'rotx(30))'], r"column 9 of EXPR: unbalanced '\)'"),
    (['eval', 'inv(rotx(30)'], r"column 1 of EXPR: unbalanced '\(': 'inv\(' is not closed"),
    (['eval', 'rotx(30'], r"column 5 of EXPR: unbalanced '\('"),
    (['eval', 'inv rotx(3)'], r"column 5 of EXPR: 'inv' needs '\('"),
    (['eval', 'inv()'], r'column 1 of EXPR: .inv. of an empty expression'),
    (['eval', ''], r'column 1 of EXPR: empty expression'),
    (['eval', '   '], r'column 1 of EXPR: empty expression'),
    (['eval', '* rotx(3)'], r"column 1 of EXPR: '\*' needs a term on its left"),
    (['eval', 'rotx(3) *'], r"column 9 of EXPR: expected a term after '\*'"),
    (['eval', 'rotx(3) * * rotz(3)'], r"column 11 of EXPR: '\*' follows '\*'"),
    (['eval', 'inv(scale(1,0,1))'], r'column 1 of EXPR: .inv.: singular'),
    (['eval', 'rotx(3) inv(persp(z,2) scale(0,1,1))'], r'column 9 of EXPR: .inv.: singular'),
    (['eval', 'rot(0,0,0,30)'], r'column 1 of EXPR: .rot.: zero rotation axis'),
    (['eval', 'persp(z,0)'], r'column 9 of EXPR: .*focal length f = 0'),
    (['eval', 'persp(w,2)'], r'column 7 of EXPR: .*axis must be x, y or z'),
    (['eval', 'scale(3e38,1,1) scale(3e38,1,1)'], r'column 17 of EXPR: overflow'),
    (['eval', 'inv(' * 17 + 'rotx(1)' + ')' * 17], r'column 65 of EXPR: inv\(\) nested deeper than 16'),
    (['eval', '--fixed', 'scale(1,2,3)'], r'column 1 of EXPR: .scale. is not rigid'),
    (['eval', '--fixed', 'persp(z,2)'], r'column 1 of EXPR: .persp. is not rigid'),
    (['eval', '--fixed', 'trans(40000,0,0)'], r'column 7 of EXPR: overflow'),
    (['eval', '--fixed', 'rotx(40000)'], r'column 6 of EXPR: overflow'),
    (['eval', '--fixed', 'trans(30000,0,0) trans(30000,0,0)'], r'column 18 of EXPR: overflow'),
    (['eval', '--fixed', 'rot(0,0,0,3)'], r'column 1 of EXPR: .rot.: zero rotation axis'),
    (['eval', 'rotx(3)\x01'], r"column 8 of EXPR: unexpected character '\\x01'"),
    (['axis', 'rotw(1)'], r'column 1 of EXPR: unknown term'),
    (['point', 'rotx(3', '1', '2', '3'], r"column 5 of EXPR: unbalanced '\('"),
    (['point', 'rotx(3)', '1', 'x', '3'], r"bad number 'x' for y"),
    (['point', 'rotx(3)', '1', '2', 'nan'], r"bad number 'nan' for z: NaN"),
    (['point', 'rotx(3)', '1', '2'], r'usage error: point takes EXPR x y z \[w\]'),
    (['point', 'scale(3e38,1,1)', '10', '0', '0'], r'not finite'),
    (['plane', 'scale(0,1,1)', '1', '0', '0', '0'], r'plane: EXPR is singular'),
    (['plane', 'rotx(3)', '1', '0', '0'], r'usage error: plane takes EXPR a b c d'),
    (['euler', 'XXZ', 'rotx(3)'], r"usage error: unknown Euler sequence 'XXZ'"),
    (['euler', 'XYz', 'rotx(3)'], r"usage error: unknown Euler sequence 'XYz'"),
    (['euler', 'XYZ', 'scale(2,1,1)'], r'euler: the 3x3 part of EXPR is not a rotation'),
    (['euler', 'XYZ', 'rotx(3'], r"column 5 of EXPR: unbalanced"),
    (['euler', 'XYZ'], r'usage error: euler takes SEQ EXPR'),
    (['quat', 'scale(1,1,-1)'], r'quat: the 3x3 part of EXPR is not a rotation'),
    (['quat', 'rotx(3) rotq(3)'], r'column 9 of EXPR: unknown term .rotq.'),
    (['eval'], r'usage error: eval takes one EXPR'),
    (['eval', 'rotx(1)', 'rotz(2)'], r'usage error: eval takes one EXPR'),
    (['eval', '--bogus', 'rotx(1)'], r"usage error: unknown or inapplicable option '--bogus'"),
    (['eval', '--frames', 'rotx(1)'], r"usage error: unknown or inapplicable option '--frames'"),
    (['eval', '-x', 'rotx(1)'], r"usage error: unknown option '-x'"),
    (['frobnicate'], r"usage error: unknown command 'frobnicate'"),
    ([], r'^dhmath: usage error: no COMMAND given'),
    (['--version', 'x'], r'^dhmath: usage error: --version takes no arguments'),
    # a repeated option is an error, flag or valued, either spelling
    (['eval', '--fixed', '--fixed', 'ident'], r"^dhmath: usage error: option '--fixed' given more than once"),
    (['fk', '--frames', 'r.dh', '0', '--frames'], r"^dhmath: usage error: option '--frames' given more than once"),
    (['ik', 'r.dh', 'ident', '--q0', '0', '--q0=1'], r"^dhmath: usage error: option '--q0=1' given more than once"),
    (['ik', 'r.dh', 'ident', '--w-rot=1', '--w-rot', '2'],
     r"^dhmath: usage error: option '--w-rot' given more than once"),
    # standard input can be read once
    (['ik', '-', '-'], r"^dhmath: usage error: '-' \(standard input\) given more than once"),
    (['eval', '-'], r'^dhmath: error at column 1 of EXPR: empty expression'),
    # a projective EXPR has no rotation (as ik says of such a target)
    (['quat', 'persp(z,2)'], r'^dhmath: error: quat: EXPR is not rigid: its bottom row is 0 0 -0.5 1, not 0 0 0 1'),
    (['euler', 'ZYX', 'rotx(10) persp(x,4)'], r'^dhmath: error: euler: EXPR is not rigid: its bottom row is '),
    (['axis', 'persp(y,10)'], r'^dhmath: error: axis: EXPR is not rigid: its bottom row is 0 -0.100000001 0 1'),
]


def group_errors():
    for args, pat in ERROR_CASES:
        rc, out, err = run(args)
        check(rc == 2, 'error case %r: exit %d (want 2)' % (args, rc))
        check(out == '', 'error case %r: stdout not empty: %r' % (args, out))
        check(re.search(pat, err) is not None, 'error case %r: stderr %r does not match %r' % (args, err, pat))
        check(err.startswith('dhmath: '),
              'error case %r: stderr should start with "dhmath: ": %r' % (args, err))


def rand_num(rng, lo, hi):
    return '%.6g' % rng.uniform(lo, hi)


def rand_expr(rng, depth=0, fixed=False, nterms=None):
    terms = []
    for _ in range(nterms or rng.randint(1, 5)):
        k = rng.random()
        if k < 0.2:
            terms.append('trans(%s,%s,%s)' % tuple(rand_num(rng, -100, 100) for _ in range(3)))
        elif k < 0.5:
            terms.append('rot%s(%s)' % (rng.choice('xyz'), rand_num(rng, -720, 720)))
        elif k < 0.65:
            terms.append('rot(%s,%s,%s,%s)' % (rand_num(rng, -1, 1), rand_num(rng, -1, 1),
                                               rand_num(rng, 0.1, 1), rand_num(rng, -360, 360)))
        elif k < 0.72 and not fixed:
            terms.append('scale(%s,%s,%s)' % tuple(rand_num(rng, 0.5, 2) for _ in range(3)))
        elif k < 0.76 and not fixed:
            terms.append('persp(%s,%s)' % (rng.choice('xyz'), rand_num(rng, 50, 200)))
        elif k < 0.8:
            terms.append('ident')
        elif depth < 3:
            terms.append('inv(%s)' % rand_expr(rng, depth + 1, fixed, rng.randint(1, 3)))
        else:
            terms.append('rotz(%s)' % rand_num(rng, -180, 180))
    return rng.choice([' ', ' * ', '*', '  ']).join(terms)


def scale_of(M):
    return max(1.0, max(abs(x) for row in M for x in row))


def group_random(seed):
    rng = random.Random(seed)
    worst = {'float': 0.0, 'fixed_rot': 0.0, 'fixed_pos': 0.0, 'point': 0.0, 'plane': 0.0}
    n = 300
    for it in range(n):
        e = rand_expr(rng)
        rc, out, err = run(['eval', e])
        check(rc == 0, 'random eval %r: rc %d %r' % (e, rc, err))
        if rc:
            continue
        got, ref = nums(out), ref_expr(e)
        d = maxdiff(got, ref) / scale_of(ref)
        worst['float'] = max(worst['float'], d)
        # measured over seeds 1..60 (18000 EXPRs of up to ~15 chained
        # products incl. scale/persp/inv, angles between table points):
        # <= 3.2e-6 relative to max(1, largest entry)
        check(d <= 4e-6, 'random eval %r: relative error %.3g' % (e, d))
    for it in range(n):
        e = rand_expr(rng, fixed=True)
        rc, out, err = run(['eval', '--fixed', e])
        check(rc == 0, 'random eval --fixed %r: rc %d %r' % (e, rc, err))
        if rc:
            continue
        got, ref = nums(out), ref_expr(e)
        dr = max(abs(got[r][c] - ref[r][c]) for r in range(3) for c in range(3))
        dp = max(abs(got[r][3] - ref[r][3]) for r in range(3))
        worst['fixed_rot'] = max(worst['fixed_rot'], dr)
        worst['fixed_pos'] = max(worst['fixed_pos'], dp)
        # the reference uses the decimal inputs; the fixed path sees them
        # rounded to Q16.16 (angles 1.5e-5 deg = 2.7e-7 rad, lengths 1.5e-5).
        # measured over seeds 1..60: rotation <= 6.0e-7, position <= 8.3e-5
        # (|p| up to a few hundred)
        check(dr <= 8e-7 and dp <= 1.2e-4, 'random eval --fixed %r: rot %.3g pos %.3g' % (e, dr, dp))
    print('random: %d float EXPRs max relative error %.3g; %d fixed EXPRs max rotation error %.3g, '
          'max position error %.3g (seed %d)' % (n, worst['float'], n, worst['fixed_rot'],
                                                 worst['fixed_pos'], seed))
    # point/plane vs reference
    for it in range(100):
        e = rand_expr(rng)
        u = [rng.uniform(-10, 10) for _ in range(3)] + [rng.choice([1.0, 0.0, 2.5])]
        su = ['%.6g' % x for x in u]
        u = [float(x) for x in su]
        rc, out, err = run(['point', e] + su)
        check(rc == 0, 'random point %r' % e)
        if rc == 0:
            ref = ref_expr(e)
            v = [sum(ref[r][k] * u[k] for k in range(4)) for r in range(4)]
            got = nums(out)[0]
            d = max(abs(a - b) for a, b in zip(got, v)) / max(1.0, max(abs(x) for x in v))
            worst['point'] = max(worst['point'], d)
            # measured over seeds 1..60: <= 3.1e-6
            check(d <= 4e-6, 'random point %r %r: %.3g' % (e, su, d))
        P = ['%.6g' % rng.uniform(-2, 2) for _ in range(4)]
        rc, out, err = run(['plane', e] + P)
        check(rc == 0, 'random plane %r' % e)
        if rc == 0:
            Hi = inverse(ref_expr(e))
            pv = [float(x) for x in P]
            q = [sum(pv[k] * Hi[k][c] for k in range(4)) for c in range(4)]
            got = nums(out)[0]
            # error of each component relative to sum_k |P_k| |Hinv_kc| (the
            # size of the terms that are summed, so cancellation does not
            # inflate it)
            d = max(abs(got[c] - q[c]) / max(1e-30, sum(abs(pv[k] * Hi[k][c]) for k in range(4)))
                    for c in range(4))
            worst['plane'] = max(worst['plane'], d)
            # measured over seeds 1..60: <= 7.6e-6
            check(d <= 1e-5, 'random plane %r %r: %.3g' % (e, P, d))
    print('random: 100 points max relative error %.3g, 100 planes %.3g' % (worst['point'], worst['plane']))


RF_ERRORS = [
    # (file text, regex; NAME is replaced by the file path)
    ('joint R a=1\nfoo 3\n', r'NAME:2:1: unknown keyword .foo.'),
    ('joint R a=1 b=2\n', r'NAME:1:13: joint: unknown key .b.'),
    ('joint R a=1 a=2\n', r'NAME:1:13: joint: duplicate key .a.'),
    ('# c\n\njoint R a=x\n', r'NAME:3:11: joint: bad number .x.'),
    ('joint R alpha=nan\n', r'NAME:1:15: joint: bad number .nan.*NaN'),
    ('joint R d=1e39\n', r'NAME:1:11: joint: bad number .*out of float range'),
    ('joint Q a=1\n', r'NAME:1:7: joint: type must be R or P'),
    ('joint\n', r'NAME:1:1: joint: missing type'),
    ('joint R a 1\n', r'NAME:1:9: joint: expected key=value'),
    ('joint R min=10 max=-10\n', r'NAME:1:1: joint: min=10 is greater than max=-10'),
    ('joint R min=10\n', r'NAME:1:1: joint: .min. given without .max.'),
    (''.join('joint R a=1\n' for _ in range(9)), r'NAME:9:1: too many joints'),
    ('joint R\nbase rotx(30) rotw(1)\n', r'NAME:2:15: bad base EXPR: unknown term .rotw.'),
    ('joint R\ntool inv(scale(0,1,1))\n', r'NAME:2:6: bad tool EXPR: .inv.: singular'),
    ('joint R\ntool\n', r'NAME:2:1: .tool. needs an EXPR'),
    ('joint R\nbase ident\nbase ident\n', r'NAME:3:1: duplicate .base. \(first given on line 2\)'),
    ('joint R\nconvention modified\n', r'NAME:2:1: .convention. must come before the first joint'),
    ('convention craig\njoint R\n', r'NAME:1:12: unknown convention .craig.'),
    ('convention standard\nconvention standard\njoint R\n', r'NAME:2:1: duplicate .convention.'),
    ('convention standard extra\njoint R\n', r'NAME:1:21: unexpected .extra.'),
    ('# only a comment\n', r'NAME:1: no .joint. lines'),
    ('', r'NAME:1: no .joint. lines'),
    ('joint R a=1\x00\n', r'NAME:1:11: joint: bad number .1\\x00.'),
    ('joint R vmax=0\n', r'NAME:1:14: joint: .vmax. must be greater than 0'),
    ('joint R vmax=10 amax=-5\n', r'NAME:1:22: joint: .amax. must be greater than 0'),
    ('joint R vmax=1 vmax=2\n', r'NAME:1:16: joint: duplicate key .vmax.'),
]


def rand_robot(rng, njoints):
    conv = rng.choice(['standard', 'modified'])
    lines = ['# random robot', 'convention %s' % conv]
    for _ in range(njoints):
        t = rng.choice('RRRP')
        kv = []
        for k, lo, hi in (('a', -0.5, 0.5), ('d', -0.5, 0.5), ('alpha', -180, 180), ('theta', -180, 180)):
            if rng.random() < 0.8:
                kv.append('%s=%s' % (k, rand_num(rng, lo, hi)))
        if rng.random() < 0.3:
            kv.append('min=-170 max=170' if t == 'R' else 'min=-1 max=1')
        rng.shuffle(kv)
        lines.append('joint %s %s   # comment' % (t, ' '.join(kv)))
    if rng.random() < 0.5:
        lines.append('base trans(%s,%s,%s) rotz(%s)' % (rand_num(rng, -1, 1), rand_num(rng, -1, 1),
                                                        rand_num(rng, -1, 1), rand_num(rng, -180, 180)))
    if rng.random() < 0.5:
        lines.append('tool trans(0,0,%s) rotx(%s)' % (rand_num(rng, 0, 0.2), rand_num(rng, -180, 180)))
    return '\n'.join(lines) + '\n'


def rand_q(rng, rob):
    return ['%.6g' % (rng.uniform(-170, 170) if j['type'] == 'R' else rng.uniform(-1, 1))
            for j in rob['joints']]


def jac_ref(rob, q):
    """Geometric Jacobian by central differences of the double FK (per rad / per unit)."""
    n = len(q)
    J = [[0.0] * n for _ in range(6)]
    for i, j in enumerate(rob['joints']):
        h = 1e-6
        step = math.degrees(h) if j['type'] == 'R' else h
        qp = q[:]
        qm = q[:]
        qp[i] += step
        qm[i] -= step
        Tp, Tm = ref_fk(rob, qp), ref_fk(rob, qm)
        T = ref_fk(rob, q)
        for r in range(3):
            J[r][i] = (Tp[r][3] - Tm[r][3]) / (2 * h)
        # angular velocity: skew part of dR R^T
        dR = [[(Tp[r][c] - Tm[r][c]) / (2 * h) for c in range(3)] for r in range(3)]
        W = [[sum(dR[r][k] * T[c][k] for k in range(3)) for c in range(3)] for r in range(3)]
        J[3][i] = (W[2][1] - W[1][2]) / 2
        J[4][i] = (W[0][2] - W[2][0]) / 2
        J[5][i] = (W[1][0] - W[0][1]) / 2
    return J


def group_robotfile(seed, tmp):
    for k, (text, pat) in enumerate(RF_ERRORS):
        path = os.path.join(tmp, 'bad%02d.dh' % k)
        with open(path, 'wb') as f:
            f.write(text.encode('latin-1'))
        rc, out, err = run(['fk', path, '0'])
        want = pat.replace('NAME', re.escape(path))
        check(rc == 2 and out == '' and re.search(want, err) is not None,
              'robot file %r: rc %d out %r err %r (want %r)' % (text, rc, out, err, want))
    # rate limits: vmax=/amax= reach the robot (dhmath gen writes every
    # field: the float value, its Q16.16 / dh_qpos copy, unlimited as
    # INFINITY / INT32_MAX)
    path = os.path.join(tmp, 'rates.dh')
    with open(path, 'w') as f:
        f.write('joint R a=0.5 vmax=180 amax=720\njoint P vmax=0.25\n')
    rc, out, err = run(['gen', path, 'rates'])
    check(rc == 0, 'gen with rates: rc %d %r' % (rc, err))
    joints = re.findall(r'\[(\d)\] = \{ \.type(.*?)\}', out, re.S)
    check(len(joints) == 2, 'gen with rates: %d joints' % len(joints))
    if len(joints) == 2:
        j1, j2 = joints[0][1], joints[1][1]
        check('.vmax = 0x1.68p+7f' in j1 and '.amax = 0x1.68p+9f' in j1 and
              '.vmax_q = %d' % (180 * 65536) in j1 and '.amax_q = %d' % (720 * 65536) in j1,
              'gen joint 1 rates: %r' % j1)
        check('.vmax = 0x1p-2f' in j2 and '.amax = INFINITY' in j2 and '.amax_q = 2147483647' in j2,
              'gen joint 2 rates: %r' % j2)
    path = os.path.join(tmp, 'missing.dh')
    rc, out, err = run(['fk', path, '0'])
    check(rc == 2 and out == '' and 'cannot open' in err, 'missing robot file: %r' % err)
    # a length beyond Q16.16 (40000 units): the float path works, the fixed
    # path is unavailable and says why
    path = os.path.join(tmp, 'big.dh')
    with open(path, 'w') as f:
        f.write('convention standard\njoint R a=40000 d=0 alpha=0\n')
    rc, out, err = run(['fk', path, '0'])
    check(rc == 0, 'fk on a robot with a = 40000: rc %d %r' % (rc, err))
    rc, out, err = run(['fk', '--fixed', path, '0'])
    check(rc == 2 and out == '' and 'joint 1: a=40000 does not fit the fixed-point length format' in err,
          'fk --fixed on a robot with a = 40000: rc %d out %r err %r' % (rc, out, err))

    rng = random.Random(seed)
    good = os.path.join(tmp, 'good.dh')
    worst = [0.0, 0.0, 0.0, 0.0]
    for it in range(60):
        n = rng.randint(1, 8)
        text = rand_robot(rng, n)
        with open(good, 'w') as f:
            f.write(text)
        rob = read_robot(text)
        q = rand_q(rng, rob)
        qf = [float(x) for x in q]
        # wrong count
        rc, out, err = run(['fk', good, ','.join(q + ['0'])])
        check(rc == 2 and out == '' and 'expected %d values' % n in err, 'fk wrong count: %r' % err)
        rc, out, err = run(['fk', good, ','.join(q)])
        check(rc == 0, 'fk %r %r: rc %d %r' % (text, q, rc, err))
        if rc == 0:
            d = maxdiff(nums(out), ref_fk(rob, qf))
            worst[0] = max(worst[0], d)
            # metre-sized random chains of up to 8 joints:
            # measured over seeds 1..40 <= 6.9e-7
            check(d <= 1e-6, 'fk %r %r: error %.3g' % (text, q, d))
        rc, out, err = run(['fk', '--frames', good, ','.join(q)])
        check(rc == 0, 'fk --frames rc %d %r' % (rc, err))
        if rc == 0:
            blocks = out.strip('\n').split('\n\n')
            refs = ref_fk(rob, qf, frames=True)
            check(len(blocks) == n + 1, 'fk --frames: %d blocks for %d joints' % (len(blocks), n))
            for b, R in zip(blocks, refs):
                check(maxdiff(nums(b), R) <= 1e-6, 'fk --frames block error')
        rc, out, err = run(['fk', '--expr', good, ','.join(q)])
        check(rc == 0 and out.count('\n') == 1, 'fk --expr rc %d %r %r' % (rc, out, err))
        if rc == 0:
            d = maxdiff(ref_expr(out.strip()), ref_fk(rob, qf))
            worst[3] = max(worst[3], d)
            # float frame -> float axis/angle printed with 9 digits; measured
            # over seeds 1..40 <= 7.2e-7
            check(d <= 1e-6, 'fk --expr %r %r: %r error %.3g' % (text, q, out, d))
        rc, out, err = run(['fk', '--fixed', good, ','.join(q)])
        check(rc == 0, 'fk --fixed %r rc %d %r' % (text, rc, err))
        if rc == 0:
            d = maxdiff(nums(out), ref_fk(rob, qf))
            worst[1] = max(worst[1], d)
            # inputs rounded to Q16.16 (angles 1.5e-5 deg, lengths 1.5e-5);
            # measured over seeds 1..40 <= 5.5e-5
            check(d <= 8e-5, 'fk --fixed %r %r: error %.3g' % (text, q, d))
        rc, out, err = run(['fk', '--fixed', '--frames', good, ','.join(q)])
        check(rc == 0, 'fk --fixed --frames rc %d %r' % (rc, err))
        if rc == 0:
            blocks = out.strip('\n').split('\n\n')
            check(len(blocks) == n + 1, 'fk --fixed --frames: %d blocks for %d joints' % (len(blocks), n))
            for b, R in zip(blocks, ref_fk(rob, qf, frames=True)):
                check(maxdiff(nums(b), R) <= 8e-5, 'fk --fixed --frames block error')
        rc, out, err = run(['jacobian', good, ','.join(q)])
        check(rc == 0, 'jacobian rc %d %r' % (rc, err))
        if rc == 0:
            J = nums(out)
            check(len(J) == 6 and all(len(r) == n for r in J), 'jacobian shape %r' % out)
            if len(J) == 6 and all(len(r) == n for r in J):
                Jr = jac_ref(rob, qf)
                d = max(abs(J[r][c] - Jr[r][c]) for r in range(6) for c in range(n))
                worst[2] = max(worst[2], d)
                # includes the O(h^2) central-difference error of the
                # reference; measured over seeds 1..40 <= 6.3e-7
                check(d <= 1e-6, 'jacobian %r %r: error %.3g\n%r\n%r' % (text, q, d, J, Jr))
    print('robotfile: 60 random robots: fk max error %.3g, fk --fixed %.3g, jacobian %.3g, fk --expr %.3g '
          '(seed %d)' % (worst[0], worst[1], worst[2], worst[3], seed))


def det(M):
    M = [row[:] for row in M]
    n, d = len(M), 1.0
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(M[r][c]))
        if M[p][c] == 0.0:
            return 0.0
        if p != c:
            M[c], M[p] = M[p], M[c]
            d = -d
        d *= M[c][c]
        for r in range(c + 1, n):
            f = M[r][c] / M[c][c]
            M[r] = [x - f * y for x, y in zip(M[r], M[c])]
    return d


def near_singular(rob, q, unit):
    """det(J J^T) small against its scale (position rows in metres)."""
    J = jac_ref(rob, q)
    J = [[x / unit for x in row] for row in J[:3]] + J[3:]
    G = [[sum(a * b for a, b in zip(J[i], J[j])) for j in range(6)] for i in range(6)]
    tr = sum(G[i][i] for i in range(6)) / 6.0
    # 1e-9: q5 = 0.016 deg on the Puma gives 8e-11, q5 = 2 deg 1.2e-6
    return det(G) < 1e-9 * tr ** 6


def group_examples():
    rdir = os.path.join(ROOT, 'examples', 'robots')
    puma = os.path.join(rdir, 'puma560.dh')
    check(os.path.exists(puma), 'examples/robots/puma560.dh missing')
    if not os.path.exists(puma):
        return
    rob = read_robot(open(puma).read())
    z = [0.0] * len(rob['joints'])
    rc, out, err = run(['fk', puma, ','.join('0' for _ in z)])
    check(rc == 0, 'fk puma560 at 0: rc %d %r' % (rc, err))
    if rc == 0:
        got = nums(out)
        d = maxdiff(got, ref_fk(rob, z))
        check(d <= 2e-6, 'fk puma560 at 0: error %.3g\n%s' % (d, out))
        # published pose at q = 0 (Corke, RTB Puma560 with the 0.67183 m
        # pedestal): R = I, p = (0.4521, -0.15005, 1.10363)
        want = [[1, 0, 0, 0.4521], [0, 1, 0, -0.15005], [0, 0, 1, 1.10363], [0, 0, 0, 1]]
        check(maxdiff(got, want) <= 1e-6, 'fk puma560 at 0 vs published pose:\n%s' % out)
        print('fk puma560.dh at 0:\n' + out.rstrip())
    # unreachable target: best effort printed, exit 3, status on stderr
    rc, out, err = run(['ik', puma, 'trans(5,0,0)'])
    check(rc == 3 and len(nums(out)[0]) == 6 and err.startswith('ik: not converged'),
          'ik unreachable: rc %d out %r err %r' % (rc, out, err))
    for args, pat in ((['ik', puma, 'trans(0.5,0,0) rotw(3)'], r'column 16 of EXPR: unknown term'),
                      (['ik', puma, 'ident', '--q0', '1,2,3'], r'--q0: expected 6 values'),
                      (['ik', puma, 'ident', '--q0'], r"option '--q0' needs a value"),
                      (['ik', puma, 'ident', '--tol-pos', '-1'], r'--tol-pos must be >= 0'),
                      (['ik', puma, 'ident', '--max-iter', '2.5'], r'--max-iter must be an integer'),
                      (['ik', puma], r'usage error: ik takes ROBOTFILE EXPR'),
                      (['fk', puma, '0,0,0,0,0'], r'expected 6 values'),
                      (['fk', puma, '0,0,0,0,0,x'], r"value 6 'x' \(column 11\): not a number"),
                      (['fk', puma, '0,0,0,0,0,nan'], r"value 6 'nan'.*NaN"),
                      (['fk', '--fixed', puma, '0,0,0,0,0,40000'], r'overflow: joint value 6'),
                      (['jacobian', puma, '0,0,0'], r'expected 6 values')):
        rc, out, err = run(args)
        check(rc == 2 and out == '' and re.search(pat, err) is not None,
              'robot error case %r: rc %d out %r err %r' % (args[2:], rc, out, err))
    # a value outside the limits is computed, with a warning on stderr
    rc, out, err = run(['fk', puma, '170,0,0,0,0,0'])
    check(rc == 0 and 'warning: joint 1 value 170 outside its limits' in err, 'fk limit warning %r' % err)
    # --fixed at q = 0 reproduces the published pose too
    rc, out, err = run(['fk', '--fixed', puma, '0,0,0,0,0,0'])
    check(rc == 0 and maxdiff(nums(out), ref_fk(rob, z)) <= 1e-4, 'fk --fixed puma560 at 0: %r %r' % (out, err))

    rng = random.Random(7)
    stats = {}
    for name in sorted(os.listdir(rdir)):
        if not name.endswith('.dh'):
            continue
        path = os.path.join(rdir, name)
        rob = read_robot(open(path).read())
        unit = 1000.0 if 'mm' in name else 1.0
        for it in range(10):
            # within +-90 deg and the joint's limits (a prismatic joint: its limits)
            q = ['%.4f' % (rng.uniform(j['min'], j['max']) if j['type'] == 'P' else
                           rng.uniform(max(-90.0, j.get('min', -90.0)), min(90.0, j.get('max', 90.0))))
                 for j in rob['joints']]
            rc, out, err = run(['fk', path, ','.join(q)])
            check(rc == 0 or 'outside its limits' in err, 'fk %s rc %d %r' % (name, rc, err))
            if rc:
                continue
            T = ref_fk(rob, [float(x) for x in q])
            d = maxdiff(nums(out), T)
            check(d <= 5e-6 * unit, 'fk %s %r: error %.3g' % (name, q, d))
            # ik round trip: target = fk(q), start near q; configurations
            # near a singularity (e.g. the Puma wrist at q5 ~ 0) are
            # skipped: there the pose does not pin the joints down
            if near_singular(rob, [float(x) for x in q], unit):
                stats.setdefault('skipped near a singularity', [0, 0])[0] += 1
                continue
            q0 = ['%.4f' % (float(x) + rng.uniform(-5, 5)) for x in q]
            rc, out, err = run(['ik', path, to_expr(T), '--q0', ','.join(q0)])
            check(rc in (0, 3), 'ik %s rc %d %r' % (name, rc, err))
            st = stats.setdefault(name, [0, 0])
            st[0 if rc == 0 else 1] += 1
            # the status line last; before it only the warnings for a start
            # outside the limits (clamped by the IK)
            lines = err.splitlines()
            check(len(lines) >= 1 and lines[-1].startswith('ik: ') and
                  all(re.match(r'dhmath: warning: --q0: joint \d value .* clamped to ', x) for x in lines[:-1]),
                  'ik status line %r' % err)
            if rc == 0:
                qs = [float(x) for x in nums(out)[0]]
                T2 = ref_fk(rob, qs)
                dp = max(abs(T2[r][3] - T[r][3]) for r in range(3))
                dr = max(abs(T2[r][c] - T[r][c]) for r in range(3) for c in range(3))
                check(dp <= 1e-3 * unit and dr <= 1e-3, 'ik %s round trip: pos %.3g rot %.3g' % (name, dp, dr))
    for name, (ok, nc) in sorted(stats.items()):
        print('ik round trips %s: %d converged, %d not' % (name, ok, nc))
        if name.startswith('skipped'):
            continue
        # started within 5 deg of a solution: all of them must converge
        check(nc == 0, 'ik %s: %d round trips did not converge' % (name, nc))


def group_rot(seed):
    rng = random.Random(seed)
    worst = [0.0, 0.0]
    for it in range(480):
        axes = rng.choice(['XYZ', 'XZY', 'YXZ', 'YZX', 'ZXY', 'ZYX', 'XYX', 'XZX', 'YXY', 'YZY', 'ZXZ', 'ZYZ'])
        proper = axes[0] == axes[2]
        seq = axes if rng.random() < 0.5 else axes.lower()
        a, c = rng.uniform(-179, 179), rng.uniform(-179, 179)
        # away from gimbal lock so the angles are unique
        b = rng.uniform(2, 178) if proper else rng.uniform(-88, 88)
        ang = ['%.6f' % v for v in (a, b, c)]
        terms = ['rot%s(%s)' % (ax.lower(), v) for ax, v in zip(axes, ang)]
        # intrinsic: R = R1(a) R2(b) R3(c); extrinsic: R = R3(c) R2(b) R1(a)
        e = ' '.join(terms if seq.isupper() else terms[::-1])
        rc, out, err = run(['euler', seq, e])
        check(rc == 0, 'euler %s %r: rc %d %r' % (seq, e, rc, err))
        if rc == 0:
            got = nums(out)[0]
            d = max(abs((g - float(w) + 180.0) % 360.0 - 180.0) for g, w in zip(got, ang))
            worst[0] = max(worst[0], d)
            # measured over seeds 1..40: <= 2.3e-5 deg (float entries with
            # ~1e-7 error; worst near the gimbal margin of 2 deg)
            check(d <= 4e-5, 'euler %s %r: %r, error %.3g deg' % (seq, e, got, d))
    for it in range(200):
        k = [rng.uniform(-1, 1) for _ in range(3)]
        n = math.sqrt(sum(x * x for x in k))
        th = rng.uniform(0.5, 179.5)
        sk = ['%.6f' % x for x in k]
        kf = [float(x) for x in sk]
        n = math.sqrt(sum(x * x for x in kf))
        rc, out, err = run(['quat', 'rot(%s,%s,%s,%.6f)' % (sk[0], sk[1], sk[2], th)])
        check(rc == 0, 'quat rc %d %r' % (rc, err))
        if rc == 0:
            t = math.radians(float('%.6f' % th)) / 2
            want = [math.cos(t)] + [math.sin(t) * x / n for x in kf]
            d = max(abs(g - w) for g, w in zip(nums(out)[0], want))
            worst[1] = max(worst[1], d)
            # measured over seeds 1..40: <= 2.0e-7
            check(d <= 3e-7, 'quat %r: %r vs %r (%.3g)' % (sk, out, want, d))
    rc, out, err = run(['euler', 'XYZ', 'roty(90) rotz(90)'])
    check(rc == 0 and nums(out)[0][1] == 90.0, 'euler XYZ of eq. 1.41: %r %r' % (out, err))
    print('rot: 480 euler max error %.3g deg, 200 quat max error %.3g (seed %d)' % (worst[0], worst[1], seed))


def q256(rng, lo, hi):
    """a multiple of 1/256 (exact in Q16.16 and in float, short in decimal)"""
    return '%.10g' % (round(rng.uniform(lo, hi) * 256) / 256.0)


def group_fixed(seed, tmp):
    rng = random.Random(seed)
    # jacobian --fixed on the shipped robots in mm: against the double
    # reference, next to the float path on the same configurations
    worst = {}
    for name in ('puma560_mm.dh', 'ur5_mm.dh', 'puma560.dh'):
        path = os.path.join(ROOT, 'examples', 'robots', name)
        rob = read_robot(open(path).read())
        ef = eq = 0.0
        for it in range(40):
            q = [q256(rng, -170, 170) if j['type'] == 'R' else q256(rng, -1, 1) for j in rob['joints']]
            J = jac_ref(rob, [float(x) for x in q])
            rc, out, err = run(['jacobian', '--fixed', path, ','.join(q)])
            check(rc == 0, 'jacobian --fixed %s %r: rc %d %r' % (name, q, rc, err))
            rcf, outf, errf = run(['jacobian', path, ','.join(q)])
            check(rcf == 0, 'jacobian %s %r: rc %d %r' % (name, q, rcf, errf))
            if rc != 0 or rcf != 0:
                continue
            Gq, Gf = nums(out), nums(outf)
            check(len(Gq) == 6 and all(len(r) == len(q) for r in Gq), 'jacobian --fixed shape %r' % out)
            eq = max(eq, max(abs(Gq[r][c] - J[r][c]) for r in range(6) for c in range(len(q))))
            ef = max(ef, max(abs(Gf[r][c] - J[r][c]) for r in range(6) for c in range(len(q))))
        worst[name] = (eq, ef)
        if name.endswith('_mm.dh'):
            # the fixed Jacobian is at least as accurate as the float one on
            # a robot in mm (the library's test asserts the same per entry)
            check(eq <= ef, 'jacobian --fixed %s: error %.3g above the float path %.3g' % (name, eq, ef))
        else:
            # metres in Q16.16: lengths to 1.5e-5 m, entries to 1.5e-5 m per rad
            check(eq <= 1e-4, 'jacobian --fixed %s: error %.3g' % (name, eq))
    # no fixed path: a length beyond Q16.16
    bad = os.path.join(tmp, 'nofixed.dh')
    with open(bad, 'w') as f:
        f.write('convention standard\njoint R a=40000\n')
    rc, out, err = run(['jacobian', '--fixed', bad, '0'])
    check(rc == 2 and out == '' and 'does not fit the fixed-point length format' in err and
          err.startswith('dhmath: error:'), 'jacobian --fixed without a fixed path: rc %d out %r err %r' % (rc, out, err))
    rc, out, err = run(['jacobian', bad, '0'])
    check(rc == 0, 'jacobian (float) on the same robot: rc %d %r' % (rc, err))
    # a chain whose lever arm leaves the fixed length format: overflow, exit 2
    far = os.path.join(tmp, 'far.dh')
    with open(far, 'w') as f:
        f.write('convention standard\njoint R a=30000\njoint R a=30000\n')
    rc, out, err = run(['jacobian', '--fixed', far, '0,0'])
    check(rc == 2 and out == '' and 'overflow' in err, 'jacobian --fixed overflow: rc %d out %r err %r' % (rc, out, err))
    # euler --fixed: 24 sequences, angles exact in Q16.16
    we = wq = 0.0
    for it in range(240):
        axes = rng.choice(['XYZ', 'XZY', 'YXZ', 'YZX', 'ZXY', 'ZYX', 'XYX', 'XZX', 'YXY', 'YZY', 'ZXZ', 'ZYZ'])
        proper = axes[0] == axes[2]
        seq = axes if rng.random() < 0.5 else axes.lower()
        ang = [q256(rng, -179, 179), q256(rng, 2, 178) if proper else q256(rng, -88, 88), q256(rng, -179, 179)]
        terms = ['rot%s(%s)' % (ax.lower(), v) for ax, v in zip(axes, ang)]
        e = ' '.join(terms if seq.isupper() else terms[::-1])
        rc, out, err = run(['euler', '--fixed', seq, e])
        check(rc == 0, 'euler --fixed %s %r: rc %d %r' % (seq, e, rc, err))
        if rc == 0:
            got = nums(out)[0]
            d = max(abs((g - float(w) + 180.0) % 360.0 - 180.0) for g, w in zip(got, ang))
            we = max(we, d)
            # the library's bound away from the poles
            check(d <= 2e-5, 'euler --fixed %s %r: %r, error %.3g deg' % (seq, e, got, d))
    for it in range(100):
        sk = ['%.6f' % rng.uniform(-1, 1) for _ in range(3)]
        kf = [float(x) for x in sk]
        n = math.sqrt(sum(x * x for x in kf))
        if n < 0.1:
            continue
        th = q256(rng, 0.5, 179.5)
        rc, out, err = run(['quat', '--fixed', 'rot(%s,%s,%s,%s)' % (sk[0], sk[1], sk[2], th)])
        check(rc == 0, 'quat --fixed rc %d %r' % (rc, err))
        if rc == 0:
            t = math.radians(float(th)) / 2
            want = [math.cos(t)] + [math.sin(t) * x / n for x in kf]
            d = max(abs(g - w) for g, w in zip(nums(out)[0], want))
            wq = max(wq, d)
            # the float path's bound for the quaternion (rot.h: 2e-7)
            check(d <= 2e-7, 'quat --fixed %r: %r vs %r (%.3g)' % (sk, out, want, d))
    # the same output format as the float path
    # (at the pole: the third angle 0, the float path's policy)
    rc, out, err = run(['euler', '--fixed', 'XYZ', 'roty(90) rotz(90)'])
    rcf, outf, errf = run(['euler', 'XYZ', 'roty(90) rotz(90)'])
    check(rc == 0 and out == '90 90 0\n' and out == outf, 'euler --fixed XYZ of eq. 1.41: %r %r (float %r)' % (out, err, outf))
    rc, out, err = run(['quat', '--fixed', 'ident'])
    check(rc == 0 and out == '1 0 0 0\n', 'quat --fixed ident: %r %r' % (out, err))
    # EXPRs without a fixed rotation, bad sequences: exit 2, one message
    for args, pat in ((['euler', '--fixed', 'XYZ', 'scale(1,2,3)'], r'not rigid'),
                      (['quat', '--fixed', 'persp(z,2)'], r'not rigid'),
                      (['euler', '--fixed', 'XXY', 'ident'], r'unknown Euler sequence'),
                      (['quat', '--fixed', '--fixed', 'ident'], r'given more than once')):
        rc, out, err = run(args)
        check(rc == 2 and out == '' and re.search(pat, err) and err.startswith('dhmath: '),
              '%r: rc %d out %r err %r' % (args, rc, out, err))
    # ik --fixed (dh_ik_q) on the Puma 560 and UR5 in mm: the solution's end
    # frame (double reference FK) within 1e-3 mm and 1e-5 rad of the target
    # (the target is the reference FK of a configuration within 80 % of the
    # limits, the start 10 deg away on every joint)
    wik = 0.0
    nok = 0
    for name in ('puma560_mm.dh', 'ur5_mm.dh'):
        path = os.path.join(ROOT, 'examples', 'robots', name)
        rob = read_robot(open(path).read())
        for it in range(12):
            q = [rng.uniform(0.8 * j['min'], 0.8 * j['max']) for j in rob['joints']]
            T = ref_fk(rob, q)
            q0 = ','.join('%.6f' % (v + (10.0 if rng.random() < 0.5 else -10.0)) for v in q)
            rc, out, err = run(['ik', '--fixed', '--tol-pos', '0.0009', '--tol-rot', '0.000009', '--q0', q0, path, to_expr(T)])
            check(rc in (0, 3) and 'ik --fixed:' in err, 'ik --fixed %s: rc %d %r' % (name, rc, err))
            if rc != 0:
                continue
            nok += 1
            got = nums(out)[0]
            check(len(got) == len(q), 'ik --fixed %s: %r' % (name, out))
            G = ref_fk(rob, got)
            dp = max(abs(G[k][3] - T[k][3]) for k in range(3))
            dr = max(abs(G[r][c] - T[r][c]) for r in range(3) for c in range(3))
            wik = max(wik, dp)
            check(dp <= 1e-3 and dr <= 1e-5, 'ik --fixed %s %r: position %.3g mm, rotation %.3g' % (name, got, dp, dr))
    check(nok >= 20, 'ik --fixed: only %d of 24 converged' % nok)
    puma_mm = os.path.join(ROOT, 'examples', 'robots', 'puma560_mm.dh')
    rc, out, err = run(['ik', '--fixed', puma_mm, 'trans(5000,0,0)'])
    check(rc == 3 and len(nums(out)) == 1 and 'not converged' in err, 'ik --fixed unreachable: rc %d %r %r' % (rc, out, err))
    for args, pat in ((['ik', '--fixed', puma_mm, 'trans(50000,0,0)'], r'not a rigid frame in the fixed-point formats'),
                      (['ik', '--fixed', puma_mm, 'scale(1,2,3)'], r'not a rigid frame'),
                      (['ik', '--fixed', bad, 'ident'], r'does not fit the fixed-point length format'),
                      (['ik', '--fixed', '--tol-rot', '3', puma_mm, 'ident'], r'--tol-rot must be in')):
        rc, out, err = run(args)
        check(rc == 2 and out == '' and re.search(pat, err) and err.startswith('dhmath: '),
              '%r: rc %d out %r err %r' % (args, rc, out, err))
    print('fixed: jacobian --fixed max error (fixed, float) %s; euler --fixed %.3g deg, quat --fixed %.3g; '
          'ik --fixed %d of 24 converged, worst %.3g mm (seed %d)' %
          (', '.join('%s %.3g %.3g' % (k, v[0], v[1]) for k, v in worst.items()), we, wq, nok, wik, seed))


def group_help():
    # --version: the library version from include/dhmath/config.h
    hdr = open(os.path.join(ROOT, 'include', 'dhmath', 'config.h')).read()
    ver = '.'.join(re.search(r'#define DH_VERSION_%s (\d+)' % k, hdr).group(1) for k in ('MAJOR', 'MINOR', 'PATCH'))
    rc, out, err = run(['--version'])
    check(rc == 0 and out == 'dhmath %s\n' % ver and err == '', '--version: rc %d out %r err %r' % (rc, out, err))
    for args in (['--help'], ['help'], ['-h']):
        rc, out, err = run(args)
        check(rc == 0 and out.startswith('usage: dhmath') and err == '', 'help %r' % args)
        for word in ('eval', 'axis', 'point', 'plane', 'fk', 'jacobian', 'ik', 'euler', 'quat', 'EXPR',
                     'persp(x|y|z,f)', '--version', "'-'"):
            check(word in out, 'help mentions %s' % word)


def f32_bits(b):
    return struct.unpack('<f', struct.pack('<I', b))[0]


def g9(x):
    s = '%.9g' % x
    return '0' if x == 0.0 else s


def group_numbers():
    """Every float the CLI prints (%.9g) must read back as the same float:
    point ident x y z 1 prints x, y, z after parsing them into floats."""
    edges = [0x7f7fffff, 0xff7fffff, 0x00800000, 0x80800000, 0x007fffff, 0x807fffff, 0x00000001,
             0x80000001, 0x00000002, 0x00400000, 0x00800001, 0x7f7ffffe, 0x3f800000, 0x3f7fffff]
    # plus a strided sample of all finite patterns (both signs)
    pats = edges + [b for b in range(0, 1 << 32, (1 << 32) // 1500 + 7919)
                    if (b & 0x7f800000) != 0x7f800000]
    vals = [f32_bits(b) for b in pats]
    bad = 0
    for k in range(0, len(vals), 3):
        tri = (vals[k:k + 3] + [0.0, 0.0])[:3]
        texts = [g9(v) for v in tri]
        # the first argument is x: a 0 * FLT_MAX cannot appear (ident)
        rc, out, err = run(['point', 'ident'] + texts + ['1'])
        ok = rc == 0 and out == ' '.join(texts) + ' 1\n'
        bad += not ok
        check(ok, 'point ident %s 1: rc %d out %r err %r' % (' '.join(texts), rc, out, err))
    # the same texts inside an EXPR
    rc, out, err = run(['eval', 'trans(3.40282347e+38,-1.17549435e-38,1.40129846e-45)'])
    check(rc == 0 and [r.split(' ')[3] for r in out.split('\n')[:3]] == ['3.40282347e+38', '-1.17549435e-38',
                                                                         '1.40129846e-45'],
          'eval trans(FLT_MAX, -FLT_MIN, 2^-149): rc %d %r %r' % (rc, out, err))
    print('numbers: %d floats through point ident, %d failed' % (len(vals), bad))


def write(tmp, name, text):
    path = os.path.join(tmp, name)
    with open(path, 'w') as f:
        f.write(text)
    return path


def group_messages(tmp):
    puma = os.path.join(ROOT, 'examples', 'robots', 'puma560.dh')
    rc, out, err = run(['fk', '--expr', puma, '10,-30,45,20,35,-60'])
    check(rc == 0, 'fk --expr puma560: rc %d %r' % (rc, err))
    target = out.strip()
    cases = []
    # the robot's size overflows the float IK
    big = write(tmp, 'big.dh', 'joint R a=3e38\njoint R a=1\n')
    cases.append((['ik', big, 'ident'], r"^dhmath: error: ik: the robot's size overflows the float IK: L = 3e\+38"))
    cases.append((['ik', big, 'ident', '--w-rot', '1'],
                  r"^dhmath: error: ik: overflow: .* not finite in float \(the robot's size L = 3e\+38\)"))
    # --w-rot beyond the IK's bound is named
    cases.append((['ik', puma, target, '--w-rot', '1e30'], r'^dhmath: error: --w-rot 1e30 is too large'))
    cases.append((['ik', puma, target, '--w-rot=5e18'], r'^dhmath: error: --w-rot 5e18 is too large'))
    # a tool or base that is not rigid is named, not the target
    sc = write(tmp, 'scaled_tool.dh', 'joint R a=1\njoint R a=1\n\ntool scale(2,2,2)\n')
    cases.append((['ik', sc, 'trans(1,0,0)'], r"^dhmath: error: ik: the robot's tool \(%s:4\) is not rigid"
                  % re.escape(sc)))
    sb = write(tmp, 'scaled_base.dh', 'base scale(1,1,-1)\njoint R a=1\n')
    cases.append((['ik', sb, 'trans(1,0,0)'], r"^dhmath: error: ik: the robot's base \(%s:1\) is not rigid"
                  % re.escape(sb)))
    cases.append((['ik', puma, 'persp(z,2)'], r'^dhmath: error: ik: EXPR is not rigid: its bottom row'))
    cases.append((['ik', puma, 'scale(1,2,1)'], r'^dhmath: error: ik: the rotation part of the target EXPR'))
    # fk --fixed: the constant without a fixed-point form, its value and the range
    for k, (key, val, fmt, unit) in enumerate((('a', '40000', 'length format Q16.16', '-32768 <= a < 32768 length units'),
                                ('d', '-32768.5', 'length format Q16.16', '-32768 <= d < 32768 length units'),
                                ('alpha', '40000', r'angle format \(degrees\) Q16.16', '-32768 <= alpha < 32768 deg'),
                                ('theta', '-33000', r'angle format \(degrees\) Q16.16', '-32768 <= theta < 32768 deg'),
                                ('a', '32767.99999', 'length format Q16.16', '-32768 <= a < 32768'))):
        path = write(tmp, 'q_%d.dh' % k, '# big\njoint R a=1\njoint P %s=%s\n' % (key, val))
        cases.append((['fk', '--fixed', path, '0,0'], r'^dhmath: error: %s:3: joint 2: %s=%s.* does not fit the '
                      r'fixed-point %s of --fixed \(it needs %s' % (re.escape(path), key, re.escape(val), fmt, unit)))
    sat = write(tmp, 'sat.dh', 'joint R a=20000\njoint R a=20000\n')
    cases.append((['fk', '--fixed', sat, '0,0'], r'^dhmath: error: overflow: fk --fixed: an entry of a frame of the '
                  r'chain saturates \(positions must lie in the fixed-point length format Q16.16, \|x\| < 32768'))
    for args, pat in cases:
        rc, out, err = run(args)
        check(rc == 2 and out == '' and re.search(pat, err) is not None,
              'message case %r: rc %d out %r err %r (want %r)' % (args, rc, out, err, pat))
    # the float path of the same robots still works
    rc, out, err = run(['fk', sat, '0,0'])
    check(rc == 0 and nums(out)[0][3] == 40000.0, 'fk (float) of sat.dh: %r %r' % (out, err))
    rc, out, err = run(['ik', sc, 'trans(1,0,0)', '--position'])
    check(rc == 0, 'ik --position with a scaled tool: rc %d %r' % (rc, err))

    # --q0 outside the limits: a warning that it was clamped, then the solve
    rc, out, err = run(['ik', puma, target, '--q0', '170,0,0,0,0,0'])
    check(rc in (0, 3) and 'dhmath: warning: --q0: joint 1 value 170 outside its limits [-160, 160]: clamped to 160'
          in err, 'ik --q0 clamp warning: rc %d %r' % (rc, err))
    lim = write(tmp, 'lim.dh', 'joint R a=1 min=10 max=20\njoint R a=1\n')
    rc, out, err = run(['ik', lim, 'trans(1.5,0.5,0)', '--position'])
    check(rc in (0, 3) and 'warning: start (no --q0, all zeros): joint 1 value 0 outside its limits [10, 20]: '
          'clamped to 10' in err, 'ik default start clamp warning: rc %d %r' % (rc, err))
    rc, out, err = run(['ik', puma, target, '--q0', '10,0,0,0,0,0'])
    check('warning' not in err, 'ik --q0 within the limits warns: %r' % err)

    # '-' reads the EXPR or the robot file from standard input
    for args, stdin in ((['eval', '-'], b'trans(4,-3,7) roty(90)\n rotz(90)\n'),
                        (['eval', '--fixed', '-'], b'trans(4,-3,7) roty(90) rotz(90)'),
                        (['point', '-', '7', '3', '2'], b'trans(4,-3,7) roty(90) rotz(90)')):
        rc, out, err = run(args, stdin=stdin)
        want = {'point': '6 4 10 1\n'}.get(args[0], '0 0 1 4\n1 0 0 -3\n0 1 0 7\n0 0 0 1\n')
        check(rc == 0 and out == want, '%r < %r: rc %d out %r err %r' % (args, stdin, rc, out, err))
    text = open(puma, 'rb').read()
    rc1, out1, _ = run(['fk', puma, '10,20,30,40,50,60'])
    rc2, out2, err2 = run(['fk', '-', '10,20,30,40,50,60'], stdin=text)
    check(rc1 == 0 and rc2 == 0 and out1 == out2, 'fk - < puma560.dh: rc %d %r %r' % (rc2, out2, err2))
    rc, out, err = run(['ik', '-', target, '--q0', '15,-25,40,25,30,-55'], stdin=text)
    check(rc == 0 and len(nums(out)[0]) == 6, 'ik - < puma560.dh: rc %d %r %r' % (rc, out, err))
    rc, out, err = run(['ik', puma, '-', '--q0', '15,-25,40,25,30,-55'], stdin=target.encode())
    check(rc == 0 and len(nums(out)[0]) == 6, 'ik ROBOT - < EXPR: rc %d %r %r' % (rc, out, err))
    rc, out, err = run(['fk', '-', '0'], stdin=b'joint R a=1\njoint Q\n')
    check(rc == 2 and out == '' and err.startswith('dhmath: error: <stdin>:2:7: joint: type must be R or P'),
          'fk - with a bad robot file: %r' % err)
    rc, out, err = run(['eval', '-'], stdin=b'rotx(30) rotw(3)')
    check(rc == 2 and 'column 10 of EXPR: unknown term' in err, 'eval - with a bad EXPR: %r' % err)


def ang_diff(a, b):
    d = (a - b) % 360.0
    return min(d, 360.0 - d)


def group_ikc(seed, tmp):
    rdir = os.path.join(ROOT, 'examples', 'robots')
    rng = random.Random(seed)
    for name in ('puma560.dh', 'kuka_kr5.dh', 'abb_irb140.dh', 'stanford.dh'):
        path = os.path.join(rdir, name)
        rob = read_robot(open(path).read())
        js = rob['joints']
        nsol = 0
        for it in range(20):
            q = [rng.uniform(j['min'], j['max']) for j in js]
            if abs(math.sin(math.radians(q[4] + js[4]['theta']))) < 0.1:
                continue
            T = ref_fk(rob, q)
            rc, out, err = run(['ik', '--all', path, to_expr(T)])
            lines = err.splitlines()
            check(rc in (0, 3) and len(lines) == 1 and lines[0].startswith('ik --all: '),
                  'ik --all %s: rc %d err %r' % (name, rc, err))
            if rc != 0:
                check(out == '', 'ik --all %s rc 3 printed %r' % (name, out))
                continue
            best = 1e30
            rows = nums(out)
            check(re.match(r'ik --all: %d closed-form solutions? within the limits \(\d+ outside\)$' % len(rows),
                           lines[0]) is not None, 'ik --all %s summary %r' % (name, lines[0]))
            for row in rows:
                check(len(row) == len(js), 'ik --all %s: line %r' % (name, row))
                T2 = ref_fk(rob, row)
                d = maxdiff(T2, T)
                check(d <= 2e-5, 'ik --all %s: solution %r misses the target by %.3g' % (name, row, d))
                for j, v in zip(js, row):
                    check(j['min'] <= v <= j['max'], 'ik --all %s: %r outside the limits' % (name, row))
                w = max(ang_diff(a, b) if j['type'] == 'R' else abs(a - b) for j, a, b in zip(js, row, q))
                best = min(best, w)
            nsol += len(rows)
            check(best <= 1e-2, 'ik --all %s: generating q %r not printed (nearest %.3g)\n%s' % (name, q, best, out))
        print('ik --all %s: %d solutions printed' % (name, nsol))
    puma = os.path.join(rdir, 'puma560.dh')
    kr5 = os.path.join(rdir, 'kuka_kr5.dh')
    # --q0 chooses the 360-degree shift: KR5 joints 4 and 6 over +-350
    rob = read_robot(open(kr5).read())
    q = [20, -40, 60, 200, 50, -190]
    target = to_expr(ref_fk(rob, q))
    for q0, want in (('0,0,0,180,0,-180', (200, -190)), ('0,0,0,0,0,0', (-160, 170))):
        rc, out, err = run(['ik', '--all', '--q0', q0, kr5, target])
        ok = rc == 0 and any(abs(r[0] - 20) < 1e-2 and abs(r[1] + 40) < 1e-2 and abs(r[3] - want[0]) < 1e-2 and
                             abs(r[5] - want[1]) < 1e-2 for r in nums(out))
        check(ok, 'ik --all --q0 %s: %r %r' % (q0, out, err))
    # no solution: exit 3, nothing on stdout, one line on stderr
    rc, out, err = run(['ik', '--all', puma, 'trans(5,0,0)'])
    check(rc == 3 and out == '' and err == 'ik --all: no solution: the target is out of reach\n',
          'ik --all unreachable: rc %d %r %r' % (rc, out, err))
    narrow = write(tmp, 'narrow.dh', open(puma).read().replace('min=-160 max=160', 'min=10 max=20'))
    rc, out, err = run(['ik', '--all', narrow, target_of_puma(60)])
    check(rc == 3 and out == '' and re.match(r'ik --all: no solution within the joint limits \(\d+ outside\)\n$', err),
          'ik --all outside the limits: rc %d %r %r' % (rc, out, err))
    # robots without a closed form, errors: exit 2 and the reason
    offset = write(tmp, 'offset.dh', open(puma).read().replace(
        'joint R a=0      d=0       alpha=-90', 'joint R a=0.05   d=0       alpha=-90'))
    cases = [(['ik', '--all', os.path.join(rdir, 'panda.dh'), 'ident'],
              r'^dhmath: error: ik --all: .*panda.dh has no closed-form inverse kinematics: the joint count or types '
              r'match no closed-form family\n$'),
             (['ik', '--all', offset, 'ident'],
              r'^dhmath: error: ik --all: .*offset.dh has no closed-form inverse kinematics: the last three axes do '
              r'not meet in one point'),
             (['ik', '--all', '--position', puma, 'ident'], r'^dhmath: usage error: ik --all takes only --q0'),
             (['ik', '--all', '--max-iter', '3', puma, 'ident'], r'^dhmath: usage error: ik --all takes only --q0'),
             (['ik', '--all', '--q0', '1,2', puma, 'ident'], r'--q0: expected 6 values'),
             (['ik', '--all', puma, 'scale(1,2,1)'], r'^dhmath: error: ik: the rotation part of the target EXPR'),
             (['ik', '--all', puma, 'persp(z,2)'], r'^dhmath: error: ik: EXPR is not rigid')]
    for args, pat in cases:
        rc, out, err = run(args)
        check(rc == 2 and out == '' and re.search(pat, err) is not None,
              'ik --all error %r: rc %d out %r err %r' % (args, rc, out, err))


    group_ikc_calibrated(rng, tmp, rdir)
    group_ikc_fixed(rng, tmp, rdir)


# A UR5 as a calibration could give it: lengths off by up to 1.8 mm, twists
# by up to 0.4 deg, a joint 5 length of 1.5 mm (ur5.dh with these values).
UR5_CALIBRATED = """convention standard
joint R a=0.0011    d=0.089859 alpha=90.3   min=-360 max=360
joint R a=-0.4262   d=0.0014   alpha=-0.2   min=-360 max=360
joint R a=-0.39105  d=-0.0009  alpha=0.4    min=-360 max=360
joint R a=-0.0007   d=0.10835  alpha=89.8   min=-360 max=360
joint R a=0.0015    d=0.09545  alpha=-90.25 min=-360 max=360
joint R a=0         d=0.0829   alpha=0.1    min=-360 max=360
"""


# A Puma 560 as a calibration could give it: a wrist offset (a4, a5, d5) of
# up to 0.5 mm, twists off by up to 0.2 deg (puma560.dh with these values).
PUMA_CALIBRATED = """convention standard
joint R a=0       d=0.67183 alpha=90.15  min=-360 max=360
joint R a=0.4318  d=0       alpha=-0.1   min=-360 max=360
joint R a=0.0203  d=0.15005 alpha=-90.2  min=-360 max=360
joint R a=0.0004  d=0.4318  alpha=90.1   min=-360 max=360
joint R a=-0.0003 d=0.0005  alpha=-89.85 min=-360 max=360
joint R a=0       d=0       alpha=0.2    min=-360 max=360
"""


def calibrated_q(rng, name):
    """A configuration of the calibrated robot away from its singularities."""
    if name == 'ur5':
        return [rng.uniform(-170, 170), rng.uniform(-130, -50), rng.choice((-1, 1)) * rng.uniform(65, 115),
                rng.uniform(-170, 170), rng.choice((-1, 1)) * rng.uniform(55, 125), rng.uniform(-170, 170)]
    return [rng.uniform(-170, 170), rng.uniform(-60, 60), rng.uniform(20, 70) * rng.choice((-1, 1)) - 90,
            rng.uniform(-170, 170), rng.choice((-1, 1)) * rng.uniform(40, 140), rng.uniform(-170, 170)]


def group_ikc_calibrated(rng, tmp, rdir):
    """ik --all on a calibrated UR5 and a calibrated Puma 560 (spherical
    wrist): unchanged command line, the summary says the solutions were
    refined, every printed solution reaches the target (double reference FK
    of the calibrated table), the generating configuration (away from the
    singularities) is printed."""
    for name, table in (('ur5', UR5_CALIBRATED), ('puma', PUMA_CALIBRATED)):
        path = write(tmp, name + '_calibrated.dh', table)
        rob = read_robot(table)
        nsol = 0
        for it in range(10):
            q = calibrated_q(rng, name)
            T = ref_fk(rob, q)
            rc, out, err = run(['ik', '--all', path, to_expr(T)])
            lines = err.splitlines()
            rows = nums(out)
            check(rc == 0 and len(lines) == 1 and re.match(
                r'ik --all: %d closed-form solutions? within the limits \(0 outside\), refined by Newton steps on '
                r'the calibrated chain' % len(rows), lines[0]) is not None,
                'ik --all calibrated %s: rc %d err %r' % (name, rc, err))
            best = 1e30
            for row in rows:
                d = maxdiff(ref_fk(rob, row), T)
                check(d <= 2e-5, 'ik --all calibrated %s: solution %r misses the target by %.3g' % (name, row, d))
                best = min(best, max(ang_diff(a, b) for a, b in zip(row, q)))
            check(best <= 1e-2, 'ik --all calibrated %s: generating q %r not printed (nearest %.3g)\n%s' %
                  (name, q, best, out))
            nsol += len(rows)
        print('ik --all calibrated %s: %d solutions printed' % (name, nsol))


def group_ikc_fixed(rng, tmp, rdir):
    """ik --all --fixed on robots in mm: every printed solution reaches the
    target (double reference FK, mm), the generating configuration is printed."""
    for name in ('puma560_mm.dh', 'ur5_mm.dh'):
        path = os.path.join(rdir, name)
        rob = read_robot(open(path).read())
        js = rob['joints']
        nsol = 0
        for it in range(20):
            q = [rng.uniform(j['min'], j['max']) for j in js]
            if abs(math.sin(math.radians(q[4] + js[4]['theta']))) < 0.1:
                continue
            if name.startswith('ur5') and abs(math.sin(math.radians(q[2]))) < 0.1:
                continue
            T = ref_fk(rob, q)
            rc, out, err = run(['ik', '--all', '--fixed', path, to_expr(T)])
            lines = err.splitlines()
            check(rc in (0, 3) and len(lines) == 1 and lines[0].startswith('ik --all --fixed: '),
                  'ik --all --fixed %s: rc %d err %r' % (name, rc, err))
            if rc != 0:
                check(out == '', 'ik --all --fixed %s rc 3 printed %r' % (name, out))
                continue
            rows = nums(out)
            check(re.match(r'ik --all --fixed: %d closed-form solutions? within the limits \(\d+ outside\)$'
                           % len(rows), lines[0]) is not None, 'ik --all --fixed %s summary %r' % (name, lines[0]))
            best = 1e30
            for row in rows:
                check(len(row) == len(js), 'ik --all --fixed %s: line %r' % (name, row))
                T2 = ref_fk(rob, row)
                dp = max(abs(T2[i][3] - T[i][3]) for i in range(3))
                dr = max(abs(T2[i][c] - T[i][c]) for i in range(3) for c in range(3))
                check(dp <= 5e-3 and dr <= 5e-6, 'ik --all --fixed %s: solution %r misses the target by %.3g mm, '
                      '%.3g' % (name, row, dp, dr))
                for j, v in zip(js, row):
                    check(j['min'] <= v <= j['max'], 'ik --all --fixed %s: %r outside the limits' % (name, row))
                best = min(best, max(ang_diff(a, b) for a, b in zip(row, q)))
            nsol += len(rows)
            check(best <= 1e-2, 'ik --all --fixed %s: generating q %r not printed (nearest %.3g)\n%s'
                  % (name, q, best, out))
        print('ik --all --fixed %s: %d solutions printed' % (name, nsol))
    puma = os.path.join(rdir, 'puma560_mm.dh')
    rc, out, err = run(['ik', '--all', '--fixed', puma, 'trans(5000,0,0)'])
    check(rc == 3 and out == '' and err == 'ik --all --fixed: no solution: the target is out of reach\n',
          'ik --all --fixed unreachable: rc %d %r %r' % (rc, out, err))
    rob = read_robot(open(puma).read())
    narrow = write(tmp, 'narrow_mm.dh', open(puma).read().replace('min=-160 max=160', 'min=10 max=20'))
    rc, out, err = run(['ik', '--all', '--fixed', narrow, to_expr(ref_fk(rob, [60, -30, 40, 10, 30, 20]))])
    check(rc == 3 and out == '' and
          re.match(r'ik --all --fixed: no solution within the joint limits \(\d+ outside\)\n$', err),
          'ik --all --fixed outside the limits: rc %d %r %r' % (rc, out, err))
    huge = write(tmp, 'huge_mm.dh', open(puma).read().replace('a=431.8', 'a=40000'))
    cases = [(['ik', '--all', '--fixed', os.path.join(rdir, 'panda.dh'), 'ident'],
              r'^dhmath: error: ik --all --fixed: .*panda.dh has no fixed-point closed-form inverse kinematics: the '
              r'joint count or types match no closed-form family\n$'),
             (['ik', '--all', '--fixed', huge, 'ident'], r'^dhmath: error: .*huge_mm.dh'),
             (['ik', '--all', '--fixed', puma, 'trans(20000,0,0)'],
              r'^dhmath: error: overflow: ik --all --fixed: the target is more than 2\^30 LSB'),
             (['ik', '--all', '--fixed', puma, 'trans(1e6,0,0)'],
              r'^dhmath: error: overflow: ik --all --fixed: the target EXPR does not fit'),
             (['ik', '--all', '--fixed', puma, 'scale(1,1.5,1)'],
              r'^dhmath: error: ik --all --fixed: the rotation part of the target EXPR is not a rotation'),
             (['ik', '--all', '--fixed', puma, 'scale(1,2,1)'],
              r'^dhmath: error: overflow: ik --all --fixed: the target EXPR does not fit'),
             (['ik', '--all', '--fixed', '--q0', '1,2', puma, 'ident'], r'--q0: expected 6 values')]
    for args, pat in cases:
        rc, out, err = run(args)
        check(rc == 2 and out == '' and re.search(pat, err) is not None,
              'ik --all --fixed error %r: rc %d out %r err %r' % (args, rc, out, err))


def target_of_puma(q1):
    rob = read_robot(open(os.path.join(ROOT, 'examples', 'robots', 'puma560.dh')).read())
    return to_expr(ref_fk(rob, [q1, -30, 40, 10, 30, 20]))


def group_track_fixed(seed, tmp):
    """dhmath track --fixed on the UR5 in mm: every step within vmax dt
    (the fixed bound floor(vmax 2^16 dt_us / 10^6) LSB, the printed values
    rounded back to Q16.16), OK only when the double FK of the printed joints is within the
    fixed tolerances (2^-19 L, 2e-5 rad) plus the rounding of the printed
    target, a jump approached without a jump, the period's errors."""
    rng = random.Random(seed)
    ur5 = os.path.join(ROOT, 'examples', 'robots', 'ur5_mm.dh')
    rob = read_robot(open(ur5).read())
    n = len(rob['joints'])
    dt, vmax = 0.001, 180.0
    bound = math.floor(vmax * 65536 * 1000 / 1e6) / 65536.0
    qa = [10.0, -60.0, 70.0, 20.0, 40.0, 30.0]
    qb = [q + rng.uniform(-20.0, 20.0) for q in qa]
    steps = 400
    targets = []
    for k in range(1, steps + 1):
        s = 0.5 - 0.5 * math.cos(math.pi * k / steps)
        targets.append(to_expr(ref_fk(rob, [a + (b - a) * s for a, b in zip(qa, qb)])))
    targets += [to_expr(ref_fk(rob, [q + 20.0 for q in qb]))] * 300
    rc, out, err = run(['track', ur5, '--fixed', '--q0', ','.join('%.9g' % v for v in qa), '--dt', str(dt),
                        '--vmax', str(vmax)], stdin=('\n'.join(targets) + '\n').encode())
    check(rc == 0 and err == '', 'track --fixed ur5_mm: rc %d err %r' % (rc, err))
    lines = out.strip('\n').split('\n') if out else []
    check(len(lines) == len(targets), 'track --fixed: %d lines for %d targets' % (len(lines), len(targets)))
    prev = [round(q * 65536) / 65536.0 for q in qa]
    worst, words = 0.0, []
    for k, (line, tgt) in enumerate(zip(lines, targets)):
        tok = line.split()
        check(len(tok) == n + 3 and tok[n] in ('ok', 'lagging', 'unreachable'), 'track --fixed line %d: %r' %
              (k + 1, line))
        if len(tok) != n + 3:
            continue
        # the Q16.16 values back from %.9g (within 5e-7 of them, below
        # half an LSB for |q| < 1000 deg)
        q = [round(float(x) * 65536) / 65536.0 for x in tok[:n]]
        words.append(tok[n])
        step = max(abs(a - b) for a, b in zip(q, prev))
        worst = max(worst, step)
        check(step <= bound + 1e-12, 'track --fixed line %d: step %.9g beyond %.9g' % (k + 1, step, bound))
        if tok[n] == 'ok':
            T = ref_fk(rob, q)
            R = ref_expr(tgt)
            pe = math.sqrt(sum((T[i][3] - R[i][3]) ** 2 for i in range(3)))
            # pos_tol (its default, the fixed closed form's bound: 328 LSB,
            # 5.0e-3 mm) plus the fixed FK error and the Q16.16 rounding of
            # the target (1e-4 mm)
            check(pe <= 5.1e-3, 'track --fixed line %d: ok with position error %.3g mm' % (k + 1, pe))
            # the printed errors are measured (FK at q), not the bound:
            # within the fixed FK's error (4 n LSB, 3.7e-4 mm) and the
            # target's rounding of the double one
            check(abs(float(tok[n + 1]) - pe) <= 5e-4, 'track --fixed line %d: printed error %s, FK %.3g mm' %
                  (k + 1, tok[n + 1], pe))
        prev = q
    check(all(w == 'ok' for w in words[:steps]), 'track --fixed: the slow path not ok on every line: %r' %
          [i for i, w in enumerate(words[:steps]) if w != 'ok'][:5])
    check('lagging' in words[steps:steps + 5] and words[-1] == 'ok', 'track --fixed: the jump %r' %
          words[steps:steps + 5])
    first = steps + words[steps:].index('ok') if 'ok' in words[steps:] else -1
    check(0 < first - steps <= 114, 'track --fixed: jump reached after %d lines' % (first - steps))
    print('track --fixed: %d targets, largest step %.9g deg (bound %.9g), jump reached after %d lines' %
          (len(lines), worst, bound, first - steps))
    one = targets[0] + '\n'
    for args, want in ((['--dt', '0.0000005'], 'whole number of microseconds'),
                       (['--dt', '2'], 'whole number of microseconds')):
        rc, out, err = run(['track', ur5, '--fixed', '--q0', ','.join(map(str, qa)), '--vmax', '180'] + args,
                           stdin=one.encode())
        check(rc == 2 and out == '' and want in err, 'track --fixed %r: rc %d out %r err %r' % (args, rc, out, err))


def group_track(seed, tmp):
    """dhmath track: the step bound, OK only when reached (double FK here),
    a jump approached without a jump, --vmax forms, errors."""
    rng = random.Random(seed)
    ur5 = os.path.join(ROOT, 'examples', 'robots', 'ur5.dh')
    rob = read_robot(open(ur5).read())
    n = len(rob['joints'])
    dt, vmax = 0.001, 180.0
    qa = [10.0, -60.0, 70.0, 20.0, 40.0, 30.0]
    qb = [q + rng.uniform(-20.0, 20.0) for q in qa]
    steps = 400  # peak rate pi/2 * 20 deg / 0.4 s = 79 deg/s < vmax / 2
    targets, qs = [], []
    for k in range(1, steps + 1):
        s = 0.5 - 0.5 * math.cos(math.pi * k / steps)
        q = [a + (b - a) * s for a, b in zip(qa, qb)]
        qs.append(q)
        targets.append(to_expr(ref_fk(rob, q)))
    # a jump: 30 more lines at a pose 20 deg away on every joint
    qj = [q + 20.0 for q in qb]
    targets += [to_expr(ref_fk(rob, qj))] * 300
    rc, out, err = run(['track', ur5, '--q0', ','.join('%.9g' % v for v in qa), '--dt', str(dt), '--vmax',
                        str(vmax)], stdin=('\n'.join(targets) + '\n').encode())
    check(rc == 0 and err == '', 'track ur5: rc %d err %r' % (rc, err))
    lines = out.strip('\n').split('\n') if out else []
    check(len(lines) == len(targets), 'track: %d lines for %d targets' % (len(lines), len(targets)))
    prev, worst, words = qa, 0.0, []
    for k, (line, tgt) in enumerate(zip(lines, targets)):
        tok = line.split()
        check(len(tok) == n + 3 and tok[n] in ('ok', 'lagging', 'unreachable'), 'track line %d: %r' % (k + 1, line))
        if len(tok) != n + 3:
            continue
        q = [float(x) for x in tok[:n]]
        words.append(tok[n])
        step = max(abs(a - b) for a, b in zip(q, prev))
        worst = max(worst, step)
        # the bound is vmax dt; %.9g of a float reads back exactly
        check(step <= vmax * dt, 'track line %d: step %.9g beyond %.9g' % (k + 1, step, vmax * dt))
        T = ref_fk(rob, q)
        R = ref_expr(tgt)
        pe = math.sqrt(sum((T[i][3] - R[i][3]) ** 2 for i in range(3)))
        if tok[n] == 'ok':
            # 2e-6 L (L about 1.3 m) plus the float FK error
            check(pe <= 5e-6, 'track line %d: ok with position error %.3g' % (k + 1, pe))
        check(abs(float(tok[n + 1]) - pe) <= 1e-6 + 1e-5 * pe, 'track line %d: reported %s, true %.3g' %
              (k + 1, tok[n + 1], pe))
        prev = q
    check(all(w == 'ok' for w in words[:steps]), 'track: the slow path not ok on every line: %r' %
          [i for i, w in enumerate(words[:steps]) if w != 'ok'][:5])
    check('lagging' in words[steps:steps + 5] and words[-1] == 'ok', 'track: the jump %r' % words[steps:steps + 5])
    # 20 deg at 0.18 deg per period: about 112 periods, ok from then on
    first = steps + words[steps:].index('ok') if 'ok' in words[steps:] else -1
    check(0 < first - steps <= 114, 'track: jump reached after %d lines' % (first - steps))
    print('track: %d targets, largest step %.6g deg (bound %.6g), jump reached after %d lines' %
          (len(lines), worst, vmax * dt, first - steps))
    # --vmax forms: n values; from the robot file; neither
    one = targets[0] + '\n'
    rc, out, err = run(['track', ur5, '--q0', ','.join(map(str, qa)), '--dt', '0.001', '--vmax',
                        '180,180,180,90,90,90'], stdin=one.encode())
    check(rc == 0 and len(out.split()) == n + 3, 'track --vmax list: rc %d %r %r' % (rc, out, err))
    path = os.path.join(tmp, 'ur5_rates.dh')
    with open(path, 'w') as f:
        f.write(open(ur5).read().replace('min=', 'vmax=180 min='))
    rc, out, err = run(['track', path, '--q0', ','.join(map(str, qa)), '--dt', '0.001'], stdin=one.encode())
    check(rc == 0 and out.split()[n] == 'ok', 'track with vmax= in the robot file: rc %d %r %r' % (rc, out, err))
    rc, out, err = run(['track', ur5, '--q0', ','.join(map(str, qa)), '--dt', '0.001'], stdin=one.encode())
    check(rc == 2 and out == '' and 'no --vmax' in err, 'track without vmax: rc %d %r' % (rc, err))
    # the Panda (no closed form): damped steps
    panda = os.path.join(ROOT, 'examples', 'robots', 'panda.dh')
    prob = read_robot(open(panda).read())
    pq = [0.0, -30.0, 0.0, -120.0, 0.0, 90.0, 45.0]
    pt = to_expr(ref_fk(prob, [v + 0.05 for v in pq]))
    rc, out, err = run(['track', panda, '--q0', ','.join(map(str, pq)), '--dt', '0.001', '--vmax', '150'],
                       stdin=((pt + '\n') * 20).encode())
    plines = out.strip('\n').split('\n') if rc == 0 else []
    check(rc == 0 and len(plines) == 20 and plines[-1].split()[7] == 'ok', 'track panda: rc %d %r %r' %
          (rc, out[-200:], err))
    # errors: exit 2, nothing on stdout, the line named
    good = ','.join(map(str, qa))
    bad_cases = [
        (['--q0', good, '--dt', '0.001', '--vmax', '180'], one + one + 'rotx(30) rotw(2)\n', 'line 3: column 10'),
        (['--q0', good, '--dt', '0.001', '--vmax', '180'], one + 'scale(2,1,1)\n', 'line 2: target not rigid'),
        (['--q0', good, '--dt', '0', '--vmax', '180'], one, '--dt'),
        (['--q0', good, '--dt', '0.001', '--vmax', '-5'], one, 'greater than 0'),
        (['--q0', good, '--dt', '0.001', '--vmax', '1,2'], one, 'expected 6 values'),
        (['--q0', '10,20', '--dt', '0.001', '--vmax', '180'], one, 'expected 6 values'),
        (['--q0', '10,-60,70,20,40,400', '--dt', '0.001', '--vmax', '180'], one, 'outside its limits'),
        (['--dt', '0.001', '--vmax', '180'], one, 'needs --q0'),
        (['--q0', good, '--vmax', '180'], one, 'needs --dt'),
    ]
    for args, stdin, want in bad_cases:
        rc, out, err = run(['track', ur5] + args, stdin=stdin.encode())
        check(rc == 2 and out == '' and want in err, 'track %r: rc %d out %r err %r (want %r)' %
              (args, rc, out[:80], err, want))


# ---- move ------------------------------------------------------------------

def f32_ulp(x):
    """ulp of |x| as a float (the spacing of floats at x)."""
    x = abs(float(struct.unpack('f', struct.pack('f', x))[0]))
    if x < 1.1754944e-38:
        return 2.0 ** -149
    return 2.0 ** (math.floor(math.log2(x)) - 23)


def f32(x):
    return struct.unpack('f', struct.pack('f', x))[0]


def read_csv(out, n):
    """header and rows (t, q list, status) of a move's CSV."""
    lines = out.strip('\n').split('\n') if out else []
    head = lines[0] if lines else ''
    rows = []
    for line in lines[1:]:
        tok = line.split(',')
        if len(tok) != n + 2:
            rows.append(None)
            continue
        rows.append((float(tok[0]), [f32(float(x)) for x in tok[1:n + 1]], tok[n + 1]))
    return head, rows


def rot_angle(A, B):
    """angle (rad) of R_A^T R_B"""
    tr = sum(A[k][r] * B[k][r] for r in range(3) for k in range(3))
    return math.acos(max(-1.0, min(1.0, (tr - 1.0) / 2.0)))


def trap_T(d, v, a):
    """duration of the time-optimal rest-to-rest trapezoid over |d| (double)"""
    d = abs(d)
    if d == 0.0:
        return 0.0
    if d >= v * v / a:
        return d / v + v / a
    return 2.0 * math.sqrt(d / a)


def check_joint_limits(what, q0, rows, vmax, amax, dt, eps, at_rest=True):
    """every step within vmax dt and every change of step within amax dt^2
    (finite differences here), q0 the configuration before the first row,
    at rest; eps[i]: the rounding allowance of joint i. at_rest: the last
    row is at rest too (holding it next period keeps the bound)."""
    prev, step0 = q0, [0.0] * len(q0)
    worst_v = worst_a = 0.0
    for k, row in enumerate(rows):
        q = row[1]
        for i in range(len(q)):
            st = q[i] - prev[i]
            worst_v = max(worst_v, abs(st) / (vmax[i] * dt))
            worst_a = max(worst_a, abs(st - step0[i]) / (amax[i] * dt * dt))
            if abs(st) > vmax[i] * dt + eps[i]:
                check(False, '%s: period %d joint %d step %.9g beyond vmax dt %.9g' % (what, k + 1, i + 1, st,
                                                                                        vmax[i] * dt))
                return worst_v, worst_a
            if abs(st - step0[i]) > amax[i] * dt * dt + 2.0 * eps[i]:
                check(False, '%s: period %d joint %d change of step %.9g beyond amax dt^2 %.9g' %
                      (what, k + 1, i + 1, st - step0[i], amax[i] * dt * dt))
                return worst_v, worst_a
            step0[i] = st
        prev = q
    if at_rest:
        for i in range(len(q0)):
            check(abs(step0[i]) <= amax[i] * dt * dt + 2.0 * eps[i], '%s: not at rest at the end: joint %d last step '
                  '%.9g' % (what, i + 1, step0[i]))
    check(True, what)
    return worst_v, worst_a


def move_robot(tmp, name, src, vmax, amax):
    """a copy of the robot file src with vmax= and amax= on every joint"""
    out = []
    for line in open(src).read().split('\n'):
        if line.startswith('joint '):
            line = '%s vmax=%g amax=%g' % (line, vmax, amax)
        out.append(line)
    path = os.path.join(tmp, name)
    with open(path, 'w') as f:
        f.write('\n'.join(out))
    return path


def group_move(seed, tmp):
    """dhmath move: header and period count, limits by finite differences,
    the end of every segment, exit 3 beyond reach, exit 2 per bad argument."""
    rng = random.Random(seed)
    ur5 = os.path.join(ROOT, 'examples', 'robots', 'ur5.dh')
    rob = read_robot(open(ur5).read())
    n = len(rob['joints'])
    vm, am, dt = 180.0, 720.0, 0.004
    path = move_robot(tmp, 'ur5_rates.dh', ur5, vm, am)
    qa = [10.0, -60.0, 70.0, 20.0, 40.0, 30.0]
    qb = [f32(round(q + rng.uniform(-40.0, 40.0), 3)) for q in qa]
    head_want = 't,' + ','.join('q%d' % (i + 1) for i in range(n)) + ',status'

    # 1. a joint move (trapezoids): periods, limits within the contract's
    # rounding, the last line q1 bit for bit, t = k dt
    rc, out, err = run(['move', path, '--q0', ','.join(map(str, qa)), '--dt', str(dt),
                        '--joint', ','.join('%.9g' % q for q in qb)])
    check(rc == 0 and err == '', 'move --joint: rc %d err %r' % (rc, err))
    head, rows = read_csv(out, n)
    check(head == head_want, 'move --joint: header %r' % head)
    check(rows and None not in rows and all(r[2] == 'ok' for r in rows), 'move --joint: rows %r' % rows[:3])
    if rows and None not in rows:
        lo = 1.0 - 2.0 ** -10
        T = max(trap_T(b - a, vm * lo, am * lo) for a, b in zip(qa, qb))
        check(abs(len(rows) - math.ceil(T / dt)) <= 1, 'move --joint: %d periods for T %.6g s' % (len(rows), T))
        eps = [vm * 2 * f32_ulp(T) + 4 * f32_ulp(max(abs(a), abs(b))) + 4 * f32_ulp(b - a) for a, b in zip(qa, qb)]
        wv, wa = check_joint_limits('move --joint', qa, rows, [vm] * n, [am] * n, dt, eps)
        check(rows[-1][1] == qb, 'move --joint: last line %r, not %r' % (rows[-1][1], qb))
        check(all(abs(r[0] - (k + 1) * dt) <= 1e-9 * (k + 1) * dt for k, r in enumerate(rows)), 'move --joint: t')
        print('move --joint: %d periods (T %.6g s), largest step %.6f of vmax dt, change %.6f of amax dt^2' %
              (len(rows), T, wv, wa))
        # --jerk: the seven-phase profiles, slower than the trapezoids, same limits and end
        rc, out, err = run(['move', path, '--q0', ','.join(map(str, qa)), '--dt', str(dt), '--jerk', '4000',
                            '--joint', ','.join('%.9g' % q for q in qb)])
        head, jrows = read_csv(out, n)
        check(rc == 0 and head == head_want and jrows and None not in jrows, 'move --jerk: rc %d %r' % (rc, err))
        if jrows and None not in jrows:
            check(len(jrows) > len(rows), 'move --jerk: %d periods, trapezoids %d' % (len(jrows), len(rows)))
            check_joint_limits('move --jerk', qa, jrows, [vm] * n, [am] * n, dt, eps)
            check(jrows[-1][1] == qb, 'move --jerk: last line %r' % (jrows[-1][1],))

    # 2. a line, an arc and a joint move back (tracked segments): every
    # period ok, the tracker's limits, the tool on the line and within one
    # period's travel of the previous, each segment's end reached
    A = ref_fk(rob, qa)
    p0 = [A[r][3] for r in range(3)]
    dp = [rng.uniform(-0.08, 0.08) for _ in range(3)]
    pB = [p0[r] + dp[r] for r in range(3)]
    rB = [rng.uniform(-1, 1) for _ in range(3)] + [rng.uniform(-20.0, 20.0)]
    endB = 'trans(%.6f,%.6f,%.6f) %s rot(%.6f,%.6f,%.6f,%.6f)' % tuple(pB + [to_expr(A).split(' ', 1)[1]] + rB)
    B = ref_expr(endB)
    # the via point 5 cm from the chord's middle, across the chord (a short arc)
    ax = [0.0, 0.0, 1.0] if abs(dp[2]) < 0.9 * math.sqrt(sum(d * d for d in dp)) else [1.0, 0.0, 0.0]
    nv = [dp[1] * ax[2] - dp[2] * ax[1], dp[2] * ax[0] - dp[0] * ax[2], dp[0] * ax[1] - dp[1] * ax[0]]
    nn = math.sqrt(sum(v * v for v in nv))
    via = [p0[r] + 0.5 * dp[r] + 0.05 * nv[r] / nn for r in range(3)]
    viaC = 'trans(%.6f,%.6f,%.6f)' % tuple(via)
    endC = to_expr(A)
    speed, accel, rsp, racc = 0.25, 1.0, 60.0, 240.0
    rc, out, err = run(['move', path, '--q0', ','.join(map(str, qa)), '--dt', str(dt), '--speed', str(speed),
                        '--accel', str(accel), '--rspeed', str(rsp), '--raccel', str(racc), '--line', endB,
                        '--arc', viaC, endC, '--joint', ','.join('%.9g' % q for q in qb)])
    check(rc == 0 and err == '', 'move line/arc/joint: rc %d err %r' % (rc, err))
    head, rows = read_csv(out, n)
    check(head == head_want and rows and None not in rows, 'move line/arc/joint: header %r' % head)
    if rows and None not in rows:
        check(all(r[2] == 'ok' for r in rows), 'move line/arc/joint: not ok: %r' %
              [r for r in rows if r[2] != 'ok'][:2])
        eps = [4 * f32_ulp(360.0)] * n
        wv, wa = check_joint_limits('move line/arc/joint', qa, rows, [vm] * n, [am] * n, dt, eps)
        check(rows[-1][1] == qb, 'move line/arc/joint: last line %r, not %r' % (rows[-1][1], qb))
        # the line: its periods are the first ones; the tool on the segment
        L = math.sqrt(sum(d * d for d in dp))
        ang = math.degrees(rot_angle(A, B))
        Tl = trap_T(1.0, min(speed / L, rsp / ang), min(accel / L, racc / ang))
        on_line, reached, prev = 0.0, None, p0
        for k, r in enumerate(rows):
            F = ref_fk(rob, r[1])
            p = [F[i][3] for i in range(3)]
            stepl = math.sqrt(sum((a - b) ** 2 for a, b in zip(p, prev)))
            check(stepl <= speed * dt * (1 + 1e-3) + 1e-5, 'move line: period %d tool step %.9g beyond speed dt' %
                  (k + 1, stepl))
            prev = p
            s = sum((p[i] - p0[i]) * dp[i] for i in range(3)) / (L * L)
            foot = [p0[i] + s * dp[i] for i in range(3)]
            on_line = max(on_line, math.sqrt(sum((a - b) ** 2 for a, b in zip(p, foot))))
            if max(abs(p[i] - pB[i]) for i in range(3)) <= 5e-6 and rot_angle(F, B) <= 5e-5:
                reached = k + 1
                break
        check(reached is not None, 'move line: the end frame never reached')
        if reached is not None:
            check(abs(reached - (math.ceil(Tl / dt) + 1)) <= 2, 'move line: end reached at period %d, planned %d' %
                  (reached, math.ceil(Tl / dt) + 1))
        check(on_line <= 1e-5, 'move line: the tool %.3g off the line' % on_line)
        print('move line/arc/joint: %d periods, line %d (planned T %.4g s), tool off the line %.3g, largest step '
              '%.4f of vmax dt, change %.4f of amax dt^2' % (len(rows), reached or 0, Tl, on_line, wv, wa))

    # 2b. the same line jerk-limited (--jerk: the tool's linear jerk, the
    # angular one J raccel / accel): every period ok, slower than the
    # trapezoid, the tool on the line, its jerk by third differences over
    # windows of 10 periods within J, the end frame reached
    jerk = 5.0
    rc, out, err = run(['move', path, '--q0', ','.join(map(str, qa)), '--dt', str(dt), '--speed', str(speed),
                        '--accel', str(accel), '--rspeed', str(rsp), '--raccel', str(racc), '--jerk', str(jerk),
                        '--line', endB])
    check(rc == 0 and err == '', 'move --jerk line: rc %d err %r' % (rc, err))
    head, jl = read_csv(out, n)
    check(head == head_want and jl and None not in jl, 'move --jerk line: header %r' % head)
    if jl and None not in jl and rows and None not in rows:
        check(all(r[2] == 'ok' for r in jl), 'move --jerk line: not ok: %r' % [r for r in jl if r[2] != 'ok'][:2])
        check_joint_limits('move --jerk line', qa, jl, [vm] * n, [am] * n, dt, [4 * f32_ulp(360.0)] * n)
        pts = [p0] + [[F[i][3] for i in range(3)] for F in (ref_fk(rob, r[1]) for r in jl)]
        L = math.sqrt(sum(d * d for d in dp))
        off = max(math.sqrt(sum((p[i] - p0[i] - sum((p[k] - p0[k]) * dp[k] for k in range(3)) / (L * L) * dp[i]) ** 2
                                for i in range(3))) for p in pts)
        check(off <= 1e-5, 'move --jerk line: the tool %.3g off the line' % off)
        # each tool point is within e of its path point: the tracker's
        # default tolerance 2e-6 L (L the sum of |a| and |d|) plus the float
        # FK's error it is measured with (1e-6); a third difference of four
        # such points carries up to 8 e of them, so the windows are long
        # enough (25 periods) for that to be a small part of J
        e = 2e-6 * sum(abs(j['a']) + abs(j['d']) for j in rob['joints']) + 1e-6
        w = 25
        jw = window_jerk(pts, w, dt)
        slack = 8.0 * e / (w * dt) ** 3
        check(jw <= jerk * (1 + 1e-3) + slack, 'move --jerk line: jerk %.6g over %d periods beyond %g + %.3g' %
              (jw, w, jerk, slack))
        F, E = ref_fk(rob, jl[-1][1]), B
        pe = max(abs(F[i][3] - E[i][3]) for i in range(3))
        check(pe <= 5e-6 and rot_angle(F, E) <= 5e-5, 'move --jerk line: last line %.3g, %.3g rad from the end' %
              (pe, rot_angle(F, E)))
        line_periods = reached if reached is not None else len(rows)
        check(len(jl) > line_periods, 'move --jerk line: %d periods, the trapezoid %d' % (len(jl), line_periods))
        print('move --jerk line: %d periods (trapezoid %d), jerk <= %.4g of %g over %d periods, tool off the line '
              '%.3g' % (len(jl), line_periods, jw, jerk, w, off))

    # 3. a Puma 560 line ending at rest on its end frame
    puma = move_robot(tmp, 'puma_rates.dh', os.path.join(ROOT, 'examples', 'robots', 'puma560.dh'), 150.0, 600.0)
    prob = read_robot(open(puma).read())
    pq = [10.0, -30.0, 45.0, 20.0, 35.0, -60.0]
    P = ref_fk(prob, pq)
    endP = 'trans(%.6f,%.6f,%.6f) %s' % (P[0][3] + 0.2, P[1][3] + 0.07, P[2][3] + 0.12, to_expr(P).split(' ', 1)[1])
    rc, out, err = run(['move', puma, '--q0', ','.join(map(str, pq)), '--dt', '0.002', '--speed', '0.3', '--accel',
                        '1.5', '--rspeed', '90', '--raccel', '360', '--line', endP])
    head, prows = read_csv(out, 6)
    check(rc == 0 and prows and None not in prows and all(r[2] == 'ok' for r in prows), 'move puma: rc %d %r' %
          (rc, err))
    if prows and None not in prows:
        check_joint_limits('move puma', pq, prows, [150.0] * 6, [600.0] * 6, 0.002, [4 * f32_ulp(360.0)] * 6)
        F, E = ref_fk(prob, prows[-1][1]), ref_expr(endP)
        pe = max(abs(F[i][3] - E[i][3]) for i in range(3))
        check(pe <= 5e-6 and rot_angle(F, E) <= 5e-5, 'move puma: last line %.3g, %.3g rad from the end' %
              (pe, rot_angle(F, E)))

    # 3b. docs/motion.md's Puma 560 line ending in the base's orientation (the
    # wrist asked for more than its rates): it slows down and completes (exit 3), lagging on
    # at most a quarter of its periods, every joint step within the limits,
    # at rest on its end frame
    endI = 'trans(0.5,-0.03,1.0)'
    rc, out, err = run(['move', puma, '--q0', ','.join(map(str, pq)), '--dt', '0.002', '--speed', '0.3', '--accel',
                        '1.5', '--rspeed', '90', '--raccel', '360', '--line', endI])
    head, irows = read_csv(out, 6)
    check(rc == 3 and 'completed with' in err and irows and None not in irows, 'move puma infeasible: rc %d %r' %
          (rc, err))
    if irows and None not in irows:
        lag = sum(1 for r in irows if r[2] == 'lagging')
        check(0 < lag <= len(irows) // 4 and irows[-1][2] == 'ok', 'move puma infeasible: %d of %d periods lagging' %
              (lag, len(irows)))
        check_joint_limits('move puma infeasible', pq, irows, [150.0] * 6, [600.0] * 6, 0.002,
                           [4 * f32_ulp(360.0)] * 6)
        F, E = ref_fk(prob, irows[-1][1]), ref_expr(endI)
        pe = max(abs(F[i][3] - E[i][3]) for i in range(3))
        check(pe <= 5e-6 and rot_angle(F, E) <= 5e-5, 'move puma infeasible: last line %.3g, %.3g rad from the end' %
              (pe, rot_angle(F, E)))
        print('move puma infeasible: %d periods, %d lagging' % (len(irows), lag))

    # 4. a line beyond reach: exit 3, the cap, unreachable periods, limits kept
    far = 'trans(-1.2,-0.35,0.35) ' + to_expr(A).split(' ', 1)[1]
    rc, out, err = run(['move', path, '--q0', ','.join(map(str, qa)), '--dt', str(dt), '--speed', str(speed),
                        '--accel', str(accel), '--rspeed', str(rsp), '--raccel', str(racc), '--line', far,
                        '--joint', ','.join('%.9g' % q for q in qb)])
    head, frows = read_csv(out, n)
    check(rc == 3 and 'segment 1 (--line) did not complete within' in err, 'move beyond reach: rc %d err %r' %
          (rc, err))
    if frows and None not in frows:
        Lf = math.sqrt(sum((a - b) ** 2 for a, b in zip(p0, [-1.2, -0.35, 0.35])))
        Tf = trap_T(1.0, speed / Lf, accel / Lf)
        cap = math.ceil((4.0 * Tf + 1.0) / dt)
        check(head == head_want and abs(len(frows) - cap) <= 2, 'move beyond reach: %d periods, cap %d' %
              (len(frows), cap))
        check(frows[-1][2] == 'unreachable', 'move beyond reach: last %r' % (frows[-1][2],))
        check_joint_limits('move beyond reach', qa, frows, [vm] * n, [am] * n, dt, [4 * f32_ulp(360.0)] * n,
                           at_rest=False)

    # 5. a blended square (--blend): shorter than the square at rest at
    # its corners, every period ok, the joints within the tracker's limits,
    # the tool's speed and acceleration within --speed and --accel by
    # finite differences over 20 periods (1e-3 relative), the tool on the
    # square's sides or within R of a corner (and off the sides somewhere)
    side, R = 0.1, 0.02
    rot = to_expr(A).split(' ', 1)[1]
    sq = [[p0[0] + side, p0[1], p0[2]], [p0[0] + side, p0[1] + side, p0[2]], [p0[0], p0[1] + side, p0[2]], p0]
    sq_args = ['move', path, '--q0', ','.join(map(str, qa)), '--dt', str(dt), '--speed', str(speed), '--accel',
               str(accel), '--rspeed', str(rsp), '--raccel', str(racc)]
    for c in sq:
        sq_args += ['--line', 'trans(%.6f,%.6f,%.6f) %s' % (c[0], c[1], c[2], rot)]
    rc0, out0, err0 = run(sq_args)
    rc, out, err = run(sq_args + ['--blend', str(R)])
    head0, rows0 = read_csv(out0, n)
    head, brows = read_csv(out, n)
    check(rc0 == 0 and rc == 0 and err == '' and head == head_want and brows and None not in brows and
          all(r[2] == 'ok' for r in brows), 'move --blend square: rc %d %d err %r' % (rc0, rc, err))
    if brows and None not in brows and rows0:
        check(len(brows) < len(rows0), 'move --blend square: %d periods, at rest %d' % (len(brows), len(rows0)))
        check_joint_limits('move --blend square', qa, brows, [vm] * n, [am] * n, dt, [4 * f32_ulp(360.0)] * n)
        pts = [p0] + [[F[i][3] for i in range(3)] for F in (ref_fk(rob, r[1]) for r in brows)]
        off, worst = polyline_dist(pts, [p0] + sq, sq[:3])
        check(worst <= R + 1e-5 and off > 1e-3, 'move --blend square: off the sides %.3g, %.6g from a corner '
              '(radius %g)' % (off, worst, R))
        vw, aw, w = check_rates('move --blend square', pts, dt, speed, accel)
        print('move --blend square: %d periods (at rest at the corners %d), off the sides %.4g m, within %.6g m of '
              'a corner there (radius %g), speed %.6g, acceleration %.6g over %d periods' %
              (len(brows), len(rows0), off, worst, R, vw, aw, w))

    # 5c. the blended square jerk-limited (--blend with --jerk): shorter
    # than the jerk-limited square at rest at its corners, every period ok,
    # the joints within the tracker's limits, the tool within R of a corner
    # off the sides (and off them somewhere), its speed and acceleration
    # over 20 periods and its jerk by third differences over 25 periods
    # (the --jerk line's windows and slack) within their limits, the end
    # frame reached
    jsq_args = sq_args + ['--jerk', str(jerk)]
    rc0, out0, err0 = run(jsq_args)
    rc, out, err = run(jsq_args + ['--blend', str(R)])
    head0, jrows0 = read_csv(out0, n)
    head, jrows = read_csv(out, n)
    check(rc0 == 0 and rc == 0 and err == '' and head == head_want and jrows and None not in jrows and
          all(r[2] == 'ok' for r in jrows), 'move --blend --jerk square: rc %d %d err %r' % (rc0, rc, err))
    if jrows and None not in jrows and jrows0:
        check(len(jrows) < len(jrows0), 'move --blend --jerk square: %d periods, at rest %d' %
              (len(jrows), len(jrows0)))
        check_joint_limits('move --blend --jerk square', qa, jrows, [vm] * n, [am] * n, dt,
                           [4 * f32_ulp(360.0)] * n)
        pts = [p0] + [[F[i][3] for i in range(3)] for F in (ref_fk(rob, r[1]) for r in jrows)]
        off, worst = polyline_dist(pts, [p0] + sq, sq[:3])
        check(worst <= R + 1e-5 and off > 1e-4, 'move --blend --jerk square: off the sides %.3g, %.6g from a '
              'corner (radius %g)' % (off, worst, R))
        vw, aw, w = check_rates('move --blend --jerk square', pts, dt, speed, accel)
        e = 2e-6 * sum(abs(j['a']) + abs(j['d']) for j in rob['joints']) + 1e-6
        wj = 25
        jw = window_jerk(pts, wj, dt)
        slack = 8.0 * e / (wj * dt) ** 3
        check(jw <= jerk * (1 + 1e-3) + slack, 'move --blend --jerk square: jerk %.6g over %d periods beyond %g + '
              '%.3g' % (jw, wj, jerk, slack))
        F = ref_fk(rob, jrows[-1][1])
        pe = max(abs(F[i][3] - p0[i]) for i in range(3))
        check(pe <= 5e-6, 'move --blend --jerk square: last line %.3g from the end' % pe)
        print('move --blend --jerk square: %d periods (at rest at the corners %d), off the sides %.4g m, within '
              '%.6g m of a corner there (radius %g), speed %.6g, acceleration %.6g over %d periods, jerk %.6g over '
              '%d' % (len(jrows), len(jrows0), off, worst, R, vw, aw, w, jw, wj))

    # 5b. a blended line, arc, line (--blend with an arc): shorter than at
    # rest at its corners, every period ok, the joints within the tracker's
    # limits, the tool's speed and acceleration (the arc's centripetal one
    # included) within --speed and --accel by finite differences over 20
    # periods (1e-3 relative), the tool on its line or arc (1e-5 m: the
    # tracker's tolerance and the float FK) or within R of a corner (and
    # off the path by more than 10 times that somewhere)
    c1 = [p0[0] + side, p0[1], p0[2]]
    c2 = [p0[0] + side, p0[1] + side, p0[2]]
    c3 = [p0[0], p0[1] + side, p0[2]]
    via = [p0[0] + 1.3 * side, p0[1] + 0.5 * side, p0[2]]
    tr = lambda c: 'trans(%.6f,%.6f,%.6f) %s' % (c[0], c[1], c[2], rot)
    la_args = sq_args[:sq_args.index('--line')] + ['--line', tr(c1), '--arc', 'trans(%.6f,%.6f,%.6f)' % tuple(via),
                                                   tr(c2), '--line', tr(c3)]
    rc0, out0, err0 = run(la_args)
    rc, out, err = run(la_args + ['--blend', str(R)])
    head0, rows0 = read_csv(out0, n)
    head, lrows = read_csv(out, n)
    check(rc0 == 0 and rc == 0 and err == '' and head == head_want and lrows and None not in lrows and
          all(r[2] == 'ok' for r in lrows), 'move --blend line-arc-line: rc %d %d err %r' % (rc0, rc, err))
    if lrows and None not in lrows and rows0:
        check(len(lrows) < len(rows0), 'move --blend line-arc-line: %d periods, at rest %d' %
              (len(lrows), len(rows0)))
        check_joint_limits('move --blend line-arc-line', qa, lrows, [vm] * n, [am] * n, dt, [4 * f32_ulp(360.0)] * n)
        pts = [p0] + [[F[i][3] for i in range(3)] for F in (ref_fk(rob, r[1]) for r in lrows)]
        # the circle through c1, via, c2 (all at height p0[2]): centre in the plane
        (ax, ay), (bx, by), (vx, vy) = c1[:2], c2[:2], via[:2]
        dd = 2.0 * (ax * (vy - by) + vx * (by - ay) + bx * (ay - vy))
        ux = ((ax * ax + ay * ay) * (vy - by) + (vx * vx + vy * vy) * (by - ay) + (bx * bx + by * by) * (ay - vy)) / dd
        uy = ((ax * ax + ay * ay) * (bx - vx) + (vx * vx + vy * vy) * (ax - bx) + (bx * bx + by * by) * (vx - ax)) / dd
        rho = math.hypot(ax - ux, ay - uy)

        def arc_dist(p):
            # the arc is the part of the circle on the via point's side of the chord c1 c2 (x >= c1's)
            if p[0] < c1[0]:
                return min(math.sqrt(sum((p[i] - c[i]) ** 2 for i in range(3))) for c in (c1, c2))
            return math.hypot(p[2] - p0[2], math.hypot(p[0] - ux, p[1] - uy) - rho)
        worst, off, onp = 0.0, 0.0, 0.0
        for p in pts:
            ds = min(seg_dist(p, p0, c1), arc_dist(p), seg_dist(p, c2, c3))
            dc = min(math.sqrt(sum((p[i] - c[i]) ** 2 for i in range(3))) for c in (c1, c2))
            off = max(off, ds)
            if ds > 1e-5:
                worst = max(worst, dc)
        check(worst <= R + 1e-5 and off > 1e-4, 'move --blend line-arc-line: off the path %.3g, %.6g from a corner '
              '(radius %g)' % (off, worst, R))
        vw, aw, w = check_rates('move --blend line-arc-line', pts, dt, speed, accel)
        print('move --blend line-arc-line: %d periods (at rest at the corners %d), off the path %.4g m, within %.6g m '
              'of a corner there (radius %g), speed %.6g, acceleration %.6g over %d periods' %
              (len(lrows), len(rows0), off, worst, R, vw, aw, w))

    # 6. every bad argument: exit 2, nothing on stdout, the message naming it
    q0 = ['--q0', ','.join(map(str, qa))]
    cart = ['--speed', '0.2', '--accel', '1', '--rspeed', '60', '--raccel', '240']
    jt = ['--joint', '0,0,0,0,0,0']
    ln = ['--line', to_expr(A)]
    no_amax = os.path.join(tmp, 'ur5_vmax_only.dh')
    with open(no_amax, 'w') as f:
        f.write(open(ur5).read().replace('max=360\n', 'max=360 vmax=100\n'))
    cases = [
        ([path, '--dt', '0.01'] + jt, 'move needs --q0'),
        ([path] + q0 + jt, 'move needs --dt'),
        ([path] + q0 + ['--dt', '0.01'], 'move needs at least one segment'),
        (q0 + ['--dt', '0.01'] + jt, 'move needs a ROBOT'),
        ([path, path] + q0 + ['--dt', '0.01'] + jt, 'extra argument'),
        ([path] + q0 + ['--dt', '0'] + jt, '--dt'),
        ([path] + q0 + ['--dt', 'x'] + jt, "bad number 'x' for --dt"),
        ([path, '--q0', '1,2'] + ['--dt', '0.01'] + jt, '--q0: expected 6 values'),
        ([path, '--q0', '400,0,0,0,0,0'] + ['--dt', '0.01'] + jt, '--q0: a joint value is outside its limits'),
        ([path] + q0 + ['--dt', '0.01', '--vmax', '0'] + jt, '--vmax: joint 1 value 0'),
        ([path] + q0 + ['--dt', '0.01', '--vmax', '1,2'] + jt, '--vmax: expected 6 values'),
        ([path] + q0 + ['--dt', '0.01', '--amax', '-5'] + jt, '--amax: joint 1 value -5'),
        ([ur5] + q0 + ['--dt', '0.01'] + jt, 'move: no --vmax and joint 1 has no vmax='),
        ([no_amax] + q0 + ['--dt', '0.01'] + jt, 'move: no --amax and joint 1 has no amax='),
        ([path] + q0 + ['--dt', '0.01', '--joint', '1,2,3'], 'segment 1 (--joint): expected 6 values'),
        ([path] + q0 + ['--dt', '0.01'] + jt + ['--joint', '0,0,0,0,0,361'], 'segment 2 (--joint): a joint value is '
                                                                              'outside its limits'),
        ([path] + q0 + ['--dt', '0.01'] + ln, 'a --line or --arc segment needs --speed'),
        ([path] + q0 + ['--dt', '0.01', '--speed', '0.2', '--accel', '1', '--rspeed', '60'] + ln, 'needs --raccel'),
        ([path] + q0 + ['--dt', '0.01', '--speed', '0', '--accel', '1', '--rspeed', '60', '--raccel', '1'] + ln,
         '--speed: 0 must be'),
        ([path] + q0 + ['--dt', '0.01'] + cart + jt + ['--line', 'trans(1,2'], 'segment 2 (--line): end frame EXPR, '
                                                                               'column'),
        ([path] + q0 + ['--dt', '0.01'] + cart + ['--line', 'scale(2,1,1)'], 'segment 1 (--line): end frame: not a '
                                                                             'rigid frame'),
        ([path] + q0 + ['--dt', '0.01'] + cart + ['--arc', 'trans(%r,%r,%r)' % tuple(p0), to_expr(B)],
         'segment 1 (--arc): no path from the previous segment\'s end: the start, via and end points are collinear'),
        ([path] + q0 + ['--dt', '0.01'] + cart + ['--arc', 'ident'], "'--arc' needs two values"),
        ([path] + q0 + ['--dt', '0.01', '--jerk', '0'] + jt, '--jerk: 0 must be'),
        ([path] + q0 + ['--dt', '0.01', '--jerk', '1e38', '--speed', '0.2', '--accel', '1e-30', '--rspeed', '60',
                        '--raccel', '240'] + ln, 'move --jerk: the angular jerk limit J * raccel / accel is not a '
                                                 'positive float'),
        ([path] + q0 + ['--dt', '0.01', '--blend', '-0.01'] + cart + ln + ln, '--blend: -0.01 must be a finite radius'),
        ([path] + q0 + ['--dt', '0.01', '--blend', '-0.01', '--jerk', '100'] + cart + ln + ln,
         '--blend: -0.01 must be a finite radius'),
        ([path] + q0 + ['--dt', '0.01', '--blend', 'r'] + cart + ln + ln, "bad number 'r' for --blend"),
        ([path] + q0 + ['--dt', '0.01', '--fixed', '--jerk', '10', '--blend', '1'] + jt,
         'move --fixed --jerk --blend: the fixed-point blended corners are not jerk-limited'),
        ([path] + q0 + ['--dt', '0.01', '--dt', '0.02'] + jt, "option '--dt' given more than once"),
        ([path] + q0 + ['--dt', '0.01', '--frames'] + jt, "unknown or inapplicable option '--frames'"),
        ([path] + q0 + ['--dt', '0.01', '--joint'], "option '--joint' needs a value"),
        ([path] + q0 + ['--dt', '1e-7', '--joint', '300,0,0,0,0,0'], 'more than 1000000 control periods'),
        (['-'] + q0 + ['--dt', '0.01'] + cart + ['--line', '-'], "'-' (standard input) given more than once"),
        ([os.path.join(tmp, 'none.dh')] + q0 + ['--dt', '0.01'] + jt, 'cannot open robot file'),
    ]
    for args, want in cases:
        rc, out, err = run(['move'] + args)
        check(rc == 2 and out == '' and want in err and err.startswith('dhmath: '),
              'move %r: rc %d out %r err %r (want %r)' % (args, rc, out[:80], err, want))


def group_move_fixed(seed, tmp):
    """dhmath move --fixed on the UR5 in mm: a line, an arc and a joint move
    through the fixed executor and tracker; the rows against the float
    run's (the same periods, every tool position within the two trackers'
    tolerances, 2^-19 L each, and the two paths' rounding of each other);
    every step within the fixed bound floor(vmax 2^16 dt_us / 10^6) LSB and
    every change of step within the fixed amax bound (finite differences of
    the printed values, which %.9g prints exactly); the tool on the line
    within 5e-3 mm; the joint move's end exact; --fixed with --jerk and a
    --dt that is no whole number of microseconds: exit 2; a blended square
    (move_fixed_blend) and a line-arc-line one (move_fixed_blend_arc); a
    lagging Puma queue (move_fixed_lagging)."""
    rng = random.Random(seed)
    ur5 = os.path.join(ROOT, 'examples', 'robots', 'ur5_mm.dh')
    rob = read_robot(open(ur5).read())
    n = len(rob['joints'])
    vm, am, dt = 180.0, 720.0, 0.004
    path = move_robot(tmp, 'ur5_mm_rates.dh', ur5, vm, am)
    qa = [10.0, -60.0, 70.0, 20.0, 40.0, 30.0]
    qb = [round(q + rng.uniform(-30.0, 30.0), 3) for q in qa]
    A = ref_fk(rob, qa)
    p0 = [A[r][3] for r in range(3)]
    dp = [rng.uniform(-80.0, 80.0) for _ in range(3)]
    pB = [p0[r] + dp[r] for r in range(3)]
    rB = [rng.uniform(-1, 1) for _ in range(3)] + [rng.uniform(-20.0, 20.0)]
    endB = 'trans(%.6f,%.6f,%.6f) %s rot(%.6f,%.6f,%.6f,%.6f)' % tuple(pB + [to_expr(A).split(' ', 1)[1]] + rB)
    ax = [0.0, 0.0, 1.0] if abs(dp[2]) < 0.9 * math.sqrt(sum(d * d for d in dp)) else [1.0, 0.0, 0.0]
    nv = [dp[1] * ax[2] - dp[2] * ax[1], dp[2] * ax[0] - dp[0] * ax[2], dp[0] * ax[1] - dp[1] * ax[0]]
    nn = math.sqrt(sum(v * v for v in nv))
    via = [p0[r] + 0.5 * dp[r] + 50.0 * nv[r] / nn for r in range(3)]
    args = [path, '--q0', ','.join(map(str, qa)), '--dt', str(dt), '--speed', '250', '--accel', '1000', '--rspeed',
            '60', '--raccel', '240', '--line', endB, '--arc', 'trans(%.6f,%.6f,%.6f)' % tuple(via), to_expr(A),
            '--joint', ','.join('%.9g' % q for q in qb)]
    rc, out, err = run(['move'] + args + ['--fixed'])
    check(rc == 0 and err == '', 'move --fixed: rc %d err %r' % (rc, err))
    head, rows = read_csv(out, n)
    rc2, out2, err2 = run(['move'] + args)
    head2, frows = read_csv(out2, n)
    check(rc2 == 0 and head == head2 and rows and None not in rows, 'move --fixed: header %r' % head)
    if not rows or None in rows or not frows or None in frows:
        return
    check(all(r[2] == 'ok' for r in rows), 'move --fixed: not ok: %r' % [r for r in rows if r[2] != 'ok'][:2])
    check(len(rows) == len(frows), 'move --fixed: %d periods, the float run %d' % (len(rows), len(frows)))
    L = sum(abs(j[1]) + abs(j[2]) for j in ((0, 89.159, 0), (0, 425, 0), (0, 392.25, 0), (0, 109.15, 0),
                                            (0, 94.65, 0), (0, 82.3, 0)))
    tol = 2.0 * 2.0 ** -19 * L + 1e-3
    worst = 0.0
    for r, f in zip(rows, frows):
        F, G = ref_fk(rob, r[1]), ref_fk(rob, f[1])
        worst = max(worst, math.sqrt(sum((F[i][3] - G[i][3]) ** 2 for i in range(3))))
    check(worst <= tol, 'move --fixed: tool %.3g mm from the float run (bound %.3g)' % (worst, tol))
    # the fixed bounds: floor(vmax 2^16 dt_us / 10^6) LSB per step and
    # floor(floor(amax 2^16 dt_us / 10^6) dt_us / 10^6) per change of step
    us = round(dt * 1e6)
    vb = math.floor(vm * 65536 * us / 1e6) / 65536.0
    ab = math.floor(math.floor(am * 65536 * us / 1e6) * us / 1e6) / 65536.0
    check_joint_limits('move --fixed', qa, rows, [vb / dt] * n, [ab / (dt * dt)] * n, dt, [4 * f32_ulp(360.0)] * n)
    check(rows[-1][1] == [f32(math.floor(q * 65536 + 0.5) / 65536.0) for q in qb],
          'move --fixed: last line %r, not %r' % (rows[-1][1], qb))
    L1 = math.sqrt(sum(d * d for d in dp))
    off = 0.0
    for r in rows:
        F = ref_fk(rob, r[1])
        p = [F[i][3] for i in range(3)]
        s = max(0.0, min(1.0, sum((p[i] - p0[i]) * dp[i] for i in range(3)) / (L1 * L1)))
        d = math.sqrt(sum((p[i] - p0[i] - s * dp[i]) ** 2 for i in range(3)))
        if max(abs(p[i] - pB[i]) for i in range(3)) <= 5e-3:
            break
        off = max(off, d)
    check(off <= 5e-3, 'move --fixed: the tool %.3g mm off the line' % off)
    print('move --fixed: %d periods (float %d), tool within %.3g mm of the float run, %.3g mm off the line' %
          (len(rows), len(frows), worst, off))
    q0 = ['--q0', ','.join(map(str, qa))]
    cart = ['--speed', '200', '--accel', '1000', '--rspeed', '60', '--raccel', '240']
    ln = ['--line', to_expr(A)]
    for extra, want in ((['--jerk', '100', '--blend', '2'] + ln + ln, 'move --fixed --jerk --blend: the fixed-point'),
                        (['--jerk', '40000'] + ln, '--jerk: out of the fixed-point range'),
                        (['--speed', '40000'] + cart[2:] + ln, '--speed: out of the fixed-point range')):
        a = [path] + q0 + ['--dt', '0.004', '--fixed'] + (cart if '--speed' not in extra else []) + extra
        rc, out, err = run(['move'] + a)
        check(rc == 2 and out == '' and want in err, 'move %r: rc %d err %r (want %r)' % (a, rc, err, want))
    rc, out, err = run(['move', path] + q0 + ['--dt', '0.0000015', '--fixed', '--joint', '0,0,0,0,0,0'])
    check(rc == 2 and out == '' and 'whole number of microseconds' in err, 'move --fixed --dt: rc %d %r' % (rc, err))
    move_fixed_blend(rob, n, path, qa, A, p0)
    move_fixed_blend_arc(rob, n, path, qa, A, p0)
    move_fixed_lagging(tmp)
    move_fixed_blend_lagging(tmp)
    move_blend_jerk_lagging(tmp)
    move_fixed_jerk(rob, n, path, qa, qb, A, endB, p0, pB, dp)


def move_blend_jerk_lagging(tmp):
    """move --blend --jerk through the float queue: the Puma 560 line of
    'move puma infeasible' (the wrist asked for more than its rates)
    blended within R = 2 cm into a line 15 cm down: lagging periods
    reported (exit 3), the queue's feed override slowing the move, which
    completes; every joint step and change of step within the tracker's
    limits (finite differences of the printed values), the tool (double FK
    of the printed joints) at ok periods within 5e-6 m of the lines or
    within R of their corner, off the lines somewhere, and at rest on the
    last line's end (5e-6 m)."""
    puma = move_robot(tmp, 'puma_rates_bj.dh', os.path.join(ROOT, 'examples', 'robots', 'puma560.dh'), 150.0, 600.0)
    rob = read_robot(open(puma).read())
    pq, dt, R = [10.0, -30.0, 45.0, 20.0, 35.0, -60.0], 0.002, 0.02
    ends = [None, [0.5, -0.03, 1.0], [0.5, -0.03, 0.85]]
    A = ref_fk(rob, pq)
    ends[0] = [A[i][3] for i in range(3)]
    args = ['move', puma, '--q0', ','.join(map(str, pq)), '--dt', str(dt), '--speed', '0.3', '--accel', '1.5',
            '--rspeed', '90', '--raccel', '360', '--jerk', '8', '--line', 'trans(0.5,-0.03,1.0)', '--line',
            'trans(0.5,-0.03,0.85)', '--blend', str(R)]
    rc, out, err = run(args)
    head, rows = read_csv(out, 6)
    check(rc == 3 and 'completed with' in err and rows and None not in rows,
          'move --blend --jerk puma lagging: rc %d %r' % (rc, err))
    if not rows or None in rows:
        return
    lag = sum(1 for r in rows if r[2] == 'lagging')
    check(lag > 0 and rows[-1][2] == 'ok', 'move --blend --jerk puma lagging: %d of %d periods lagging' %
          (lag, len(rows)))
    check_joint_limits('move --blend --jerk puma lagging', pq, rows, [150.0] * 6, [600.0] * 6, dt,
                       [4 * f32_ulp(360.0)] * 6)
    worst, off = 0.0, 0.0
    for r in rows:
        if r[2] != 'ok':
            continue
        F = ref_fk(rob, r[1])
        p = [F[i][3] for i in range(3)]
        ds = min(seg_dist(p, ends[0], ends[1]), seg_dist(p, ends[1], ends[2]))
        if ds > 5e-6:
            off = max(off, ds)
            worst = max(worst, math.sqrt(sum((p[i] - ends[1][i]) ** 2 for i in range(3))))
    F = ref_fk(rob, rows[-1][1])
    pe = max(abs(F[i][3] - ends[2][i]) for i in range(3))
    check(off > 1e-4 and worst <= R + 1e-5 and pe <= 5e-6,
          'move --blend --jerk puma lagging: off the lines %.3g, %.6g from the corner (radius %g), end %.3g' %
          (off, worst, R, pe))
    print('move --blend --jerk puma lagging: %d periods, %d lagging, ok periods off the lines up to %.4g m, within '
          '%.6g m of the corner there (radius %g), end %.3g m' % (len(rows), lag, off, worst, R, pe))


def move_fixed_blend_lagging(tmp):
    """move --fixed --blend through the fixed queue: the Puma 560 (mm)
    line of move_fixed_lagging blended within 20 mm into a line 150 mm
    down, then a joint move back: lagging periods reported (exit 3), the
    move completed, every joint step and change of step within the fixed
    bounds (finite differences of the printed values), the joint move's end
    exact, the tool (double FK of the printed joints, within the fixed
    tracker's 5e-3 mm of its target at ok periods) within 5e-3 mm of the
    lines or within R + 5e-3 mm of their corner, and the run shorter than
    with the corner at rest (the wrist lags near the corner, so the blend
    itself passes in lagging periods)."""
    puma = os.path.join(ROOT, 'examples', 'robots', 'puma560_mm.dh')
    path = move_robot(tmp, 'puma560_mm_rates.dh', puma, 150.0, 600.0)
    rob = read_robot(open(path).read())
    pq, dt, R = [10.0, -30.0, 45.0, 20.0, 35.0, -60.0], 0.002, 20.0
    args = ['move', path, '--q0', ','.join(map(str, pq)), '--dt', str(dt), '--speed', '300', '--accel', '1500',
            '--rspeed', '90', '--raccel', '360', '--line', 'trans(500,-30,1000)', '--line', 'trans(500,-30,850)',
            '--joint', ','.join(map(str, pq)), '--fixed']
    rc0, out0, err0 = run(args)
    rc, out, err = run(args + ['--blend', str(R)])
    head0, rows0 = read_csv(out0, 6)
    head, rows = read_csv(out, 6)
    check(rc == 3 and 'completed with' in err and rows and None not in rows,
          'move --fixed --blend puma lagging: rc %d %r' % (rc, err))
    if not rows or None in rows:
        return
    lag = sum(1 for r in rows if r[2] == 'lagging')
    check(lag > 0 and rows[-1][2] == 'ok', 'move --fixed --blend puma lagging: %d of %d periods lagging' %
          (lag, len(rows)))
    us = round(dt * 1e6)
    vb = math.floor(150.0 * 65536 * us / 1e6) / 65536.0
    ab = math.floor(math.floor(600.0 * 65536 * us / 1e6) * us / 1e6) / 65536.0
    check_joint_limits('move --fixed --blend puma lagging', pq, rows, [vb / dt] * 6, [ab / (dt * dt)] * 6, dt,
                       [4 * f32_ulp(360.0)] * 6)
    check(rows[-1][1] == [f32(math.floor(q * 65536 + 0.5) / 65536.0) for q in pq],
          'move --fixed --blend puma lagging: last line %r, not %r' % (rows[-1][1], pq))
    A = ref_fk(rob, pq)
    ends = [[A[i][3] for i in range(3)], [500.0, -30.0, 1000.0], [500.0, -30.0, 850.0]]

    def seg_dist(p, a, b):
        d = [b[i] - a[i] for i in range(3)]
        u = max(0.0, min(1.0, sum((p[i] - a[i]) * d[i] for i in range(3)) / sum(x * x for x in d)))
        return math.sqrt(sum((p[i] - a[i] - u * d[i]) ** 2 for i in range(3)))
    worst, off, nline = 0.0, 0.0, 0
    for r in rows:
        F = ref_fk(rob, r[1])
        p = [F[i][3] for i in range(3)]
        if math.sqrt(sum((p[i] - ends[2][i]) ** 2 for i in range(3))) <= 5e-3:
            break    # the second line's end: the joint move back follows
        if r[2] != 'ok':
            continue
        ds = min(seg_dist(p, ends[0], ends[1]), seg_dist(p, ends[1], ends[2]))
        nline += 1
        off = max(off, ds)
        if ds > 5e-3:
            worst = max(worst, math.sqrt(sum((p[i] - ends[1][i]) ** 2 for i in range(3))))
    check(nline > 0 and worst <= R + 5e-3 and rc0 == 3 and len(rows) < len(rows0),
          'move --fixed --blend puma lagging: off the lines %.3g, %.6g from the corner (radius %g), %d periods (at '
          'rest %d)' % (off, worst, R, len(rows), len(rows0)))
    print('move --fixed --blend puma lagging: %d periods (at rest at the corner %d), %d lagging, ok periods off the '
          'lines %.4g mm, within %.6g mm of the corner there (radius %g)' % (len(rows), len(rows0), lag, off, worst, R))


def move_fixed_jerk(rob, n, path, qa, qb, A, endB, p0, pB, dp):
    """move --fixed --jerk J on the UR5 (mm): a joint move, exit 0, every
    joint's third difference over windows of w periods within J (deg/s^3)
    times 1 + 1e-3 plus 8 e / (w dt)^3 (e: the fixed joint move's 4 LSB +
    2^-27 of its distance, 5 LSB), w the least window with that noise
    within 2.5e-4 of J; steps and changes of step within the fixed vmax
    and amax bounds; the end exactly qb. A line and an arc with --jerk:
    exit 0, every period ok, the tool within 5e-3 mm of the line, the
    same number of periods as the float run's (both the seven-phase
    minimum), the last row's tool at B."""
    dt, J = 0.004, 1500.0
    rc, out, err = run(['move', path, '--q0', ','.join(map(str, qa)), '--dt', str(dt), '--jerk', str(J), '--joint',
                        ','.join('%.9g' % q for q in qb), '--fixed'])
    head, rows = read_csv(out, n)
    check(rc == 0 and err == '' and rows and None not in rows, 'move --fixed --jerk joint: rc %d %r' % (rc, err))
    if not rows or None in rows:
        return
    us = round(dt * 1e6)
    vb = math.floor(180.0 * 65536 * us / 1e6) / 65536.0
    ab = math.floor(math.floor(720.0 * 65536 * us / 1e6) * us / 1e6) / 65536.0
    check_joint_limits('move --fixed --jerk', qa, rows, [vb / dt] * n, [ab / (dt * dt)] * n, dt,
                       [4 * f32_ulp(360.0)] * n)
    e = 5.0 / 65536.0
    w = int(math.ceil((8.0 * e / (2.5e-4 * J)) ** (1.0 / 3.0) / dt))
    qs = [qa] * (3 * w) + [r[1] for r in rows] + [rows[-1][1]] * (3 * w)
    worst, windows = 0.0, 0
    for k in range(len(qs) - 3 * w):
        h = (w * dt) ** 3
        for i in range(n):
            d = abs(qs[k + 3 * w][i] - 3.0 * qs[k + 2 * w][i] + 3.0 * qs[k + w][i] - qs[k][i]) / h
            worst = max(worst, d / J)
            check(d <= J * (1.0 + 1e-3) + 8.0 * e / h, 'move --fixed --jerk joint: jerk %.6g > %g (joint %d, window '
                  '%d at %d)' % (d, J, i + 1, w, k))
        windows += 1
    check(rows[-1][1] == [f32(math.floor(q * 65536 + 0.5) / 65536.0) for q in qb],
          'move --fixed --jerk joint: last line %r, not %r' % (rows[-1][1], qb))
    print('move --fixed --jerk: joint move of %d periods, largest jerk %.4f of J over %d windows of %d periods' %
          (len(rows), worst, windows, w))
    ax = [0.0, 0.0, 1.0] if abs(dp[2]) < 0.9 * math.sqrt(sum(d * d for d in dp)) else [1.0, 0.0, 0.0]
    nv = [dp[1] * ax[2] - dp[2] * ax[1], dp[2] * ax[0] - dp[0] * ax[2], dp[0] * ax[1] - dp[1] * ax[0]]
    nn = math.sqrt(sum(v * v for v in nv))
    via = [p0[r] + 0.5 * dp[r] + 50.0 * nv[r] / nn for r in range(3)]
    args = [path, '--q0', ','.join(map(str, qa)), '--dt', str(dt), '--speed', '250', '--accel', '1000', '--rspeed',
            '60', '--raccel', '240', '--jerk', '5000', '--line', endB, '--arc', 'trans(%.6f,%.6f,%.6f)' % tuple(via),
            to_expr(A)]
    rc, out, err = run(['move'] + args + ['--fixed'])
    head, rows = read_csv(out, n)
    rc2, out2, err2 = run(['move'] + args)
    head2, frows = read_csv(out2, n)
    check(rc == 0 and err == '' and rc2 == 0 and rows and None not in rows,
          'move --fixed --jerk line, arc: rc %d %r' % (rc, err))
    if not rows or None in rows or not frows or None in frows:
        return
    check(all(r[2] == 'ok' for r in rows), 'move --fixed --jerk line, arc: not ok')
    check(len(rows) == len(frows), 'move --fixed --jerk line, arc: %d periods, the float run %d' %
          (len(rows), len(frows)))
    L1 = math.sqrt(sum(d * d for d in dp))
    off, at_b = 0.0, False
    for r in rows:
        F = ref_fk(rob, r[1])
        p = [F[i][3] for i in range(3)]
        s = max(0.0, min(1.0, sum((p[i] - p0[i]) * dp[i] for i in range(3)) / (L1 * L1)))
        off = max(off, math.sqrt(sum((p[i] - p0[i] - s * dp[i]) ** 2 for i in range(3))))
        if max(abs(p[i] - pB[i]) for i in range(3)) <= 5e-3:
            at_b = True
            break
    check(at_b and off <= 5e-3, 'move --fixed --jerk: the tool %.3g mm off the line (at B: %r)' % (off, at_b))
    F = ref_fk(rob, rows[-1][1])
    end = max(abs(F[i][3] - A[i][3]) for i in range(3))
    check(end <= 5e-3, 'move --fixed --jerk: the last row %.3g mm from the arc\'s end' % end)
    print('move --fixed --jerk: line and arc in %d periods (float %d), %.3g mm off the line, end within %.3g mm' %
          (len(rows), len(frows), off, end))


def move_fixed_lagging(tmp):
    """move --fixed through the fixed queue: the Puma 560 (mm) line of
    docs/motion.md into the base's orientation, faster than its wrist can
    follow, then a joint move back: lagging periods reported (exit 3 and
    the summary on stderr), the move slowed down by the queue's feed
    override and completed, every joint step and change of step within the
    fixed bounds (finite differences of the printed values), the joint
    move's end exact."""
    puma = os.path.join(ROOT, 'examples', 'robots', 'puma560_mm.dh')
    path = move_robot(tmp, 'puma560_mm_rates.dh', puma, 150.0, 600.0)
    pq, dt = [10.0, -30.0, 45.0, 20.0, 35.0, -60.0], 0.002
    rc, out, err = run(['move', path, '--q0', ','.join(map(str, pq)), '--dt', str(dt), '--speed', '300', '--accel',
                        '1500', '--rspeed', '90', '--raccel', '360', '--line', 'trans(500,-30,1000)', '--joint',
                        ','.join(map(str, pq)), '--fixed'])
    head, rows = read_csv(out, 6)
    check(rc == 3 and 'completed with' in err and rows and None not in rows,
          'move --fixed puma lagging: rc %d %r' % (rc, err))
    if not rows or None in rows:
        return
    lag = sum(1 for r in rows if r[2] == 'lagging')
    check(lag > 0 and rows[-1][2] == 'ok', 'move --fixed puma lagging: %d of %d periods lagging' % (lag, len(rows)))
    us = round(dt * 1e6)
    vb = math.floor(150.0 * 65536 * us / 1e6) / 65536.0
    ab = math.floor(math.floor(600.0 * 65536 * us / 1e6) * us / 1e6) / 65536.0
    check_joint_limits('move --fixed puma lagging', pq, rows, [vb / dt] * 6, [ab / (dt * dt)] * 6, dt,
                       [4 * f32_ulp(360.0)] * 6)
    check(rows[-1][1] == [f32(math.floor(q * 65536 + 0.5) / 65536.0) for q in pq],
          'move --fixed puma lagging: last line %r, not %r' % (rows[-1][1], pq))
    print('move --fixed puma lagging: %d periods, %d lagging' % (len(rows), lag))


def move_fixed_blend(rob, n, path, qa, A, p0):
    """move --fixed --blend: a blended square (100 mm sides, radius 20 mm)
    through the fixed blended sequence and tracker: shorter than the
    square at rest at its corners (--fixed without --blend), every period
    ok; the tool (double FK of the printed joints, within the fixed
    tracker's 5e-3 mm of its target) on the square's sides within 5e-3 mm
    or within R + 5e-3 mm of a corner, and off the sides somewhere; its
    speed and acceleration by finite differences over 25 periods within
    --speed and --accel times 1 + 1e-3 plus the tracker's noise (2 and 4
    times 5e-3 mm over the window and its square); every joint step within
    the robot's rates (check_joint_limits)."""
    side, R, dt, w = 100.0, 20.0, 0.002, 25
    speed, accel = 200.0, 1000.0
    rot = to_expr(A).split(' ', 1)[1]
    sq = [[p0[0] + side, p0[1], p0[2]], [p0[0] + side, p0[1] + side, p0[2]], [p0[0], p0[1] + side, p0[2]], p0]
    args = ['move', path, '--q0', ','.join(map(str, qa)), '--dt', str(dt), '--speed', str(speed), '--accel',
            str(accel), '--rspeed', '60', '--raccel', '240', '--fixed']
    for c in sq:
        args += ['--line', 'trans(%.6f,%.6f,%.6f) %s' % (c[0], c[1], c[2], rot)]
    rc0, out0, err0 = run(args)
    rc, out, err = run(args + ['--blend', str(R)])
    head0, rows0 = read_csv(out0, n)
    head, rows = read_csv(out, n)
    check(rc0 == 0 and rc == 0 and err == '' and rows and None not in rows and all(r[2] == 'ok' for r in rows),
          'move --fixed --blend square: rc %d %d err %r' % (rc0, rc, err))
    if not rows or None in rows or not rows0:
        return
    check(len(rows) < len(rows0), 'move --fixed --blend square: %d periods, at rest %d' % (len(rows), len(rows0)))
    check_joint_limits('move --fixed --blend square', qa, rows, [180.0] * n, [720.0] * n, dt,
                       [4 * f32_ulp(360.0)] * n)
    pts = [p0] + [[F[i][3] for i in range(3)] for F in (ref_fk(rob, r[1]) for r in rows)]
    corners = [p0] + sq

    def side_dist(p, a, b):
        d = [b[i] - a[i] for i in range(3)]
        u = max(0.0, min(1.0, sum((p[i] - a[i]) * d[i] for i in range(3)) / sum(x * x for x in d)))
        return math.sqrt(sum((p[i] - a[i] - u * d[i]) ** 2 for i in range(3)))
    worst, off = 0.0, 0.0
    for p in pts:
        ds = min(side_dist(p, corners[k], corners[k + 1]) for k in range(4))
        dc = min(math.sqrt(sum((p[i] - c[i]) ** 2 for i in range(3))) for c in sq[:3])
        off = max(off, ds)
        if ds > 5e-3:
            worst = max(worst, dc)
    check(worst <= R + 5e-3 and off > 1.0, 'move --fixed --blend square: off the sides %.3g, %.6g from a corner '
          '(radius %g)' % (off, worst, R))
    vw, aw, noise = 0.0, 0.0, 5e-3
    for k in range(len(pts) - 2 * w):
        d1 = [pts[k + w][i] - pts[k][i] for i in range(3)]
        d2 = [pts[k + 2 * w][i] - 2 * pts[k + w][i] + pts[k][i] for i in range(3)]
        vw = max(vw, math.sqrt(sum(x * x for x in d1)) / (w * dt))
        aw = max(aw, math.sqrt(sum(x * x for x in d2)) / (w * dt) ** 2)
    check(vw <= speed * (1 + 1e-3) + 2 * noise / (w * dt) and aw <= accel * (1 + 1e-3) + 4 * noise / (w * dt) ** 2,
          'move --fixed --blend square: speed %.6g, acceleration %.6g over %d periods' % (vw, aw, w))
    print('move --fixed --blend square: %d periods (at rest at the corners %d), off the sides %.4g mm, within '
          '%.6g mm of a corner there (radius %g), speed %.6g, acceleration %.6g over %d periods' %
          (len(rows), len(rows0), off, worst, R, vw, aw, w))


def move_fixed_blend_arc(rob, n, path, qa, A, p0):
    """move --fixed --blend with arc corners: a line (100 mm), an arc
    bulging 30 mm out of its 100 mm chord, a line (100 mm), the corners
    line-arc and arc-line blended within R = 15 mm by the fixed queue:
    shorter than at rest (--fixed without --blend), every period ok; the
    tool (double FK of the printed joints, within the fixed tracker's
    5e-3 mm of its target) within 5e-3 mm of a line or of the arc's circle
    (through its ends and via point) or within R + 5e-3 mm of a corner,
    off the paths somewhere; its speed and acceleration (centripetal
    included) by finite differences over 25 periods within --speed and
    --accel times 1 + 1e-3 plus the tracker's noise (2 and 4 times 5e-3 mm
    over the window and its square); every joint step within the robot's
    rates."""
    R, dt, w, noise = 15.0, 0.002, 25, 5e-3
    speed, accel = 200.0, 1000.0
    rot = to_expr(A).split(' ', 1)[1]
    c1 = [p0[0] + 100.0, p0[1], p0[2]]
    c2 = [p0[0] + 100.0, p0[1] + 100.0, p0[2]]
    c3 = [p0[0], p0[1] + 100.0, p0[2]]
    via = [p0[0] + 130.0, p0[1] + 50.0, p0[2]]
    # the circle through c1, via, c2: its centre on y = p0 + 50, equally far from c1 and via
    xc, yc = p0[0] + (130.0 ** 2 - 100.0 ** 2 - 50.0 ** 2) / (2.0 * 30.0), p0[1] + 50.0
    rho = math.hypot(c1[0] - xc, c1[1] - yc)
    args = ['move', path, '--q0', ','.join(map(str, qa)), '--dt', str(dt), '--speed', str(speed), '--accel',
            str(accel), '--rspeed', '60', '--raccel', '240', '--fixed', '--line', 'trans(%.6f,%.6f,%.6f) %s' %
            tuple(c1 + [rot]), '--arc', 'trans(%.6f,%.6f,%.6f)' % tuple(via), 'trans(%.6f,%.6f,%.6f) %s' %
            tuple(c2 + [rot]), '--line', 'trans(%.6f,%.6f,%.6f) %s' % tuple(c3 + [rot])]
    rc0, out0, err0 = run(args)
    rc, out, err = run(args + ['--blend', str(R)])
    head0, rows0 = read_csv(out0, n)
    head, rows = read_csv(out, n)
    check(rc0 == 0 and rc == 0 and err == '' and rows and None not in rows and all(r[2] == 'ok' for r in rows),
          'move --fixed --blend arc: rc %d %d err %r %r' % (rc0, rc, err0, err))
    if not rows or None in rows or not rows0:
        return
    check(len(rows) < len(rows0), 'move --fixed --blend arc: %d periods, at rest %d' % (len(rows), len(rows0)))
    check_joint_limits('move --fixed --blend arc', qa, rows, [180.0] * n, [720.0] * n, dt, [4 * f32_ulp(360.0)] * n)
    pts = [p0] + [[F[i][3] for i in range(3)] for F in (ref_fk(rob, r[1]) for r in rows)]

    def arc_dist(p):
        # the arc is the part of the circle on the via point's side of the chord c1 c2 (x >= c1's)
        return math.hypot(p[2] - p0[2], math.hypot(p[0] - xc, p[1] - yc) - rho) if p[0] >= c1[0] else 1e9
    off, worst = blend_dist(pts, lambda p: min(seg_dist(p, p0, c1), arc_dist(p), seg_dist(p, c2, c3)), (c1, c2),
                            5e-3)
    check(worst <= R + 5e-3 and off > 0.1, 'move --fixed --blend arc: off the paths %.3g, %.6g from a corner '
          '(radius %g)' % (off, worst, R))
    vw, aw = window_rates(pts, w, dt)
    check(vw <= speed * (1 + 1e-3) + 2 * noise / (w * dt) and aw <= accel * (1 + 1e-3) + 4 * noise / (w * dt) ** 2,
          'move --fixed --blend arc: speed %.6g, acceleration %.6g over %d periods' % (vw, aw, w))
    print('move --fixed --blend arc: %d periods (at rest at the corners %d), off the paths %.4g mm, within '
          '%.6g mm of a corner there (radius %g), speed %.6g, acceleration %.6g over %d periods' %
          (len(rows), len(rows0), off, worst, R, vw, aw, w))


def main():
    global EXE, ROOT
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    EXE, ROOT, group = sys.argv[1], sys.argv[2], sys.argv[3]
    seed = int(sys.argv[5]) if len(sys.argv) > 5 and sys.argv[4] == '--seed' else 20261124
    with tempfile.TemporaryDirectory() as tmp:
        groups = {
            'seed': group_seed,
            'errors': group_errors,
            'random': lambda: group_random(seed),
            'robotfile': lambda: group_robotfile(seed, tmp),
            'examples': group_examples,
            'rot': lambda: group_rot(seed),
            'fixed': lambda: group_fixed(seed, tmp),
            'help': group_help,
            'numbers': group_numbers,
            'messages': lambda: group_messages(tmp),
            'ikc': lambda: group_ikc(seed, tmp),
            'track': lambda: (group_track(seed, tmp), group_track_fixed(seed, tmp)),
            'move': lambda: (group_move(seed, tmp), group_move_fixed(seed, tmp)),
        }
        if group not in groups:
            print('unknown group', group)
            return 2
        groups[group]()
    print('%s: %d checks, %d failures' % (group, CHECKS[0], len(FAILS)))
    return 1 if FAILS else 0


if __name__ == '__main__':
    sys.exit(main())
