/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_path.c - Cartesian paths (line, circular arc) between two frames and
 * their time-optimal trapezoidal moves.
 *
 * Orientation of every path: that of dh_pose_interp_f32 from A to B (the
 * slerp of the unit quaternions of R_A and R_B along the shortest arc,
 * angle proportional to s), from the quaternions the path keeps, so that
 * an evaluation converts no matrix and checks no rotation. Position of a
 * line: p_A + s (p_B - p_A) from the nearer end. Position of an arc: the circle
 * through p_A, the via point V and p_B. With a = V - p_A, b = p_B - p_A
 * (both divided by the longest side L of the triangle, so no square or
 * cube of a length overflows or underflows) and n = a x b, the centre is
 * p_A + c, c = (|a|^2 (b x n) + |b|^2 (n x a)) / (2 |n|^2) (the
 * circumcentre), u0 = p_A - centre = -c, u1 = p_B - centre = b - c. The
 * triangle p_A, V, p_B turns counterclockwise about n, so the arc from p_A
 * through V to p_B does too: the sweep is the angle from u0 to u1 about
 * n, atan2((u0 x u1) . n^, u0 . u1) taken in (0, 2 pi). |n| > 2^-10
 * (after the division by L^2) keeps the radius below 512 L: L = 2 R sin of
 * the largest angle of the triangle, and |n| = 2 area / L^2 <= 2 sin of
 * every angle.
 *
 * The arc is evaluated from its nearer end, relative to it:
 * p_A + (cos phi - 1) u0 + sin phi (n^ x u0), phi = s sweep, for s <= 1/2
 * and p_B + (cos psi - 1) u1 - sin psi (n^ x u1), psi = (1 - s) sweep,
 * after, so the offset is small where the end is near and the ends are
 * exact. phi <= sweep / 2 < pi: sin and cos of phi / 4 (at most pi/4, the
 * polynomials of dh_sincosf_pio4_ without argument reduction), then
 * sin(phi/2) = 2 s4 c4, cos(phi/2) = (c4 - s4)(c4 + s4), sin phi =
 * 2 sin(phi/2) cos(phi/2) and cos phi - 1 = -2 sin^2(phi/2) (no
 * cancellation near phi = 0).
 *
 * A move scales s by one trapezoid of d = 1 (dh_profile_trap_f32). The
 * tool point moves at length * s' along the path, with tangential
 * acceleration length * s'' and, on an arc of radius R, centripetal
 * acceleration (length s')^2 / R; the rotation turns at angle * s' about a
 * fixed axis (angular acceleration angle * s''). On an arc the speed is
 * held to V = min(vmax, sqrt(amax R / sqrt 2)), so the centripetal
 * acceleration is at most amax / sqrt 2, and the tangential one to
 * sqrt(amax^2 - (V^2/R)^2): the total stays within amax.
 *
 * A jerk-limited move scales s by one seven-phase profile
 * (dh_profile_scurve_f32) whose jerk bound is also held. On a line the
 * tool point's jerk is length * s''' and the tool's angular jerk
 * angle * s''' (the rotation turns about a fixed axis). On an arc, with
 * the arc length x = length * s, the tool point's jerk is
 * (x''' - x'^3 / R^2) t + (3 x' x'' / R) n (t the unit tangent, n the unit
 * normal towards the centre), so its magnitude is at most
 * |x'''| + x'^3 / R^2 + 3 x' |x''| / R. The speed is further held to
 * V <= cbrt(jmax R^2 / 4) (then x'^3 / R^2 <= jmax / 4), the tangential
 * acceleration At, taken from that V as above, to At <= jmax R / (12 V)
 * (then 3 x' |x''| / R <= jmax / 4) and the tangential jerk to jmax / 2:
 * the total jerk stays within jmax, and the total acceleration within
 * amax as before.
 */
#include <float.h>
#include <math.h>

#include "dhmath/motion.h"
#include "dhmath/mat4.h"
#include "../internal/dh_floatops.h"
#include "motion_impl.h"

#define PATH_2PI 6.283185307179586f
#define PATH_THIN 9.765625e-4f        /* 2^-10: the thinnest triangle of an arc */
#define PATH_RSQRT2 0.70710678118654752f
#define PATH_TWELFTH 0.0833333358f     /* 1/12: an arc's 3 V At / R held to jmax / 4 */

/* |v| without overflow or underflow of the squares: max |v_i| times the
 * norm of v / max |v_i| (0 for v == 0; +Inf when |v| overflows) */
static float path_norm(const float v[3])
{
    float m = 0.0f, x, y, z;
    int i;
    for (i = 0; i < 3; i++) {
        if (fabsf(v[i]) > m) m = fabsf(v[i]);
    }
    if (!(m > 0.0f)) return 0.0f;
    x = v[0] / m;
    y = v[1] / m;
    z = v[2] / m;
    return m * dh_sqrt_f32(x * x + y * y + z * z);
}

/* out = a x b */
static void path_cross(const float a[3], const float b[3], float out[3])
{
    float x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2], z = a[0] * b[1] - a[1] * b[0];
    out[0] = x;
    out[1] = y;
    out[2] = z;
}

/* *q = dh_mat3_to_quat_f32 of T's rotation (the matrix copy kept out of
 * the callers' frames) */
static DH_NOINLINE dh_status path_quat(const dh_mat4_f32 *T, dh_quat_f32 *q)
{
    dh_mat3_f32 R;
    dh_mat4_get_rot_f32(T, &R);
    return dh_mat3_to_quat_f32(&R, q);
}

/* the rotation check of dh_mat3_to_quat_f32 on T's rotation */
static DH_NOINLINE dh_status path_rot_check(const dh_mat4_f32 *T)
{
    dh_mat3_f32 R;
    dh_mat4_get_rot_f32(T, &R);
    return dh_mat3_check_rot_f32(&R, DH_ROT_TOL);
}

/* The checks shared by both paths: A and B rigid frames whose rotations
 * dh_mat3_to_quat_f32 accepts, p_B - p_A and (via != NULL) via - p_A
 * finite; via's entries finite. */
static dh_status path_check(const dh_mat4_f32 *A, const dh_mat4_f32 *B, const float *via)
{
    dh_status st = dh_mat4_check_rigid_f32(A, DH_ROT_TOL);
    int i;
    if (st == DH_OK) st = dh_mat4_check_rigid_f32(B, DH_ROT_TOL);
    if (st == DH_OK) st = path_rot_check(A);
    if (st == DH_OK) st = path_rot_check(B);
    if (st == DH_OK && via != NULL && !dh_allfinite_f32(via, 3u)) st = DH_ERR_NAN;
    for (i = 0; i < 3 && st == DH_OK; i++) {
        if (!dh_isfinite_f32(DH_M4(B, i, 3) - DH_M4(A, i, 3))) st = DH_ERR_OVERFLOW;
        if (via != NULL && !dh_isfinite_f32(via[i] - DH_M4(A, i, 3))) st = DH_ERR_OVERFLOW;
    }
    return st;
}

/* p's ends, their quaternions (on the shorter arc), the angle deg and the
 * kind k, after path_check accepted A and B (so the conversions, whose
 * rotation check it made, succeed) */
static void path_finish(dh_path_f32 *p, const dh_mat4_f32 *A, const dh_mat4_f32 *B, float deg, dh_path_kind k)
{
    (void)path_quat(A, &p->qa);
    (void)path_quat(B, &p->qb);
    dh_motion_shorter_f32_(&p->qa, &p->qb);
    p->A = *A;
    p->B = *B;
    p->angle = deg;
    p->kind = (uint32_t)k;
}

/* |p_B - p_A| (+Inf when it overflows) */
static DH_NOINLINE float path_length(const dh_mat4_f32 *A, const dh_mat4_f32 *B)
{
    float d[3];
    int i;
    for (i = 0; i < 3; i++) d[i] = DH_M4(B, i, 3) - DH_M4(A, i, 3);
    return path_norm(d);
}

dh_status dh_path_line_f32(dh_path_f32 *p, const dh_mat4_f32 *A, const dh_mat4_f32 *B)
{
    float len, deg;
    dh_status st;
    int i;
    DH_ASSERT(p != NULL && A != NULL && B != NULL);
    st = path_check(A, B, NULL);
    if (st != DH_OK) return st;
    len = path_length(A, B);
    if (!dh_isfinite_f32(len)) return DH_ERR_OVERFLOW;
    st = dh_pose_angle_f32(A, B, &deg);
    if (st != DH_OK) return st;
    for (i = 0; i < 3; i++) {
        p->u0[i] = 0.0f;
        p->u1[i] = 0.0f;
        p->n[i] = 0.0f;
    }
    p->length = len;
    p->radius = 0.0f;
    p->sweep = 0.0f;
    path_finish(p, A, B, deg, DH_PATH_LINE);
    return DH_OK;
}

/* The circle of the arc from p_A through via to p_B into p's u0, u1, n,
 * radius, sweep and length, written only on success. DH_ERR_OVERFLOW for
 * a side or a length that overflows, DH_ERR_SINGULAR for a thin triangle. */
static DH_NOINLINE dh_status path_circle(dh_path_f32 *p, const dh_mat4_f32 *A, const float via[3],
                                         const dh_mat4_f32 *B)
{
    float a[3], b[3], n[3], c[3], L, la, lb, ln, w, r;
    int i;
    for (i = 0; i < 3; i++) {
        a[i] = via[i] - DH_M4(A, i, 3);
        b[i] = DH_M4(B, i, 3) - DH_M4(A, i, 3);
        c[i] = b[i] - a[i];
        if (!dh_isfinite_f32(c[i])) return DH_ERR_OVERFLOW;
    }
    L = path_norm(a);
    la = path_norm(b);
    if (la > L) L = la;
    la = path_norm(c);
    if (la > L) L = la;
    if (!dh_isfinite_f32(L)) return DH_ERR_OVERFLOW;
    if (!(L > 0.0f)) return DH_ERR_SINGULAR;
    for (i = 0; i < 3; i++) {
        a[i] /= L;
        b[i] /= L;
    }
    path_cross(a, b, n);
    ln = dh_sqrt_f32(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(ln > PATH_THIN)) return DH_ERR_SINGULAR;
    la = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    lb = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
    path_cross(b, n, c);
    path_cross(n, a, a);
    w = 0.5f / (ln * ln);
    for (i = 0; i < 3; i++) {
        c[i] = (la * c[i] + lb * a[i]) * w;   /* centre - p_A, over L */
        n[i] /= ln;
        b[i] -= c[i];                         /* p_B - centre, over L */
    }
    /* the sweep from u0 = -c to u1 = b - c about n, in (0, 2 pi) */
    path_cross(c, b, a);
    w = dh_atan2f_(-(a[0] * n[0] + a[1] * n[1] + a[2] * n[2]), -(c[0] * b[0] + c[1] * b[1] + c[2] * b[2]));
    if (w < 0.0f) w += PATH_2PI;
    r = L * dh_sqrt_f32(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    if (!dh_isfinite_f32(r * w)) return DH_ERR_OVERFLOW;
    for (i = 0; i < 3; i++) {
        p->n[i] = n[i];
        p->u0[i] = -L * c[i];
        p->u1[i] = (DH_M4(B, i, 3) - DH_M4(A, i, 3)) - L * c[i];
    }
    p->radius = r;
    p->sweep = w * DH_RAD2DEG_F;
    p->length = r * w;
    return DH_OK;
}

dh_status dh_path_arc_f32(dh_path_f32 *p, const dh_mat4_f32 *A, const float via[3], const dh_mat4_f32 *B)
{
    float deg;
    dh_status st;
    DH_ASSERT(p != NULL && A != NULL && via != NULL && B != NULL);
    st = path_check(A, B, via);
    if (st == DH_OK) st = dh_pose_angle_f32(A, B, &deg);
    if (st == DH_OK) st = path_circle(p, A, via, B);
    if (st == DH_OK) path_finish(p, A, B, deg, DH_PATH_ARC);
    return st;
}

/* T's position column = the arc p's point at the distance 0 <= x <= 1/2
 * of s from its end (end 0: p_A, s = x; end 1: p_B, s = 1 - x) less that
 * end */
DH_INLINE void path_arc_off(const dh_path_f32 *p, float x, int end, dh_mat4_f32 *T)
{
    const float *u = (end != 0) ? p->u1 : p->u0;
    const float *n = p->n;
    float s4, c4, sh, ch, sn, cm;
    dh_sincosf_pio4_(0.25f * (x * (p->sweep * DH_DEG2RAD_F)), &s4, &c4);
    sh = 2.0f * s4 * c4;
    ch = (c4 - s4) * (c4 + s4);
    sn = 2.0f * sh * ch;
    cm = -2.0f * sh * sh;
    if (end != 0) sn = -sn;          /* back from p_B: clockwise */
    /* + sn (n x u), the cross product written out (no frame of its own) */
    DH_M4(T, 0, 3) = cm * u[0] + sn * (n[1] * u[2] - n[2] * u[1]);
    DH_M4(T, 1, 3) = cm * u[1] + sn * (n[2] * u[0] - n[0] * u[2]);
    DH_M4(T, 2, 3) = cm * u[2] + sn * (n[0] * u[1] - n[1] * u[0]);
}

/* The position of the arc of p at 0 < s < 1 into T, from the nearer end */
static DH_NOINLINE void path_arc_point(const dh_path_f32 *p, float s, dh_mat4_f32 *T)
{
    const dh_mat4_f32 *E = &p->A;
    float x = s;
    int i, end = 0;
    if (s > 0.5f) {
        E = &p->B;
        x = 1.0f - s;
        end = 1;
    }
    path_arc_off(p, x, end, T);
    for (i = 0; i < 3; i++) DH_M4(T, i, 3) = DH_M4(E, i, 3) + DH_M4(T, i, 3);
}

/* motion_impl.h */
void dh_motion_path_off_f32_(const dh_path_f32 *p, float x, int end, dh_mat4_f32 *T)
{
    const dh_mat4_f32 *E = (end != 0) ? &p->B : &p->A, *F = (end != 0) ? &p->A : &p->B;
    float dp;
    int i;
    if (p->kind != (uint32_t)DH_PATH_ARC) {
        for (i = 0; i < 3; i++) {
            dp = DH_M4(&p->B, i, 3) - DH_M4(&p->A, i, 3);
            DH_M4(T, i, 3) = (end != 0) ? -(x * dp) : x * dp;
        }
    } else if (x <= 0.5f) {
        path_arc_off(p, x, end, T);
    } else {
        path_arc_off(p, 1.0f - x, (end != 0) ? 0 : 1, T);
        for (i = 0; i < 3; i++) DH_M4(T, i, 3) = (DH_M4(F, i, 3) - DH_M4(E, i, 3)) + DH_M4(T, i, 3);
    }
}

/* T's rotation = that of the unit quaternion q */
static DH_NOINLINE void path_rot_set(const dh_quat_f32 *q, dh_mat4_f32 *T)
{
    dh_mat3_f32 R;
    (void)dh_quat_to_mat3_f32(q, &R);
    dh_mat4_set_rot_f32(T, &R);
}

/* The rotation of p at 0 < s < 1 into T, with the bottom row */
static DH_NOINLINE void path_rot(const dh_path_f32 *p, float s, dh_mat4_f32 *T)
{
    dh_quat_f32 q;
    int i;
    dh_motion_slerp_f32_(&p->qa, &p->qb, s, &q);
    path_rot_set(&q, T);
    for (i = 0; i < 3; i++) DH_M4(T, 3, i) = 0.0f;
    DH_M4(T, 3, 3) = 1.0f;
}

/* The position of the line of p at 0 < s < 1 into T, from the nearer end
 * (as dh_pose_interp_f32) */
static DH_NOINLINE void path_line_point(const dh_path_f32 *p, float s, dh_mat4_f32 *T)
{
    float dp;
    int i;
    for (i = 0; i < 3; i++) {
        dp = DH_M4(&p->B, i, 3) - DH_M4(&p->A, i, 3);
        DH_M4(T, i, 3) = (s > 0.5f) ? DH_M4(&p->B, i, 3) - (1.0f - s) * dp : DH_M4(&p->A, i, 3) + s * dp;
    }
}

/* 1 when p holds a path: its quaternions are unit within rounding (an
 * all-zero or NaN struct is not) */
int dh_motion_path_ok_f32_(const dh_path_f32 *p)
{
    const dh_quat_f32 *a = &p->qa, *b = &p->qb;
    float na = a->w * a->w + a->x * a->x + a->y * a->y + a->z * a->z;
    float nb = b->w * b->w + b->x * b->x + b->y * b->y + b->z * b->z;
    return na > 0.5f && na < 2.0f && nb > 0.5f && nb < 2.0f;
}

dh_status dh_path_eval_f32(const dh_path_f32 *p, float s, dh_mat4_f32 *T)
{
    DH_ASSERT(p != NULL && T != NULL);
    if (isunordered(s, s)) return DH_ERR_NAN;
    if (!dh_motion_path_ok_f32_(p)) return DH_ERR_ARG;
    if (!(s > 0.0f) || !(s < 1.0f)) {
        *T = (s > 0.0f) ? p->B : p->A;
        return DH_OK;
    }
    path_rot(p, s, T);
    if (p->kind == (uint32_t)DH_PATH_ARC) {
        path_arc_point(p, s, T);
    } else {
        path_line_point(p, s, T);
    }
    return DH_OK;
}

/* motion_impl.h */
dh_status dh_motion_bound_f32_(float *sl, float num, float den)
{
    float r;
    if (!(den > 0.0f)) return DH_OK;
    r = num / den;
    if (!(r > 0.0f)) return DH_ERR_OVERFLOW;
    if (dh_isfinite_f32(r) && (!(*sl > 0.0f) || r < *sl)) *sl = r;
    return DH_OK;
}

/* *V lowered to sqrt(amax R / sqrt 2) for the arc p (radius R) and *At
 * = the tangential acceleration that leaves room for the centripetal
 * acceleration V^2 / R within amax */
DH_INLINE void path_arc_va(const dh_path_f32 *p, float amax, float *V, float *At)
{
    const float R = p->radius;
    float r = dh_sqrt_f32(amax * PATH_RSQRT2 * R);
    if (r < *V) *V = r;
    r = (*V / amax) * (*V / R);   /* centripetal / amax <= 1/sqrt 2 */
    *At = amax * dh_sqrt_f32(1.0f - r * r);
}

/* motion_impl.h */
void dh_motion_arc_rates_f32_(const dh_path_f32 *p, float amax, float *V, float *At)
{
    path_arc_va(p, amax, V, At);
}

/* The speed and tangential acceleration of the arc p's tool point within
 * lim (and within jk's jmax when jk is not NULL), lowering *V and setting
 * *At; with jk, the tangential jerk bound into *Jt */
static void path_arc_rates(const dh_path_f32 *p, const dh_cart_limits_f32 *lim, const dh_cart_jerk_f32 *jk,
                           float *V, float *At, float *Jt)
{
    float R = p->radius, r;
    if (jk != NULL) {
        r = dh_motion_root_f32_(0.25f * jk->jmax, R, 1) * R;   /* cbrt(jmax R^2 / 4) */
        if (r < *V) *V = r;
    }
    path_arc_va(p, lim->amax, V, At);
    if (jk != NULL) {
        r = (jk->jmax * PATH_TWELFTH) * (R / *V);
        if (r < *At) *At = r;
        *Jt = 0.5f * jk->jmax;
    }
}

/* The speed, acceleration and (jk != NULL) jerk bounds of s for the path
 * p within lim and jk, into b[0], b[1], b[2] */
static dh_status path_rates(const dh_path_f32 *p, const dh_cart_limits_f32 *lim, const dh_cart_jerk_f32 *jk,
                            float b[3])
{
    float V = lim->vmax, At = lim->amax, Jt = (jk != NULL) ? jk->jmax : 0.0f;
    dh_status st;
    if (p->kind == (uint32_t)DH_PATH_ARC && p->radius > 0.0f) path_arc_rates(p, lim, jk, &V, &At, &Jt);
    b[0] = 0.0f;
    b[1] = 0.0f;
    b[2] = 0.0f;
    st = dh_motion_bound_f32_(&b[0], V, p->length);
    if (st == DH_OK) st = dh_motion_bound_f32_(&b[0], lim->wmax, p->angle);
    if (st == DH_OK) st = dh_motion_bound_f32_(&b[1], At, p->length);
    if (st == DH_OK) st = dh_motion_bound_f32_(&b[1], lim->wdmax, p->angle);
    if (st == DH_OK && (!(b[0] > 0.0f) || !(b[1] > 0.0f))) st = DH_ERR_OVERFLOW;
    if (jk != NULL) {
        if (st == DH_OK) st = dh_motion_bound_f32_(&b[2], Jt, p->length);
        if (st == DH_OK) st = dh_motion_bound_f32_(&b[2], jk->wjmax, p->angle);
        if (st == DH_OK && !(b[2] > 0.0f)) st = DH_ERR_OVERFLOW;
    }
    return st;
}

/* the status of the limits lim and jk (NULL: none): DH_ERR_NAN for a
 * NaN/Inf one, DH_ERR_ARG for one <= 0 */
static dh_status path_limits_ok(const dh_cart_limits_f32 *lim, const dh_cart_jerk_f32 *jk)
{
    if (!dh_isfinite_f32(lim->vmax) || !dh_isfinite_f32(lim->amax) || !dh_isfinite_f32(lim->wmax) ||
        !dh_isfinite_f32(lim->wdmax)) {
        return DH_ERR_NAN;
    }
    if (jk != NULL && (!dh_isfinite_f32(jk->jmax) || !dh_isfinite_f32(jk->wjmax))) return DH_ERR_NAN;
    if (!(lim->vmax > 0.0f) || !(lim->amax > 0.0f) || !(lim->wmax > 0.0f) || !(lim->wdmax > 0.0f)) {
        return DH_ERR_ARG;
    }
    if (jk != NULL && (!(jk->jmax > 0.0f) || !(jk->wjmax > 0.0f))) return DH_ERR_ARG;
    return DH_OK;
}

/* the bounds of s (b: the bounds of its first, second and third
 * derivatives) for lim and jerk (NULL: none) and the distance *d (0 when
 * length and angle are 0, or on error) */
static DH_NOINLINE dh_status path_plan(const dh_path_f32 *p, const dh_cart_limits_f32 *lim, const dh_cart_jerk_f32 *jerk,
                                       float *b, float *d)
{
    const dh_status st = path_limits_ok(lim, jerk);
    b[0] = 1.0f;
    b[1] = 1.0f;
    b[2] = 1.0f;
    *d = 0.0f; /* length and angle 0 (or an error): T = 0 */
    if (st == DH_OK && (p->length > 0.0f || p->angle > 0.0f)) {
        *d = 1.0f;
        return path_rates(p, lim, jerk, b);
    }
    return st;
}

/* on error the frame stays at A: no move, duration 0 */
static const dh_profile_f32 path_no_move = { 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0u };

/* The trapezoid and the seven-phase profile are planned by separate
 * functions, so a caller of dh_path_move_f32 does not link (nor count in
 * its stack) the seven-phase profile. */
dh_status dh_path_move_f32(dh_profile_f32 *prof, const dh_path_f32 *p, const dh_cart_limits_f32 *lim)
{
    float b[3], d;
    dh_status st;
    DH_ASSERT(prof != NULL && p != NULL && lim != NULL);
    st = path_plan(p, lim, NULL, b, &d);
    if (st == DH_OK) st = dh_profile_trap_f32(prof, d, b[0], b[1]);
    if (st != DH_OK) *prof = path_no_move;
    return st;
}

dh_status dh_path_move_jerk_f32(dh_profile_f32 *prof, const dh_path_f32 *p, const dh_cart_limits_f32 *lim,
                                const dh_cart_jerk_f32 *jerk)
{
    float b[3], d;
    dh_status st;
    DH_ASSERT(prof != NULL && p != NULL && lim != NULL);
    if (jerk == NULL) return dh_path_move_f32(prof, p, lim);
    st = path_plan(p, lim, jerk, b, &d);
    if (st == DH_OK) st = dh_profile_scurve_f32(prof, d, b[0], b[1], b[2]);
    if (st != DH_OK) *prof = path_no_move;
    return st;
}

dh_status dh_path_move_eval_f32(const dh_profile_f32 *prof, const dh_path_f32 *p, float t, dh_mat4_f32 *T,
                                float *v)
{
    DH_ASSERT(prof != NULL && p != NULL && T != NULL && v != NULL);
    if (isunordered(t, t)) return DH_ERR_NAN;
    if (!dh_motion_path_ok_f32_(p)) return DH_ERR_ARG;
    /* s, s' and s'' in T's position column (no locals beside the path's
     * evaluation: stack), which dh_path_eval_f32 then overwrites */
    (void)dh_profile_eval_f32(prof, t, &DH_M4(T, 0, 3), &DH_M4(T, 1, 3), &DH_M4(T, 2, 3));
    *v = p->length * DH_M4(T, 1, 3);
    return dh_path_eval_f32(p, DH_M4(T, 0, 3), T);
}
