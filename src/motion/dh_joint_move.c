/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_joint_move.c - synchronised point-to-point joint move.
 *
 * Method: every joint gets its time-optimal rest-to-rest profile for its
 * own limits (seven-phase, or trapezoidal without jerk limits); the move
 * lasts T = the longest of their durations, the shortest duration in which
 * the slowest joint can arrive. Every other joint's profile is stretched
 * to T by uniform time scaling, p_i(t) -> p_i(t / k_i), k_i = T / T_i >= 1
 * (dh_profile_stretch_f32): its velocity, acceleration and jerk shrink by
 * k_i, k_i^2 and k_i^3, so it stays within the limits its own optimal
 * profile met, and all joints start and stop together (the path in joint
 * space is not a straight line unless the joints' profiles have the same
 * shape, as for joints with proportional limits).
 *
 * On error every profile is set to no move (all zero, duration 0), so a
 * caller that evaluates it anyway keeps every joint at q0.
 */
#include <string.h>

#include "dhmath/motion.h"
#include "../internal/dh_floatops.h"

/* joint i's time-optimal profile into *p */
static dh_status joint_move_one(dh_profile_f32 *p, float q0, float q1, float vmax, float amax, const float *jmax)
{
    float d;
    if (!dh_isfinite_f32(q0) || !dh_isfinite_f32(q1)) return DH_ERR_NAN;
    d = q1 - q0;
    if (!dh_isfinite_f32(d)) return DH_ERR_OVERFLOW;
    if (jmax == NULL) return dh_profile_trap_f32(p, d, vmax, amax);
    return dh_profile_scurve_f32(p, d, vmax, amax, *jmax);
}

dh_status dh_joint_move_f32(dh_profile_f32 *prof, uint32_t n, const float *q0, const float *q1,
                            const float *vmax, const float *amax, const float *jmax)
{
    dh_status st = DH_OK;
    float T = 0.0f;
    uint32_t i;
    DH_ASSERT(prof != NULL && q0 != NULL && q1 != NULL && vmax != NULL && amax != NULL);
    if (n == 0u) return DH_ERR_ARG;
    for (i = 0u; i < n && st == DH_OK; i++) {
        st = joint_move_one(&prof[i], q0[i], q1[i], vmax[i], amax[i], (jmax != NULL) ? &jmax[i] : NULL);
        if (st == DH_OK && prof[i].T > T) T = prof[i].T;
    }
    for (i = 0u; i < n && st == DH_OK; i++) st = dh_profile_stretch_f32(&prof[i], T);
    /* on error every joint stays where it is: no move, duration 0 */
    if (st != DH_OK) memset(prof, 0, n * sizeof prof[0]);
    return st;
}

dh_status dh_joint_move_eval_f32(const dh_profile_f32 *prof, uint32_t n, const float *q0, const float *q1,
                                 float t, float *q, float *qd, float *qdd)
{
    float p;
    uint32_t i;
    DH_ASSERT(prof != NULL && q0 != NULL && q1 != NULL && q != NULL && qd != NULL && qdd != NULL);
    if (n == 0u) return DH_ERR_ARG;
    if (isunordered(t, t)) return DH_ERR_NAN;
    for (i = 0u; i < n; i++) {
        (void)dh_profile_eval_f32(&prof[i], t, &p, &qd[i], &qdd[i]);
        /* from the nearer end; a joint with d == 0 (q1 == q0 in a move of
         * dh_joint_move_f32, or a failed call's no move) stays at q0 */
        q[i] = (t > 0.5f * prof[i].T && !dh_feq_f32(prof[i].d, 0.0f)) ? q1[i] - (prof[i].d - p) : q0[i] + p;
    }
    return DH_OK;
}
