#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Print the two const tables of src/trig/dh_itrig_q.c (fixed-point atan2,
block scope in itrigq_atan2_u).

    /usr/bin/python3 tools/gen_itrig_tables.py           # the C initialisers
    /usr/bin/python3 tools/gen_itrig_tables.py --check   # compare with the file

* itrigq_recip_tab[129]: s_j = round(2^23 / (j + 128.5)) for j = 0..127, the
  constant of least relative error for 2^46 / x over the bucket
  x >> 23 == j + 128 (x in [2^30, 2^31)); 2^15 for j = 128 (x = 2^31). The
  script prints the worst |1 - x s / 2^46| over the bucket ends (the bound
  the file's error analysis uses).
* itrigq_atan_tab[65]: the Taylor coefficients of atan at r_k = k / 64 for
  the variable delta = 2^7 (r - r_k), in units of 2^-25 degree:
  a = atan(r_k), b = 2^-7 / (1 + r_k^2), c2 = half of
  -2^-14 r_k / (1 + r_k^2)^2, d = 2^-21 (3 r_k^2 - 1) / (3 (1 + r_k^2)^3),
  radians times 180 / pi, rounded to nearest.

The values are computed in double precision (relative error ~1e-16, below
1e-6 of a unit for every entry); the script refuses to emit a table if a
scaled value lies within 1e-4 of a rounding tie, where that error could
decide the rounding.
"""
import math
import sys

PATH = "src/trig/dh_itrig_q.c"
UNIT = 2.0 ** 25 * 180.0 / math.pi      # units of 2^-25 degree per radian


def rnd(v):
    """Round to nearest; refuse a value next to a tie."""
    if abs(abs(v - math.floor(v)) - 0.5) < 1e-4:
        sys.exit("gen_itrig_tables.py: %.9f is too close to a tie" % v)
    return int(math.floor(v + 0.5))


def recip_tab():
    return [rnd(2.0 ** 23 / (j + 128.5)) for j in range(128)] + [32768]


def atan_tab():
    rows = []
    for k in range(65):
        r = k / 64.0
        w = 1.0 + r * r
        rows.append((rnd(math.atan(r) * UNIT), rnd(UNIT * 2.0 ** -7 / w),
                     rnd(UNIT * 2.0 ** -14 * (-r / (w * w)) / 2.0),
                     rnd(UNIT * 2.0 ** -21 * (3.0 * r * r - 1.0) / (3.0 * w ** 3))))
    return rows


def lines(items, per):
    return ["        " + " ".join(items[i:i + per]) for i in range(0, len(items), per)]


def render():
    s = recip_tab()
    out = ["    static const uint16_t itrigq_recip_tab[129] = {"]
    out += lines(["%du," % v for v in s], 10)
    out += ["    };", "", "    static const itrigq_seg itrigq_atan_tab[65] = {"]
    out += lines(["{ %du, %du, %d, %d }," % row for row in atan_tab()], 2)
    out.append("    };")
    return out


def worst_seed():
    s = recip_tab()
    worst = 0.0
    for j in range(128):
        for x in ((j + 128) * 2 ** 23, (j + 129) * 2 ** 23 - 1):
            worst = max(worst, abs(1.0 - x * s[j] / 2.0 ** 46))
    return worst


def main():
    out = render()
    if len(sys.argv) > 1 and sys.argv[1] == "--check":
        text = open(PATH).read().split("\n")
        missing = [ln for ln in out if ln not in text]
        print("worst seed error |1 - x s / 2^46| = %.7f" % worst_seed())
        if missing:
            print("%s differs from the generated tables, e.g.: %s" % (PATH, missing[0]))
            return 1
        print("%s holds the generated tables" % PATH)
        return 0
    print("\n".join(out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
