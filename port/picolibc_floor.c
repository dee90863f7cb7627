/* SPDX-License-Identifier: Apache-2.0 */
/*
 * picolibc_floor.c - a correct floor() for the RV32 test firmware.
 *
 * Debian 12's picolibc (1.8) has a wrong double floor() on 32-bit targets:
 * when adding the rounding increment to the low word of a negative value
 * carries into the high word, it misses the carry (a signed comparison
 * where an unsigned one is needed), e.g. floor(-536870911.5) returns
 * -536870656. picolibc fixed it after that release ("libm: Fix carry
 * condition in floor/ceil", 2023; see docs/references.md). The test
 * suites round their double references with floor(), and picolibc's own
 * sin/cos argument reduction (k_rem_pio2) calls it, so port/dh_target.cmake
 * links this definition into every RV32 test and example executable; the
 * linker then takes no floor() from libc.a. Not part of the library
 * (which uses no libm).
 */
#include <math.h>

double floor(double x)
{
    /* 2^52: from there on every double is an integer; NaN and +-Inf fail
     * both comparisons and are returned as they are */
    const double big = 4503599627370496.0;
    double t;
    if (!(x > -big && x < big) || x == 0.0) {
        return x;   /* also keeps the sign of -0.0 */
    }
    t = (double)(long long)x;   /* truncation toward zero, exact here */
    return t > x ? t - 1.0 : t;
}
