/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fw_fixed_fk.c - firmware example for a core without FPU (Cortex-M0+):
 * forward kinematics of a UR5 in fixed point, integer arithmetic only.
 *
 * The robot lives in flash: `dhmath gen examples/robots/ur5_mm.dh
 * dhg_ur5_mm` (run by the build, test/gen/) writes the C source that defines
 * `const dh_robot dhg_ur5_mm` with every derived field computed, so the
 * firmware calls no setter and the description takes no RAM. The
 * joint angles are whole degrees turned into Q16.16 by an integer constant
 * expression: no float is involved anywhere at run time. (A robot written
 * by hand or received from outside is checked once at start-up with
 * dh_robot_check, which uses float; a generated one passes by construction.)
 *
 * Output, one line per configuration (raw fixed-point integers, which a
 * firmware would send on as they are):
 *   q_deg: <6 joint angles, whole degrees>
 *   p_qpos: <x y z, DH_QPOS_FRAC fraction bits, mm>
 *   r_q30: <r00 r01 r02 r10 r11 r12 r20 r21 r22, row by row, Q2.30>
 * examples/firmware/check_output.py recomputes every value in double
 * precision from the same DH table and compares within the error bound of
 * dh_fk_q's contract.
 *
 * Runs under QEMU (tools/check.sh examples); on a board, replace printf by
 * the board's output.
 */
#include <stdio.h>

#include "dhmath/dhmath.h"

/* whole degrees -> dh_q16 */
#define DEG(d) ((dh_q16)((d) * DH_Q16_ONE))

/* UR5 in mm (examples/robots/ur5_mm.dh), generated into .rodata */
extern const dh_robot dhg_ur5_mm;

static const int16_t configs[3][6] = {
    { 0, 0, 0, 0, 0, 0 },
    { 30, -60, 45, 10, 90, -20 },
    { -135, -100, 120, -45, -30, 170 },
};

int main(void)
{
    dh_frame_q T;
    int32_t q[6];
    unsigned i, j;

    for (i = 0; i < 3u; i++) {
        dh_status st;
        for (j = 0; j < 6u; j++) q[j] = DEG(configs[i][j]);
        st = dh_fk_q(&dhg_ur5_mm, q, &T);
        if (st != DH_OK) {
            printf("dh_fk_q: %s\n", dh_status_str(st));
            return 1;
        }
        printf("q_deg:");
        for (j = 0; j < 6u; j++) printf(" %d", configs[i][j]);
        printf("\np_qpos: %ld %ld %ld\nr_q30:", (long)T.p[0], (long)T.p[1], (long)T.p[2]);
        for (j = 0; j < 9u; j++) printf(" %ld", (long)T.r[j % 3u][j / 3u]);
        printf("\n");
    }
    return 0;
}
