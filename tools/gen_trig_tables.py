#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Generate src/trig/dh_trig_tables.c: correctly rounded whole-degree sine tables.

    /usr/bin/python3 tools/gen_trig_tables.py > src/trig/dh_trig_tables.c
    /usr/bin/python3 tools/gen_trig_tables.py --check   # only the report

Two quarter-wave tables, sin(n degrees) for n = 0..90 (cos(n) = sin(90 - n)):

* dh_trig_sin_f32[91]: IEEE binary32, round-to-nearest-even of the exact value,
  written as C99 hexadecimal float literals so the compiler cannot round them
  a second time (a decimal literal may legally be rounded either way by a
  C99 compiler; a hex literal of a representable value is exact).
* dh_trig_sin_q30[91]: Q2.30 (1.0 = 0x40000000), round-half-even of
  sin(n deg) * 2^30.

Why the rounding is correct: sin is evaluated with Python's `decimal` module
at PREC significant digits (pi from Machin's formula, then the Taylor series,
all in decimal arithmetic), so each value has an absolute error below
1e-(PREC-5). The rounding of value * 2^k to an integer is therefore decided
correctly unless the scaled value lies within that error of a rounding tie
(x.5). The script measures, for every entry, the distance of the scaled
value from the nearest tie and refuses to emit the table if any distance is
below 1e-20 (the smallest distance found is printed in the report; it is
many orders of magnitude larger). Exact cases (0, 30, 90 degrees) are not
ties: 0, 0.5 and 1 are representable in both formats.

The script also checks that the double-precision value math.sin(n*pi/180)
rounded to float / to Q2.30 gives the same entries (this is what the tests
use as their reference); the report states whether any entry differs.
"""
import decimal
import math
import struct
import sys
from fractions import Fraction

PREC = 60
D = decimal.Decimal


def dec_pi():
    """pi = 16 atan(1/5) - 4 atan(1/239) (Machin), in decimal arithmetic."""
    def atan_inv(x):
        x = D(x)
        x2 = x * x
        term = D(1) / x
        total = term
        k = 1
        while True:
            term = -term / x2
            add = term / (2 * k + 1)
            if add == 0 or abs(add) < D(10) ** (-(PREC + 5)):
                break
            total += add
            k += 1
        return total
    return 16 * atan_inv(5) - 4 * atan_inv(239)


def dec_sin(x):
    """Taylor series; x in [0, pi/2]."""
    term = x
    total = x
    k = 1
    x2 = x * x
    while True:
        term = -term * x2 / ((2 * k) * (2 * k + 1))
        if abs(term) < D(10) ** (-(PREC + 5)):
            break
        total += term
        k += 1
    return total


def round_half_even(fr):
    """Round a non-negative Fraction to an integer; also return the distance
    of fr from the nearest tie (k + 1/2)."""
    fl = fr.numerator // fr.denominator
    rem = fr - fl
    tie_dist = abs(rem - Fraction(1, 2))
    if rem > Fraction(1, 2) or (rem == Fraction(1, 2) and fl % 2 == 1):
        fl += 1
    return fl, tie_dist


def to_f32(v):
    """Correctly rounded binary32 of Fraction v in [0, 1]; returns
    (python float holding the exact binary32 value, tie distance in ulps)."""
    if v == 0:
        return 0.0, Fraction(1, 2)
    e = 0
    while v < Fraction(2) ** e:
        e -= 1
    while v >= Fraction(2) ** (e + 1):
        e += 1
    # v in [2^e, 2^(e+1)): 24 significant bits -> ulp 2^(e-23)
    scaled = v * Fraction(2) ** (23 - e)
    mant, dist = round_half_even(scaled)
    val = Fraction(mant) * Fraction(2) ** (e - 23)
    f = float(val)
    assert Fraction(f) == val
    # must be exactly representable as binary32
    assert struct.unpack('<f', struct.pack('<f', f))[0] == f
    return f, dist


def f32_of_double(x):
    return struct.unpack('<f', struct.pack('<f', x))[0]


def c_hex_float(f):
    if f == 0.0:
        return "0x0p+0f"
    mant, exp = f.hex().split("p")
    mant = mant.rstrip("0").rstrip(".")
    return mant + "p" + exp + "f"


def main():
    check_only = "--check" in sys.argv[1:]
    decimal.getcontext().prec = PREC
    pi = dec_pi()
    # sanity: 50 digits of pi
    assert str(pi).startswith("3.14159265358979323846264338327950288419716939937510")
    f32 = []
    q30 = []
    min_tie_f32 = None
    min_tie_q30 = None
    double_mismatch = []
    for n in range(91):
        if n == 90:
            val = Fraction(1)          # exact: sin(90) = 1
        elif n == 30:
            val = Fraction(1, 2)       # exact: sin(30) = 1/2
        elif n == 0:
            val = Fraction(0)
        else:
            val = Fraction(dec_sin(pi * n / 180))
        f, d1 = to_f32(val)
        q, d2 = round_half_even(val * 2 ** 30)
        if n not in (0, 30, 90):
            min_tie_f32 = d1 if min_tie_f32 is None else min(min_tie_f32, d1)
            min_tie_q30 = d2 if min_tie_q30 is None else min(min_tie_q30, d2)
        f32.append(f)
        q30.append(q)
        # the test suite's reference: double sin rounded once more
        ds = math.sin(n * math.pi / 180.0) if n not in (0, 30, 90) else float(val)
        if f32_of_double(ds) != f or round(ds * 2 ** 30) != q:
            double_mismatch.append(n)
    if min_tie_f32 < Fraction(1, 10 ** 20) or min_tie_q30 < Fraction(1, 10 ** 20):
        sys.exit("gen_trig_tables: an entry lies too close to a rounding tie")
    report = [
        "decimal precision %d digits" % PREC,
        "min distance from a rounding tie: f32 %.3e ulp, q30 %.3e LSB"
        % (float(min_tie_f32), float(min_tie_q30)),
        "entries where double sin rounded again differs: %s"
        % (double_mismatch if double_mismatch else "none"),
    ]
    if check_only:
        print("\n".join(report))
        return
    out = ["/* SPDX-License-Identifier: Apache-2.0 */"]
    out.append("/*")
    out.append(" * dh_trig_tables.c - GENERATED by tools/gen_trig_tables.py; do not edit.")
    out.append(" * Regenerate: /usr/bin/python3 tools/gen_trig_tables.py > src/trig/dh_trig_tables.c")
    out.append(" *")
    out.append(" * sin(n degrees), n = 0..90, correctly rounded (exact decimal evaluation")
    out.append(" * at %d digits, round to nearest even). cos(n) = sin(90 - n)." % PREC)
    for line in report[1:]:
        out.append(" * " + line)
    out.append(" * Sizes: dh_trig_sin_f32 %d bytes, dh_trig_sin_q30 %d bytes."
               % (4 * len(f32), 4 * len(q30)))
    out.append(" */")
    out.append('#include "dh_trig_tables.h"')
    out.append("")
    out.append("const float dh_trig_sin_f32[DH_TRIG_TAB_LEN] = {")
    for n in range(0, 91, 4):
        row = ", ".join(c_hex_float(f32[i]) for i in range(n, min(n + 4, 91)))
        out.append("    %s, /* %d.. */" % (row, n))
    out.append("};")
    out.append("")
    out.append("const int32_t dh_trig_sin_q30[DH_TRIG_TAB_LEN] = {")
    for n in range(0, 91, 6):
        row = ", ".join("0x%08x" % q30[i] for i in range(n, min(n + 6, 91)))
        out.append("    %s, /* %d.. */" % (row, n))
    out.append("};")
    print("\n".join(out))


if __name__ == "__main__":
    main()
