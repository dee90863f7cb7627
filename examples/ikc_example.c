/* SPDX-License-Identifier: Apache-2.0 */
#include <stdio.h>
#include "dhmath/dhmath.h"

/* Every closed-form IK solution of one UR5 pose, and the one nearest the
 * current configuration (DH table: examples/robots/ur5.dh). */
int main(void)
{
    static const float a[6] = { 0.0f, -0.425f, -0.39225f, 0.0f, 0.0f, 0.0f };
    static const float d[6] = { 0.089159f, 0.0f, 0.0f, 0.10915f, 0.09465f, 0.0823f };
    static const float alpha[6] = { 90.0f, 0.0f, 0.0f, 90.0f, -90.0f, 0.0f };
    const float q[6] = { 10.0f, -30.0f, 45.0f, 20.0f, 35.0f, -60.0f };  /* degrees */
    dh_robot ur5;
    dh_ikc_model_f32 model;            /* analysed once, caller-owned */
    dh_ikc_sol_f32 sol[DH_IKC_MAX_SOL];
    dh_mat4_f32 T;
    uint32_t i, n_sol, best;

    dh_robot_init(&ur5, DH_CONV_STANDARD);
    for (i = 0; i < 6; i++)
        dh_robot_add_joint_f32(&ur5, DH_JOINT_REVOLUTE, 0.0f, d[i], a[i], alpha[i]);
    if (dh_ikc_analyse_f32(&ur5, &model) != DH_OK) return 1;   /* DH_IKC_PARALLEL_234 */

    dh_fk_f32(&ur5, q, &T);                                      /* a target pose */
    if (dh_ikc_f32(&model, &T, q, 0u, sol, &n_sol) != DH_OK) return 1;
    for (i = 0; i < n_sol; i++)
        printf("%.3f %.3f %.3f %.3f %.3f %.3f flags %02x\n", (double)sol[i].q[0], (double)sol[i].q[1],
               (double)sol[i].q[2], (double)sol[i].q[3], (double)sol[i].q[4], (double)sol[i].q[5],
               (unsigned)sol[i].flags);
    dh_ikc_nearest_f32(sol, n_sol, q, 6u, &best);
    printf("%u solutions, nearest the current configuration: number %u\n", (unsigned)n_sol, (unsigned)best);
    return 0;
}
