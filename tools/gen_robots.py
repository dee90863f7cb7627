#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""gen_robots.py - C tables of the shipped robots from examples/robots/*.dh.

    python3 tools/gen_robots.py -o OUT.h FILE.dh...

The .dh files are the one copy of the robots' DH tables; the tests
(test/support_robots.c, host and target) and the benchmarks
(bench/bench_ref.c, bench/target/bench_target.c) include the header this
writes, CMake runs it at build time (tools/gen_robots.cmake).

Reads the subset of the robot-file format (cli/dh_robotfile.h) that the
shipped files use, and stops with FILE:LINE: message on anything else:
  - '#' comments; the header comment must say "lengths in metres" or
    "lengths in millimetres" (any case); NAME_mm files are millimetres,
    the others metres
  - 'convention standard|modified', at most once, before the first joint
  - 'joint R|P a=.. d=.. alpha=.. theta=.. min=.. max=..' (decimal numbers;
    a, d, alpha and theta default to 0; min and max required; a prismatic
    joint's limits are lengths and scale with the millimetre twin)
  - 'base' / 'tool' EXPR: a product of trans(x,y,z) and rotz(deg) with deg a
    multiple of 45 (exact sines and cosines)

For each FILE.dh (NAME = its stem in upper case) the header defines
  DHR_NAME_NAME         "stem"
  DHR_NAME_CONV         DH_CONV_STANDARD or DH_CONV_MODIFIED
  DHR_NAME_N            number of joints
  DHR_NAME_UNIT_PER_M   1.0 (metres) or 1000.0 (millimetres)
  DHR_NAME_JOINTS(X)    X(type, a, d, alpha, theta, qmin, qmax) per joint
  DHR_NAME_BASE, DHR_NAME_TOOL   initialisers of double m[4][4],
                        column-major m[col][row] like dh_mat4_f32
All numbers are double literals that round-trip the file's values exactly,
and each converts to the same float as the decimal text would (checked
here), so (float)(x) equals the float literal xf. A metre file NAME.dh
without a NAME_mm.dh gets a millimetre twin NAME_MM (lengths times 1000.0
in double); where NAME_mm.dh exists it must agree with NAME.dh times 1000
to 1e-12 (same angles and limits, same joint count and convention).
"""
import math
import os
import re
import struct
import sys
from fractions import Fraction

NUM = re.compile(r'^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$')
KEYS = ('a', 'd', 'alpha', 'theta', 'min', 'max')
S45 = math.sqrt(0.5)
# cos, sin of k*45 degrees, k = 0..7
ROTZ = [(1.0, 0.0), (S45, S45), (0.0, 1.0), (-S45, S45),
        (-1.0, 0.0), (-S45, -S45), (0.0, -1.0), (S45, -S45)]


class GenError(Exception):
    pass


def f32(x):
    return struct.unpack('<f', struct.pack('<f', x))[0]


def f32_of_decimal(text):
    """Nearest float to the exact decimal value (ties to even)."""
    exact = Fraction(text)
    f = f32(float(exact))
    bits = struct.unpack('<i', struct.pack('<f', f))[0]
    best = f
    for nb in (bits - 1, bits + 1):
        g = struct.unpack('<f', struct.pack('<i', nb))[0]
        if not math.isfinite(g):
            continue
        dg, db = abs(Fraction(g) - exact), abs(Fraction(best) - exact)
        if dg < db or (dg == db and nb % 2 == 0):
            best = g
    return best


def number(text, where):
    if not NUM.match(text):
        raise GenError('%s: not a decimal number: %r' % (where, text))
    x = float(text)
    if f32(x) != f32_of_decimal(text):
        raise GenError('%s: %s rounds to a different float through double' % (where, text))
    return x


def ident():
    return [[1.0 if c == r else 0.0 for r in range(4)] for c in range(4)]


def mul(A, B):
    """A * B, column-major m[col][row]."""
    return [[sum(A[k][r] * B[c][k] for k in range(4)) for r in range(4)] for c in range(4)]


def frame(text, where):
    T = ident()
    rest = text.strip()
    while rest:
        m = re.match(r'(trans|rotz)\(([^()]*)\)\s*', rest)
        if not m:
            raise GenError('%s: only trans(x,y,z) and rotz(deg) products are supported, not %r'
                           % (where, rest))
        args = [a.strip() for a in m.group(2).split(',')]
        if m.group(1) == 'trans':
            if len(args) != 3:
                raise GenError('%s: trans needs 3 arguments' % where)
            F = ident()
            F[3][0:3] = [number(a, where) for a in args]
        else:
            if len(args) != 1:
                raise GenError('%s: rotz needs 1 argument' % where)
            deg = number(args[0], where)
            if deg % 45.0 != 0.0:
                raise GenError('%s: rotz angle %s is not a multiple of 45' % (where, args[0]))
            c, s = ROTZ[int(deg // 45.0) % 8]
            F = ident()
            F[0][0], F[0][1], F[1][0], F[1][1] = c, s, -s, c
        T = mul(T, F)
        rest = rest[m.end():]
    return T


def parse(path):
    stem = os.path.splitext(os.path.basename(path))[0]
    if not re.match(r'^[a-z][a-z0-9_]*$', stem):
        raise GenError('%s: file name must be a C identifier in lower case' % path)
    rob = {'stem': stem, 'conv': None, 'joints': [], 'base': None, 'tool': None, 'unit': None}
    with open(path, encoding='ascii') as fh:
        lines = fh.read().split('\n')
    for no, raw in enumerate(lines, 1):
        where = '%s:%d' % (path, no)
        line = raw.rstrip('\r')
        text, _, comment = line.partition('#')
        low = comment.lower()
        for word, unit in (('lengths in metres', 1.0), ('lengths in millimetres', 1000.0)):
            if word in low:
                if rob['unit'] not in (None, unit):
                    raise GenError('%s: the header gives two length units' % where)
                rob['unit'] = unit
        tok = text.split()
        if not tok:
            continue
        kw = tok[0]
        if kw == 'convention':
            if rob['conv'] is not None or rob['joints'] or len(tok) != 2 or \
               tok[1] not in ('standard', 'modified'):
                raise GenError('%s: expected one "convention standard|modified" before the joints'
                               % where)
            rob['conv'] = tok[1]
        elif kw == 'joint':
            if len(tok) < 2 or tok[1] not in ('R', 'P'):
                raise GenError('%s: a joint is revolute or prismatic (joint R|P ...)' % where)
            vals = {}
            for kv in tok[2:]:
                k, eq, v = kv.partition('=')
                if not eq or k not in KEYS:
                    raise GenError('%s: unsupported joint field %r (supported: %s)'
                                   % (where, kv, ' '.join(k + '=' for k in KEYS)))
                if k in vals:
                    raise GenError('%s: duplicate key %r' % (where, k))
                vals[k] = number(v, where)
            if 'min' not in vals or 'max' not in vals or vals['min'] > vals['max']:
                raise GenError('%s: every joint needs min= and max= with min <= max' % where)
            rob['joints'].append((tok[1], vals.get('a', 0.0), vals.get('d', 0.0), vals.get('alpha', 0.0),
                                  vals.get('theta', 0.0), vals['min'], vals['max']))
        elif kw in ('base', 'tool'):
            if rob[kw] is not None:
                raise GenError('%s: duplicate %s' % (where, kw))
            rob[kw] = frame(text.strip()[len(kw):], where)
        else:
            raise GenError('%s: unsupported statement %r' % (where, kw))
    if not rob['joints']:
        raise GenError('%s: no joints' % path)
    if rob['unit'] is None:
        raise GenError('%s: the header comment must say "lengths in metres" or '
                       '"lengths in millimetres"' % path)
    if (rob['unit'] == 1000.0) != stem.endswith('_mm'):
        raise GenError('%s: NAME_mm files are in millimetres, the others in metres' % path)
    rob['conv'] = rob['conv'] or 'standard'
    rob['base'] = rob['base'] or ident()
    rob['tool'] = rob['tool'] or ident()
    return rob


def scaled(rob, stem, k):
    """Millimetre twin of a metre robot: lengths times k in double."""
    def fr(T):
        return [col[:] if c < 3 else [v * k for v in col[:3]] + [col[3]] for c, col in enumerate(T)]
    return {'stem': stem, 'conv': rob['conv'], 'unit': rob['unit'] * k,
            'joints': [(t, a * k, d * k, al, th, lo * k if t == 'P' else lo, hi * k if t == 'P' else hi)
                       for t, a, d, al, th, lo, hi in rob['joints']],
            'base': fr(rob['base']), 'tool': fr(rob['tool'])}


def same(x, y):
    return x == y or abs(x - y) <= 1e-12 * max(abs(x), abs(y))


def check_twin(mm, m, path):
    want = scaled(m, mm['stem'], 1000.0)
    ok = mm['conv'] == want['conv'] and len(mm['joints']) == len(want['joints'])
    ok = ok and all(ja[0] == jb[0] and all(same(x, y) for x, y in zip(ja[1:], jb[1:]))
                    for ja, jb in zip(mm['joints'], want['joints']))
    ok = ok and all(same(mm[f][c][r], want[f][c][r])
                    for f in ('base', 'tool') for c in range(4) for r in range(4))
    if not ok:
        raise GenError('%s: does not match %s.dh with lengths times 1000' % (path, m['stem']))


def lit(x):
    if x == 0.0:
        return '0.0'
    s = repr(x)
    return s if ('.' in s or 'e' in s) else s + '.0'


def mat(T):
    return '{ { ' + ', '.join('{ ' + ', '.join(lit(v) for v in col) + ' }' for col in T) + ' } }'


def emit(rob, src):
    N = 'DHR_' + rob['stem'].upper()
    out = ['/* %s */' % src,
           '#define %s_NAME "%s"' % (N, rob['stem']),
           '#define %s_CONV DH_CONV_%s' % (N, rob['conv'].upper()),
           '#define %s_N %du' % (N, len(rob['joints'])),
           '#define %s_UNIT_PER_M %s' % (N, lit(rob['unit'])),
           '#define %s_JOINTS(X) \\' % N]
    for t, a, d, al, th, lo, hi in rob['joints']:
        out.append('    X(%s, %s, %s, %s, %s, %s, %s) \\'
                   % ((('DH_JOINT_REVOLUTE' if t == 'R' else 'DH_JOINT_PRISMATIC'),)
                      + tuple(lit(v) for v in (a, d, al, th, lo, hi))))
    out[-1] = out[-1][:-2]
    out.append('#define %s_BASE %s' % (N, mat(rob['base'])))
    out.append('#define %s_TOOL %s' % (N, mat(rob['tool'])))
    return out


def main(argv):
    if len(argv) < 4 or argv[1] != '-o':
        sys.stderr.write('usage: gen_robots.py -o OUT.h FILE.dh...\n')
        return 2
    out_path, files = argv[2], sorted(argv[3:], key=os.path.basename)
    try:
        robots = {}
        for p in files:
            r = parse(p)
            if r['stem'] in robots:
                raise GenError('%s: robot %s given twice' % (p, r['stem']))
            robots[r['stem']] = (r, p)
        blocks = []
        for stem, (r, p) in sorted(robots.items()):
            blocks.append(emit(r, 'from ' + os.path.basename(p)))
            if stem.endswith('_mm'):
                base = robots.get(stem[:-3])
                if base:
                    check_twin(r, base[0], p)
            elif stem + '_mm' not in robots:
                blocks.append(emit(scaled(r, stem + '_mm', 1000.0),
                                   'from %s, lengths times 1000.0' % os.path.basename(p)))
    except (GenError, OSError, UnicodeDecodeError) as e:
        sys.stderr.write('gen_robots.py: error: %s\n' % e)
        return 1
    text = ['/* SPDX-License-Identifier: Apache-2.0 */',
            '/* Generated by tools/gen_robots.py from examples/robots/NAME.dh: do not edit.',
            ' * Layout of the macros: see the head of tools/gen_robots.py. */',
            '#ifndef DH_ROBOTS_H', '#define DH_ROBOTS_H', '',
            '#include "dhmath/robot.h"', '']
    for b in blocks:
        text += b + ['']
    text.append('#endif /* DH_ROBOTS_H */')
    data = '\n'.join(text) + '\n'
    tmp = out_path + '.tmp'
    with open(tmp, 'w', encoding='ascii') as fh:
        fh.write(data)
    os.replace(tmp, out_path)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
