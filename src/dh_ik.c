/*
 * dh_ik.c - numerical inverse kinematics in float: Levenberg-Marquardt with
 * Sugihara's damping (T. Sugihara, "Solvability-Unconcerned Inverse
 * Kinematics by the Levenberg-Marquardt Method", cited in seed 003).
 *
 * Per iteration, with the weighted, masked error e (position; w_rot times
 * the orientation error a(dR)), E = 1/2 e^T e and the Jacobian J taken in
 * scaled joint variables x (radians for revolute joints, length / L for
 * prismatic ones, L = the robot's characteristic length, so that every
 * column has the unit of length):
 *
 *   (J^T J + (mu E + wbar) I) dx = J^T e,    wbar = DH_IK_WBAR * L^2
 *
 * (mu = 1 is Sugihara's W_N = E_k + wbar; mu grows after a rejected step).
 * The step is projected on the joint box INSIDE the iteration: joints that
 * sit on a bound and are pushed outward are removed from the system and the
 * system is solved again for the others; the remaining step is clamped into
 * the box. A trial point is accepted only when it lowers E. mu is halved
 * after an accepted step (down to 1e-3) and tripled after a rejected one:
 * gentler than the classic /10 .. x10 schedule, which made the damping
 * saw-tooth between too short and rejected steps in the curved, nearly
 * flat valleys around the Puma's folded-elbow targets (measured: Puma 560
 * success 98.2% -> 99.2% worst seed at the same step budget). An attempt
 * that stalls (4 steps in a row with less than 1%
 * decrease of E, or an empty projected step) is restarted from a
 * deterministic pseudo-random point in the joint box (xorshift32 with a
 * fixed seed: same inputs, same outputs), at most p->restarts times within
 * p->max_iter steps; the best configuration over all attempts is returned.
 * Once the tolerances are met, up to 3 more steps refine the result towards
 * the float resolution. Everything lives in the caller's workspace; no
 * heap, no recursion.
 */
#include "dhmath/dh_kin.h"

#include <float.h>
#include <math.h>

#define IK_RAD2DEG 57.295779513082320876798f
#define IK_POLISH_STEPS 3u      /* refinement steps after the tolerance is met */
#define IK_STALL_STEPS 4u       /* steps in a row with less than 1% progress: stalled */
#define IK_MU_MAX 1e12f
#define IK_MU_MIN 1e-3f        /* lowest multiplier of E in the damping */
#define IK_MU_UP 3.0f          /* damping factor after a rejected step */
#define IK_MU_DOWN 0.5f        /* damping factor after an accepted step */
#define IK_STALL_RATIO 0.99f    /* E must drop below this fraction to count as progress */

/* Keep the helpers out of dh_ik_f32's frame so each frame stays < 256 bytes. */
#if defined(__GNUC__) || defined(__clang__)
#define IK_NOINLINE __attribute__((noinline))
#else
#define IK_NOINLINE
#endif

static int ik_finite(float x) { return fabsf(x) <= FLT_MAX; }

void dh_ik_params_default(dh_ik_params *p)
{
    DH_ASSERT(p != NULL);
    p->max_iter = 2000u;
    p->mask = DH_IK_FULL;
    p->tol_pos = 1e-6f;
    p->tol_rot = 1e-5f;
    p->w_rot = 1.0f;
    p->restarts = 200u;
}

/* Workspace layout (floats), n joints. */
typedef struct {
    float *Ja, *Jb;     /* 6n each: Jacobian at the current / trial point */
    float *H;           /* n*n: normal matrix, then its Cholesky factor */
    float *g, *dx;      /* n each */
    float *qa, *qb;     /* n each: current / trial joint values (deg or length) */
    float *sc;          /* n: joint unit per scaled variable (deg per rad, or L) */
    float *cs;          /* n: Jacobian column scale (1 for revolute, L for prismatic) */
    float *qbest;       /* n: best configuration over all attempts */
    float *ea, *eb;     /* 6 each: raw error (pos, rot) at current / trial */
} ik_ws;

static void ik_layout(ik_ws *w, float *work, uint32_t n)
{
    w->Ja = work;
    w->Jb = w->Ja + 6u * n;
    w->H = w->Jb + 6u * n;
    w->g = w->H + n * n;
    w->dx = w->g + n;
    w->qa = w->dx + n;
    w->qb = w->qa + n;
    w->sc = w->qb + n;
    w->cs = w->sc + n;
    w->qbest = w->cs + n;
    w->ea = w->qbest + n;
    w->eb = w->ea + 6;
}

/* Row weight: 0 for masked-out rows. */
static float ik_row_w(uint32_t mask, uint32_t row, float w_rot)
{
    if ((mask & (1u << row)) == 0u) return 0.0f;
    return (row < 3u) ? 1.0f : w_rot;
}

/* Evaluate J, e at q; *E = 1/2 |W e|^2, *ep / *er = masked error norms. */
static IK_NOINLINE dh_status ik_eval(const dh_robot *r, const dh_mat4_f32 *target, const float *q,
                         const dh_ik_params *p, float *J, float *e, float *E, float *ep, float *er)
{
    dh_mat4_f32 T;
    dh_status st;
    float sp = 0.0f, sr = 0.0f;
    uint32_t k;

    st = dh_jacobian_f32(r, q, J, &T);
    if (st != DH_OK) return st;
    if ((p->mask & (DH_IK_FULL & ~DH_IK_POSITION)) != 0u) {
        st = dh_pose_error_f32(target, &T, e);
        if (st != DH_OK) return st;
    } else {            /* position only: the target's rotation is not read */
        for (k = 0; k < 3u; k++) {
            e[k] = target->m[3][k] - T.m[3][k];
            e[k + 3u] = 0.0f;
        }
    }
    for (k = 0; k < 6u; k++) {
        if ((p->mask & (1u << k)) == 0u) continue;
        if (k < 3u) sp += e[k] * e[k];
        else sr += e[k] * e[k];
    }
    *ep = sqrtf(sp);
    *er = sqrtf(sr);
    *E = 0.5f * (sp + p->w_rot * p->w_rot * sr);
    if (!ik_finite(*E)) return DH_ERR_OVERFLOW;
    return DH_OK;
}

/*
 * Build (J^T W^2 J + damp I) restricted to the free joints (others get an
 * identity row/column and a zero right-hand side), factor it (Cholesky,
 * lower triangle in place) and solve for dx. 0 on success, -1 if the
 * factorisation failed (not positive definite in float / not finite).
 */
static IK_NOINLINE int ik_solve(const ik_ws *w, uint32_t n, uint32_t free_bits, uint32_t mask, float w_rot,
                    float damp)
{
    float *H = w->H, *g = w->g, *x = w->dx;
    uint32_t i, j, k;

    for (i = 0; i < n; i++) {
        int fi = (free_bits >> i) & 1u;
        float gi = 0.0f;
        if (fi) {
            for (k = 0; k < 6u; k++) {
                float wk = ik_row_w(mask, k, w_rot);
                gi += wk * wk * w->Ja[k * n + i] * w->ea[k];
            }
            gi *= w->cs[i];
        }
        g[i] = gi;
        for (j = 0; j <= i; j++) {
            float h = 0.0f;
            int fj = (free_bits >> j) & 1u;
            if (fi && fj) {
                for (k = 0; k < 6u; k++) {
                    float wk = ik_row_w(mask, k, w_rot);
                    h += wk * wk * w->Ja[k * n + i] * w->Ja[k * n + j];
                }
                h *= w->cs[i] * w->cs[j];
                if (i == j) h += damp;
            } else if (i == j) {
                h = 1.0f;
            }
            H[i * n + j] = h;
        }
    }
    /* Cholesky: H = L L^T, L in the lower triangle */
    for (j = 0; j < n; j++) {
        float d = H[j * n + j];
        for (k = 0; k < j; k++) d -= H[j * n + k] * H[j * n + k];
        if (!(d > 0.0f) || !ik_finite(d)) return -1;
        d = sqrtf(d);
        H[j * n + j] = d;
        for (i = j + 1u; i < n; i++) {
            float s = H[i * n + j];
            for (k = 0; k < j; k++) s -= H[i * n + k] * H[j * n + k];
            H[i * n + j] = s / d;
        }
    }
    /* L y = g, then L^T x = y */
    for (i = 0; i < n; i++) {
        float s = g[i];
        for (k = 0; k < i; k++) s -= H[i * n + k] * x[k];
        x[i] = s / H[i * n + i];
    }
    for (i = n; i-- > 0u;) {
        float s = x[i];
        for (k = i + 1u; k < n; k++) s -= H[k * n + i] * x[k];
        x[i] = s / H[i * n + i];
    }
    for (i = 0; i < n; i++)
        if (!ik_finite(x[i])) return -1;
    return 0;
}

static float ik_clamp(const dh_joint *jt, float v)
{
    if (jt->qmin <= jt->qmax) {
        if (v < jt->qmin) return jt->qmin;
        if (v > jt->qmax) return jt->qmax;
    }
    return v;
}

/* Characteristic length: sum of the link lengths, prismatic travel and tool offset. */
static float ik_length_scale(const dh_robot *r)
{
    float L = 0.0f;
    uint32_t i;
    for (i = 0; i < r->n; i++) {
        const dh_joint *jt = &r->joint[i];
        L += fabsf(jt->a) + fabsf(jt->d);
        if (jt->type == DH_JOINT_PRISMATIC && jt->qmin <= jt->qmax)
            L += fmaxf(fabsf(jt->qmin), fabsf(jt->qmax));
    }
    L += sqrtf(r->tool.m[3][0] * r->tool.m[3][0] + r->tool.m[3][1] * r->tool.m[3][1] +
               r->tool.m[3][2] * r->tool.m[3][2]);
    if (!(L > FLT_MIN) || !ik_finite(L * L)) L = 1.0f;
    return L;
}

/*
 * One projected LM step from w->qa into w->qb. Joints on a bound whose step
 * points outward are frozen and the system is solved again (at most n + 1
 * solves); the rest of the step is clamped into the box.
 * Returns 1 if qb differs from qa, 0 for an empty step, -1 if the normal
 * matrix could not be factored.
 */
static IK_NOINLINE int ik_step(const dh_robot *r, const ik_ws *w, const dh_ik_params *p, uint32_t all_bits,
                   float damp)
{
    uint32_t n = r->n, free_bits = all_bits, pass, i;
    int moved = 0;

    for (pass = 0; pass <= n; pass++) {
        uint32_t frozen = 0u;
        if (ik_solve(w, n, free_bits, p->mask, p->w_rot, damp) != 0) return -1;
        for (i = 0; i < n; i++) {
            const dh_joint *jt = &r->joint[i];
            float dq;
            if (((free_bits >> i) & 1u) == 0u || jt->qmin > jt->qmax) continue;
            dq = w->dx[i] * w->sc[i];
            if ((w->qa[i] <= jt->qmin && dq < 0.0f) || (w->qa[i] >= jt->qmax && dq > 0.0f))
                frozen |= 1u << i;
        }
        if (frozen == 0u) break;
        free_bits &= ~frozen;
    }
    for (i = 0; i < n; i++) {
        float dq = ((free_bits >> i) & 1u) ? w->dx[i] * w->sc[i] : 0.0f;
        w->qb[i] = ik_clamp(&r->joint[i], w->qa[i] + dq);
        if (w->qb[i] != w->qa[i]) moved = 1;
    }
    return moved;
}

/* Deterministic restart point: uniform in the box for limited joints,
 * q0 +- 180 deg (revolute) or q0 +- L (prismatic) for free joints. */
static IK_NOINLINE void ik_sample(const dh_robot *r, const float *q0, float L, uint32_t *seed, float *qo)
{
    uint32_t i;
    for (i = 0; i < r->n; i++) {
        const dh_joint *jt = &r->joint[i];
        uint32_t x = *seed;
        float u;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        *seed = x;
        u = (float)(x >> 8) * (1.0f / 16777216.0f);     /* [0, 1) */
        if (jt->qmin <= jt->qmax) qo[i] = ik_clamp(jt, jt->qmin + u * (jt->qmax - jt->qmin));
        else if (jt->type == DH_JOINT_REVOLUTE) qo[i] = q0[i] + (u * 360.0f - 180.0f);
        else qo[i] = q0[i] + (2.0f * u - 1.0f) * L;
    }
}

typedef struct {
    float E, ep, er;
} ik_err;

dh_status dh_ik_f32(const dh_robot *r, const dh_mat4_f32 *target, const float *q0, float *q,
                    const dh_ik_params *p, float *work, size_t work_len, dh_ik_result *res)
{
    ik_ws w;
    ik_err cur, best;
    uint32_t n, i, iter = 0u, stall = 0u, polish = 0u, restarts, seed = 0x2545F491u;
    uint32_t all_bits;
    float L, wbar, mu = 1.0f;
    int conv, best_conv = 0, end = 0;   /* end: 1 stalled, 2 singular (last attempt) */
    dh_status st;

    DH_ASSERT(r != NULL);
    DH_ASSERT(target != NULL);
    DH_ASSERT(q0 != NULL);
    DH_ASSERT(q != NULL);
    DH_ASSERT(p != NULL);
    DH_ASSERT(res != NULL);

    n = r->n;
    if (n == 0u || n > (uint32_t)DH_MAX_JOINTS) return DH_ERR_ARG;
    if (work == NULL || work_len < (size_t)DH_IK_WORK_FLOATS(n)) return DH_ERR_ARG;
    if (p->max_iter == 0u || p->mask == 0u || (p->mask & ~(uint32_t)DH_IK_FULL) != 0u)
        return DH_ERR_ARG;
    if (!(p->tol_pos >= 0.0f) || !(p->tol_rot >= 0.0f) || !ik_finite(p->tol_pos) ||
        !ik_finite(p->tol_rot))
        return DH_ERR_ARG;
    if (!(p->w_rot > 0.0f) || !ik_finite(p->w_rot * p->w_rot)) return DH_ERR_ARG;
    for (i = 0; i < 16u; i++)
        if (!ik_finite(target->m[i / 4u][i % 4u])) return DH_ERR_NAN;
    for (i = 0; i < n; i++)
        if (!ik_finite(q0[i])) return DH_ERR_NAN;

    ik_layout(&w, work, n);
    L = ik_length_scale(r);
    wbar = DH_IK_WBAR * L * L;
    all_bits = (n >= 32u) ? 0xFFFFFFFFu : ((1u << n) - 1u);
    restarts = p->restarts;
    for (i = 0; i < n; i++) {
        const dh_joint *jt = &r->joint[i];
        w.sc[i] = (jt->type == DH_JOINT_REVOLUTE) ? IK_RAD2DEG : L;
        w.cs[i] = (jt->type == DH_JOINT_REVOLUTE) ? 1.0f : L;
        w.qa[i] = ik_clamp(jt, q0[i]);
    }
    st = ik_eval(r, target, w.qa, p, w.Ja, w.ea, &cur.E, &cur.ep, &cur.er);
    if (st != DH_OK) return st;
    conv = (cur.ep <= p->tol_pos && cur.er <= p->tol_rot);
    best = cur;
    best_conv = conv;
    for (i = 0; i < n; i++) w.qbest[i] = w.qa[i];

    while (iter < p->max_iter && !(conv && polish >= IK_POLISH_STEPS)) {
        ik_err tr;
        int k = ik_step(r, &w, p, all_bits, mu * cur.E + wbar);
        end = 0;
        if (k < 0) {
            end = 2;
        } else if (k == 0) {
            end = 1;            /* empty projected step: nothing left to do */
        } else {
            st = ik_eval(r, target, w.qb, p, w.Jb, w.eb, &tr.E, &tr.ep, &tr.er);
            iter++;
            if (st == DH_OK && tr.E < cur.E) {
                float *t;
                stall = (tr.E < cur.E * IK_STALL_RATIO) ? 0u : stall + 1u;
                t = w.Ja; w.Ja = w.Jb; w.Jb = t;
                t = w.ea; w.ea = w.eb; w.eb = t;
                t = w.qa; w.qa = w.qb; w.qb = t;
                if (conv) polish++;
                cur = tr;
                mu = (mu * IK_MU_DOWN > IK_MU_MIN) ? mu * IK_MU_DOWN : IK_MU_MIN;
                if (!conv && cur.ep <= p->tol_pos && cur.er <= p->tol_rot) {
                    conv = 1;
                    mu = IK_MU_MIN;     /* refine with the least damping */
                }
            } else {
                /* rejected (higher error, or the trial could not be evaluated) */
                stall++;
                mu *= IK_MU_UP;
                if (conv) polish = IK_POLISH_STEPS;   /* at the float floor */
            }
            if (!conv && (stall >= IK_STALL_STEPS || mu > IK_MU_MAX)) end = 1;
        }
        if (end == 0) continue;
        /* this attempt is over (local minimum / stuck at limits / singular) */
        if (cur.E < best.E) {
            best = cur;
            best_conv = conv;
            for (i = 0; i < n; i++) w.qbest[i] = w.qa[i];
        }
        if (conv) break;
        /* restart from a deterministic pseudo-random point in the box (a
         * point where FK is not evaluable is skipped) */
        st = DH_ERR_NO_CONVERGENCE;
        while (restarts > 0u && iter < p->max_iter) {
            restarts--;
            ik_sample(r, q0, L, &seed, w.qa);
            st = ik_eval(r, target, w.qa, p, w.Ja, w.ea, &cur.E, &cur.ep, &cur.er);
            iter++;
            if (st == DH_OK) break;
        }
        if (st != DH_OK) {
            cur.E = FLT_MAX;    /* nothing new: best stays */
            break;
        }
        conv = (cur.ep <= p->tol_pos && cur.er <= p->tol_rot);
        mu = 1.0f;
        stall = 0u;
        polish = 0u;
        end = 0;
    }
    if (cur.E < best.E) {
        best = cur;
        best_conv = conv;
        for (i = 0; i < n; i++) w.qbest[i] = w.qa[i];
    }

    for (i = 0; i < n; i++) q[i] = w.qbest[i];
    res->iterations = iter;
    res->err_pos = best.ep;
    res->err_rot = best.er;
    if (best_conv) return DH_OK;
    if (end == 1) return DH_ERR_UNREACHABLE;
    if (end == 2) return DH_ERR_SINGULAR;
    return DH_ERR_NO_CONVERGENCE;
}
