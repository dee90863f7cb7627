/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fuzz_parsers.c - robustness harness of the CLI parsers (cli/dh_expr.c,
 * cli/dh_robotfile.c).
 *
 * Two ways to run it:
 *  - libFuzzer: build with -DDH_FUZZ_LIBFUZZER -fsanitize=fuzzer,address and
 *    LLVMFuzzerTestOneInput is the entry point;
 *  - ctest (cli_fuzz_parsers): main() runs a seeded, deterministic mutation
 *    loop over a corpus of valid inputs plus random bytes.
 * Every input is copied into a heap block of exactly its length (no NUL
 * after it), so under DH_SANITIZE=ON AddressSanitizer reports any read past
 * the buffer. For each input the invariants below are checked; a violation
 * prints the input (hex) and exits 1.
 *
 * Invariants: return value 0 or -1; on error the position lies within the
 * buffer (<= len), the message is NUL-terminated printable ASCII and the
 * output is untouched; on success the float result is finite and the
 * robot file has 1..DH_MAX_JOINTS joints with min <= max.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dh_expr.h"
#include "dh_robotfile.h"

static void dump_and_die(const char *what, const uint8_t *d, size_t n)
{
    size_t k;
    fprintf(stderr, "fuzz_parsers: invariant violated: %s\ninput (%lu bytes):", what, (unsigned long)n);
    for (k = 0; k < n; k++) fprintf(stderr, "%s%02x", (k % 32u) ? " " : "\n  ", d[k]);
    fprintf(stderr, "\n");
    exit(1);
}

static int msg_ok(const char *m, size_t cap)
{
    size_t k;
    for (k = 0; k < cap; k++) {
        if (m[k] == '\0') return k > 0;
        if ((unsigned char)m[k] < 0x20 || (unsigned char)m[k] > 0x7e) return 0;
    }
    return 0;
}

static void one_input(const uint8_t *data, size_t n)
{
    char *buf = (char *)malloc(n ? n : 1u);
    dh_mat4_f32 T, T0;
    dh_frame_q F, F0;
    dh_expr_error e;
    static dh_robotfile rf;
    dh_rf_error re;
    unsigned r, c, k;
    int rc;

    if (!buf) exit(2);
    if (n) memcpy(buf, data, n);
    memset(&T0, 0x5a, sizeof T0);
    memset(&F0, 0x5a, sizeof F0);

    T = T0;
    rc = dh_expr_eval_f32(buf, n, &T, &e);
    if (rc != 0 && rc != -1) dump_and_die("eval_f32 return value", data, n);
    if (rc) {
        if (e.pos > n) dump_and_die("eval_f32 error position beyond the buffer", data, n);
        if (!msg_ok(e.msg, sizeof e.msg)) dump_and_die("eval_f32 message", data, n);
        if (memcmp(&T, &T0, sizeof T) != 0) dump_and_die("eval_f32 output written on error", data, n);
    } else {
        for (c = 0; c < 4u; c++)
            for (r = 0; r < 4u; r++)
                if (!isfinite(T.m[c][r])) dump_and_die("eval_f32 non-finite result", data, n);
    }

    F = F0;
    rc = dh_expr_eval_q(buf, n, &F, &e);
    if (rc != 0 && rc != -1) dump_and_die("eval_q return value", data, n);
    if (rc) {
        if (e.pos > n) dump_and_die("eval_q error position beyond the buffer", data, n);
        if (!msg_ok(e.msg, sizeof e.msg)) dump_and_die("eval_q message", data, n);
        if (memcmp(&F, &F0, sizeof F) != 0) dump_and_die("eval_q output written on error", data, n);
    }

    rc = dh_robotfile_parse("fuzz.dh", buf, n, &rf, &re);
    if (rc != 0 && rc != -1) dump_and_die("robotfile return value", data, n);
    if (rc) {
        if (!msg_ok(re.msg, sizeof re.msg)) dump_and_die("robotfile message", data, n);
        if (re.line < 1u) dump_and_die("robotfile line number", data, n);
    } else {
        if (rf.n < 1u || rf.n > (unsigned)DH_MAX_JOINTS) dump_and_die("robotfile joint count", data, n);
        for (k = 0; k < rf.n; k++)
            if (rf.joint[k].has_limits && !(rf.joint[k].qmin <= rf.joint[k].qmax))
                dump_and_die("robotfile min > max accepted", data, n);
    }
    free(buf);
}

#ifdef DH_FUZZ_LIBFUZZER
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    one_input(data, size);
    return 0;
}
#else

static const char *const k_corpus[] = {
    "trans(4,-3,7) roty(90) rotz(90)",
    "inv(trans(4,0,0) roty(90) rotz(90)) * rot(1,1,1,120)",
    "scale(1,2,3) persp(y,10) ident inv(inv(rotx(-30.5e0)))",
    "rotx(1e38) trans(-1e-30,0,.5)",
    "convention modified\njoint R a=0 d=0.333 alpha=0 min=-166 max=166\n"
    "joint P a=1 theta=90 min=-1 max=1 # c\nbase trans(0,0,1)\ntool rotz(-45)\n",
    "joint R a=0.4318 d=0 alpha=0\r\njoint R d=0.15005 a=0.0203 alpha=-90\r\n",
    "inv(inv(inv(inv(inv(inv(inv(inv(inv(inv(inv(inv(inv(inv(inv(inv(rotx(1))))))))))))))))",
};

static uint64_t g_state = 0x9E3779B97F4A7C15ull;
static uint32_t rnd(void)
{
    g_state ^= g_state >> 12;
    g_state ^= g_state << 25;
    g_state ^= g_state >> 27;
    return (uint32_t)((g_state * 2685821657736338717ull) >> 32);
}

int main(int argc, char **argv)
{
    static const char alphabet[] = "()*, .-+e0123456789rotxyzinvtranscalepersidentjoint=RP#\n\r\tadmhb";
    unsigned long iters = 200000ul, it;
    uint8_t buf[600];
    if (argc > 1) iters = strtoul(argv[1], NULL, 10);
    for (it = 0; it < sizeof k_corpus / sizeof k_corpus[0]; it++)
        one_input((const uint8_t *)k_corpus[it], strlen(k_corpus[it]));
    for (it = 0; it < iters; it++) {
        size_t n, k, muts;
        if (rnd() % 8u == 0u) {
            /* random bytes, biased to the grammar's alphabet */
            n = rnd() % 80u;
            for (k = 0; k < n; k++)
                buf[k] = (rnd() % 4u) ? (uint8_t)alphabet[rnd() % (sizeof alphabet - 1u)] : (uint8_t)rnd();
        } else {
            const char *s = k_corpus[rnd() % (sizeof k_corpus / sizeof k_corpus[0])];
            n = strlen(s);
            memcpy(buf, s, n);
            muts = 1u + rnd() % 6u;
            for (k = 0; k < muts; k++) {
                size_t at = n ? rnd() % n : 0u;
                switch (rnd() % 5u) {
                case 0: if (n) buf[at] = (uint8_t)alphabet[rnd() % (sizeof alphabet - 1u)]; break;
                case 1: if (n) buf[at] = (uint8_t)rnd(); break;
                case 2: if (n) { memmove(buf + at, buf + at + 1, n - at - 1); n--; } break;
                case 3: if (n + 1 < sizeof buf) { memmove(buf + at + 1, buf + at, n - at); buf[at] = (uint8_t)alphabet[rnd() % (sizeof alphabet - 1u)]; n++; } break;
                default: n = at; break; /* truncate */
                }
            }
        }
        one_input(buf, n);
    }
    printf("fuzz_parsers: %lu inputs, all invariants held\n", iters + (unsigned long)(sizeof k_corpus / sizeof k_corpus[0]));
    return 0;
}
#endif
