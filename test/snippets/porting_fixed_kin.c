/* SPDX-License-Identifier: Apache-2.0 */
/* What surrounds the fragment of docs/porting.md, "Fixed-point kinematics
 * with no float linked": the body of main(), with dhg_puma560_mm generated
 * by dhmath gen from examples/robots/puma560_mm.dh in its own source
 * (test/doc_snippets.py compiles and links it). After the fragment, the
 * results it leaves are checked. */
/* @GEN@ examples/robots/puma560_mm.dh dhg_puma560_mm */
#include <stdio.h>
#include "dhmath/dhmath.h"

int main(void)
{
/* @SNIPPET@ */
    if (n_sol == 0u || best >= n_sol) {
        fprintf(stderr, "closed form: %u solutions, nearest %u\n", (unsigned)n_sol, (unsigned)best);
        return 1;
    }
    for (i = 0; i < 6u; i++) {
        const int32_t d = sol[best].q[i] - goal[i];
        if (d > DH_Q16(0.01) || d < -DH_Q16(0.01)) {
            fprintf(stderr, "nearest solution: joint %u off the goal by %ld LSB\n", (unsigned)i, (long)d);
            return 1;
        }
    }
    if (res.err_pos > p.tol_pos || res.err_rot > p.tol_rot) {
        fprintf(stderr, "dh_ik_q: errors %ld, %ld above the tolerances\n", (long)res.err_pos, (long)res.err_rot);
        return 1;
    }
    printf("%u closed-form solutions; dh_ik_q in %u steps\n", (unsigned)n_sol, (unsigned)res.iterations);
    return 0;
}
