/*
 * fw_fixed_fk.c - firmware example for a core without FPU (Cortex-M0+):
 * forward kinematics of a UR5 in fixed point, integer arithmetic only.
 *
 * The robot is built at run time from its DH table (examples/robots/
 * ur5_mm.dh: Universal Robots' published parameters, lengths in mm) with
 * the fixed-point setter; the table is written in micrometres and angles
 * in whole degrees, converted to the library's Q formats by integer
 * constant expressions, so no float is involved anywhere at run time.
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

/* micrometres -> dh_qpos millimetres, rounded (integer constant expression) */
#define UM(um) ((dh_qpos)(((int64_t)(um) * DH_QPOS_ONE + ((um) >= 0 ? 500 : -500)) / 1000))
/* whole degrees -> dh_q16 */
#define DEG(d) ((dh_q16)((d) * DH_Q16_ONE))

typedef struct {
    dh_qpos d, a;
    dh_q16 alpha;
} ur5_row;

/* UR5, standard DH: d, a, alpha (theta is the joint variable, offset 0) */
static const ur5_row ur5[6] = {
    { UM(89159), UM(0), DEG(90) },      { UM(0), UM(-425000), DEG(0) },
    { UM(0), UM(-392250), DEG(0) },     { UM(109150), UM(0), DEG(90) },
    { UM(94650), UM(0), DEG(-90) },     { UM(82300), UM(0), DEG(0) },
};

static const int16_t configs[3][6] = {
    { 0, 0, 0, 0, 0, 0 },
    { 30, -60, 45, 10, 90, -20 },
    { -135, -100, 120, -45, -30, 170 },
};

int main(void)
{
    dh_robot arm;
    dh_frame_q T;
    int32_t q[6];
    unsigned i, j;

    if (dh_robot_init(&arm, DH_CONV_STANDARD) != DH_OK) return 1;
    for (i = 0; i < 6u; i++) {
        if (dh_robot_add_joint_q(&arm, DH_JOINT_REVOLUTE, 0, ur5[i].d, ur5[i].a,
                                 ur5[i].alpha) != DH_OK)
            return 1;
    }
    for (i = 0; i < 3u; i++) {
        dh_status st;
        for (j = 0; j < 6u; j++) q[j] = DEG(configs[i][j]);
        st = dh_fk_q(&arm, q, &T);
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
