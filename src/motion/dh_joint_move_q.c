/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_joint_move_q.c - fixed-point synchronised point-to-point joint move,
 * the twin of dh_joint_move.c: every joint's time-optimal profile for its
 * own limits (dh_profile_scurve_q, or dh_profile_trap_q without jerk
 * limits), the move as long as the slowest (T = the longest duration, in
 * whole microseconds), every profile stretched to T by uniform time
 * scaling (dh_profile_stretch_q: its peaks only fall). Integer only.
 *
 * On error every profile is set to no move (all zero, duration 0), so a
 * caller that evaluates it anyway keeps every joint at q0.
 */
#include <string.h>

#include "dhmath/motion.h"
#include "../internal/dh_build.h"
#include "motion_impl.h"

/* The inputs into the profiles (d, v = vmax, a = amax, j = jmax or 0),
 * checked in the float twin's order: DH_ERR_OVERFLOW for a d beyond int32,
 * DH_ERR_ARG for a limit <= 0 (the first failing joint's). */
static DH_NOINLINE dh_status jmoveq_fill(dh_profile_q *prof, uint32_t n, const int32_t *q0, const int32_t *q1,
                                         const int32_t *vmax, const int32_t *amax, const int32_t *jmax)
{
    dh_status st = DH_OK;
    uint32_t i;
    int64_t d;
    for (i = 0u; i < n && st == DH_OK; i++) {
        d = (int64_t)q1[i] - q0[i];
        if (d > INT32_MAX || d < INT32_MIN) st = DH_ERR_OVERFLOW;
        else if (vmax[i] <= 0 || amax[i] <= 0 || (jmax != NULL && jmax[i] <= 0)) st = DH_ERR_ARG;
        prof[i].d = (int32_t)d;
        prof[i].v = vmax[i];
        prof[i].a = amax[i];
        prof[i].j = (jmax != NULL) ? jmax[i] : 0;
    }
    return st;
}

dh_status dh_joint_move_q(dh_profile_q *prof, uint32_t n, const int32_t *q0, const int32_t *q1,
                          const int32_t *vmax, const int32_t *amax, const int32_t *jmax)
{
    dh_status st;
    uint32_t T = 0u, i;
    DH_ASSERT(prof != NULL && q0 != NULL && q1 != NULL && vmax != NULL && amax != NULL);
    if (n == 0u) return DH_ERR_ARG;
    st = jmoveq_fill(prof, n, q0, q1, vmax, amax, jmax);
    /* every joint's profile planned in place, the longest duration T */
    for (i = 0u; i < n && st == DH_OK; i++) {
        st = dh_motion_profile_q_(&prof[i]);
        if (st == DH_OK && prof[i].T > T) T = prof[i].T;
    }
    for (i = 0u; i < n && st == DH_OK; i++) st = dh_profile_stretch_q(&prof[i], T);
    /* on error every joint stays where it is: no move, duration 0 */
    if (st != DH_OK) memset(prof, 0, n * sizeof prof[0]);
    return st;
}

dh_status dh_joint_move_eval_q(const dh_profile_q *prof, uint32_t n, const int32_t *q0, const int32_t *q1,
                               uint32_t t, int32_t *q, int32_t *qd, int32_t *qdd)
{
    int32_t p;
    uint32_t i;
    dh_status st = DH_OK;
    DH_ASSERT(prof != NULL && q0 != NULL && q1 != NULL && q != NULL && qd != NULL && qdd != NULL);
    if (n == 0u) return DH_ERR_ARG;
    /* every profile checked before any output is written */
    for (i = 0u; i < n && st == DH_OK; i++) st = dh_profile_eval_q(&prof[i], 0u, &p, &p, &p);
    for (i = 0u; i < n && st == DH_OK; i++) {
        (void)dh_profile_eval_q(&prof[i], t, &p, &qd[i], &qdd[i]);
        /* from the nearer end (both within int32: p lies between 0 and d);
         * a joint with d == 0 stays at q0 */
        q[i] = ((t >= prof[i].T || t > prof[i].T - t) && prof[i].d != 0) ? (int32_t)((int64_t)q1[i] - ((int64_t)prof[i].d - p))
                                                       : (int32_t)((int64_t)q0[i] + p);
    }
    return st;
}
