/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_path.c - Cartesian paths (line, circular arc) between two frames and
 * their time-optimal trapezoidal moves.
 *
 * Orientation of every path: dh_pose_interp_f32 from A to B (slerp along
 * the shortest arc, angle proportional to s). Position of a line: that of
 * dh_pose_interp_f32 (p_A + s (p_B - p_A)). Position of an arc: the circle
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
 * held to V = sqrt(amax R / sqrt 2), so the centripetal acceleration is at
 * most amax / sqrt 2, and the tangential one to sqrt(amax^2 - (V^2/R)^2):
 * the total stays within amax.
 */
#include <float.h>
#include <math.h>

#include "dhmath/motion.h"
#include "dhmath/mat4.h"
#include "../internal/dh_floatops.h"

#define PATH_2PI 6.283185307179586f
#define PATH_THIN 9.765625e-4f        /* 2^-10: the thinnest triangle of an arc */
#define PATH_RSQRT2 0.70710678118654752f

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

/* The checks shared by both paths: A and B rigid frames, d = p_B - p_A
 * finite, *deg the angle from R_A to R_B */
static dh_status path_ends(const dh_mat4_f32 *A, const dh_mat4_f32 *B, float d[3], float *deg)
{
    dh_status st = dh_mat4_check_rigid_f32(A, DH_ROT_TOL);
    int i;
    if (st == DH_OK) st = dh_mat4_check_rigid_f32(B, DH_ROT_TOL);
    if (st != DH_OK) return st;
    for (i = 0; i < 3; i++) {
        d[i] = DH_M4(B, i, 3) - DH_M4(A, i, 3);
        if (!dh_isfinite_f32(d[i])) return DH_ERR_OVERFLOW;
    }
    return dh_pose_angle_f32(A, B, deg);
}

/* The circle of an arc (the arc's fields of dh_path_f32) */
typedef struct {
    float u0[3], u1[3], n[3], radius, sweep, length;
} path_circle_t;

/* p = the path of kind k from A to B with the angle deg and the circle c
 * (all zero for a line) */
static void path_store(dh_path_f32 *p, const dh_mat4_f32 *A, const dh_mat4_f32 *B, float deg,
                       const path_circle_t *c, dh_path_kind k)
{
    int i;
    p->A = *A;
    p->B = *B;
    for (i = 0; i < 3; i++) {
        p->u0[i] = c->u0[i];
        p->u1[i] = c->u1[i];
        p->n[i] = c->n[i];
    }
    p->length = c->length;
    p->angle = deg;
    p->radius = c->radius;
    p->sweep = c->sweep;
    p->kind = (uint32_t)k;
}

dh_status dh_path_line_f32(dh_path_f32 *p, const dh_mat4_f32 *A, const dh_mat4_f32 *B)
{
    static const path_circle_t line = { { 0.0f, 0.0f, 0.0f }, { 0.0f, 0.0f, 0.0f }, { 0.0f, 0.0f, 0.0f },
                                        0.0f, 0.0f, 0.0f };
    path_circle_t c;
    float d[3], deg;
    dh_status st;
    DH_ASSERT(p != NULL && A != NULL && B != NULL);
    st = path_ends(A, B, d, &deg);
    if (st != DH_OK) return st;
    c = line;
    c.length = path_norm(d);
    if (!dh_isfinite_f32(c.length)) return DH_ERR_OVERFLOW;
    path_store(p, A, B, deg, &c, DH_PATH_LINE);
    return DH_OK;
}

/* The circle q of the arc from a = via - p_A and b = p_B - p_A (both
 * modified). DH_ERR_OVERFLOW for a side that overflows, DH_ERR_SINGULAR
 * for a thin triangle. */
static DH_NOINLINE dh_status path_circle(path_circle_t *q, float a[3], float b[3])
{
    float e[3], n[3], c[3], t[3], L, la, lb, ln, sa, sb, w;
    int i;
    for (i = 0; i < 3; i++) {
        e[i] = b[i] - a[i];
        if (!dh_isfinite_f32(e[i])) return DH_ERR_OVERFLOW;
    }
    L = path_norm(a);
    la = path_norm(b);
    if (la > L) L = la;
    la = path_norm(e);
    if (la > L) L = la;
    if (!dh_isfinite_f32(L)) return DH_ERR_OVERFLOW;
    if (!(L > 0.0f)) return DH_ERR_SINGULAR;
    for (i = 0; i < 3; i++) {
        e[i] = b[i];                 /* b unscaled, for u1 */
        a[i] /= L;
        b[i] /= L;
    }
    path_cross(a, b, n);
    ln = dh_sqrt_f32(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(ln > PATH_THIN)) return DH_ERR_SINGULAR;
    la = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    lb = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
    path_cross(b, n, c);
    path_cross(n, a, t);
    w = 0.5f / (ln * ln);
    for (i = 0; i < 3; i++) {
        c[i] = (la * c[i] + lb * t[i]) * w;   /* centre - p_A, over L */
        q->n[i] = n[i] / ln;
        q->u0[i] = -L * c[i];
        q->u1[i] = e[i] - L * c[i];
        b[i] -= c[i];                         /* u1 / L */
    }
    /* the sweep from u0 = -c to u1 = b - c about n, in (0, 2 pi) */
    path_cross(c, b, t);
    sa = -(t[0] * q->n[0] + t[1] * q->n[1] + t[2] * q->n[2]);
    sb = -(c[0] * b[0] + c[1] * b[1] + c[2] * b[2]);
    w = dh_atan2f_(sa, sb);
    if (w < 0.0f) w += PATH_2PI;
    q->radius = L * dh_sqrt_f32(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    q->sweep = w * DH_RAD2DEG_F;
    q->length = q->radius * w;
    return dh_isfinite_f32(q->length) ? DH_OK : DH_ERR_OVERFLOW;
}

dh_status dh_path_arc_f32(dh_path_f32 *p, const dh_mat4_f32 *A, const float via[3], const dh_mat4_f32 *B)
{
    path_circle_t c;
    float a[3], b[3], deg;
    dh_status st;
    int i;
    DH_ASSERT(p != NULL && A != NULL && via != NULL && B != NULL);
    st = path_ends(A, B, b, &deg);
    if (st == DH_OK && !dh_allfinite_f32(via, 3u)) st = DH_ERR_NAN;
    if (st != DH_OK) return st;
    for (i = 0; i < 3; i++) {
        a[i] = via[i] - DH_M4(A, i, 3);
        if (!dh_isfinite_f32(a[i])) return DH_ERR_OVERFLOW;
    }
    st = path_circle(&c, a, b);
    if (st == DH_OK) path_store(p, A, B, deg, &c, DH_PATH_ARC);
    return st;
}

/* The position of the arc of p at 0 < s < 1 into T, from the nearer end */
static DH_NOINLINE void path_arc_point(const dh_path_f32 *p, float s, dh_mat4_f32 *T)
{
    const dh_mat4_f32 *E = (s > 0.5f) ? &p->B : &p->A;
    const float *u = (s > 0.5f) ? p->u1 : p->u0;
    float x = ((s > 0.5f) ? 1.0f - s : s) * (p->sweep * DH_DEG2RAD_F);
    float s4, c4, sh, ch, sn, cm, t[3];
    int i;
    dh_sincosf_pio4_(0.25f * x, &s4, &c4);
    sh = 2.0f * s4 * c4;
    ch = (c4 - s4) * (c4 + s4);
    sn = 2.0f * sh * ch;
    cm = -2.0f * sh * sh;
    if (s > 0.5f) sn = -sn;          /* back from p_B: clockwise */
    path_cross(p->n, u, t);
    for (i = 0; i < 3; i++) DH_M4(T, i, 3) = DH_M4(E, i, 3) + (cm * u[i] + sn * t[i]);
}

dh_status dh_path_eval_f32(const dh_path_f32 *p, float s, dh_mat4_f32 *T)
{
    dh_status st;
    DH_ASSERT(p != NULL && T != NULL);
    if (isunordered(s, s)) return DH_ERR_NAN;
    if (!(s > 0.0f) || !(s < 1.0f)) {
        *T = (s > 0.0f) ? p->B : p->A;
        return DH_OK;
    }
    st = dh_pose_interp_f32(&p->A, &p->B, s, T);
    if (st == DH_OK && p->kind == (uint32_t)DH_PATH_ARC) path_arc_point(p, s, T);
    return st;
}

/* *sl = min(*sl, num / den) for den > 0 (*sl == 0: no bound yet); a
 * quotient of +Inf bounds nothing. DH_ERR_OVERFLOW when it underflows to
 * 0 or is NaN. */
static dh_status path_bound(float *sl, float num, float den)
{
    float r;
    if (!(den > 0.0f)) return DH_OK;
    r = num / den;
    if (!(r > 0.0f)) return DH_ERR_OVERFLOW;
    if (dh_isfinite_f32(r) && (!(*sl > 0.0f) || r < *sl)) *sl = r;
    return DH_OK;
}

/* The speed and acceleration bounds of s for the path p within lim */
static dh_status path_rates(const dh_path_f32 *p, const dh_cart_limits_f32 *lim, float *vs, float *as)
{
    float V = lim->vmax, At = lim->amax, r;
    dh_status st;
    if (p->kind == (uint32_t)DH_PATH_ARC && p->radius > 0.0f) {
        r = dh_sqrt_f32(lim->amax * PATH_RSQRT2 * p->radius);
        if (r < V) V = r;
        r = (V / lim->amax) * (V / p->radius);   /* centripetal / amax <= 1/sqrt 2 */
        At = lim->amax * dh_sqrt_f32(1.0f - r * r);
    }
    *vs = 0.0f;
    *as = 0.0f;
    st = path_bound(vs, V, p->length);
    if (st == DH_OK) st = path_bound(vs, lim->wmax, p->angle);
    if (st == DH_OK) st = path_bound(as, At, p->length);
    if (st == DH_OK) st = path_bound(as, lim->wdmax, p->angle);
    if (st == DH_OK && (!(*vs > 0.0f) || !(*as > 0.0f))) st = DH_ERR_OVERFLOW;
    return st;
}

dh_status dh_path_move_f32(dh_profile_f32 *prof, const dh_path_f32 *p, const dh_cart_limits_f32 *lim)
{
    static const dh_profile_f32 no_move = { 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0u };
    float vs = 1.0f, as = 1.0f, d = 1.0f;
    dh_status st = DH_OK;
    DH_ASSERT(prof != NULL && p != NULL && lim != NULL);
    if (!dh_isfinite_f32(lim->vmax) || !dh_isfinite_f32(lim->amax) || !dh_isfinite_f32(lim->wmax) ||
        !dh_isfinite_f32(lim->wdmax)) {
        st = DH_ERR_NAN;
    } else if (!(lim->vmax > 0.0f) || !(lim->amax > 0.0f) || !(lim->wmax > 0.0f) || !(lim->wdmax > 0.0f)) {
        st = DH_ERR_ARG;
    } else if (p->length > 0.0f || p->angle > 0.0f) {
        st = path_rates(p, lim, &vs, &as);
    } else {
        d = 0.0f;                     /* length and angle 0: T = 0 */
    }
    if (st == DH_OK) st = dh_profile_trap_f32(prof, d, vs, as);
    /* on error the frame stays at A: no move, duration 0 */
    if (st != DH_OK) *prof = no_move;
    return st;
}

dh_status dh_path_move_eval_f32(const dh_profile_f32 *prof, const dh_path_f32 *p, float t, dh_mat4_f32 *T,
                                float *v)
{
    float s, sd, sdd;
    dh_status st;
    DH_ASSERT(prof != NULL && p != NULL && T != NULL && v != NULL);
    if (isunordered(t, t)) return DH_ERR_NAN;
    (void)dh_profile_eval_f32(prof, t, &s, &sd, &sdd);
    st = dh_path_eval_f32(p, s, T);
    if (st == DH_OK) *v = p->length * sd;
    return st;
}
