/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_common.h - shared declarations of the host benchmark and the
 * accuracy data generator (host only, not part of the library).
 *
 * Every timed operation is a "wrapper": a non-inlined function
 * void bw_xxx(uint32_t i) that reads input set i (cycling through
 * BENCH_NIN precomputed random inputs), performs exactly one operation and
 * writes its result to memory the compiler must assume is observed (a global
 * output array, plus one value into a volatile sink). The timing loop calls
 * the wrapper through a function pointer, so every operation, peers and
 * dhmath alike, pays the same call harness; the harness alone is measured
 * as the "empty" operation.
 */
#ifndef BENCH_COMMON_H
#define BENCH_COMMON_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__GNUC__)
#define BENCH_NOINLINE __attribute__((noinline))
#else
#define BENCH_NOINLINE
#endif

/** Number of precomputed input sets (powers of two). Each wrapper receives
 *  the raw iteration counter and masks it with the mask of its input kind.
 *  Angles and joint configurations come in sets too large for a branch
 *  predictor to memorise (a predictor learns a cycle of 256 quadrant
 *  choices, which would flatter branchy code); matrices, whose operations
 *  have no data-dependent branches, in a set that stays in L1. */
#define BENCH_NIN 256u
#define BENCH_MASK (BENCH_NIN - 1u)
#define BENCH_NIN_TRIG 16384u
#define BENCH_TRIG_MASK (BENCH_NIN_TRIG - 1u)
#define BENCH_NIN_FK 4096u
#define BENCH_FK_MASK (BENCH_NIN_FK - 1u)
/** Closed-form IK targets (FK of random configurations, computed untimed). */
#define BENCH_NIN_IKC 256u
#define BENCH_IKC_MASK (BENCH_NIN_IKC - 1u)

typedef void (*bench_fn)(uint32_t i);

/** One timed operation. */
typedef struct {
    const char *id;      /**< short identifier, also the wrapper name suffix (bw_<id>) */
    const char *group;   /**< operation group: rows of a group are compared with each other */
    const char *lib;     /**< "dhmath", "cglm", "Eigen", "KDL", "libfixmath", "glibc", "ref" */
    const char *desc;    /**< what exactly is timed */
    bench_fn fn;
} bench_op;

/** Volatile sinks (defined in bench_host.c). */
extern volatile float bench_sink_f;
extern volatile double bench_sink_d;
extern volatile int32_t bench_sink_i;

/* ---- robots: DH tables and an independent double reference FK ---------- */

/** One row of a standard-DH table (lengths in metres, angles in degrees). */
typedef struct {
    double a, d, alpha_deg, theta_deg, qmin, qmax;
} bench_dh_row;

typedef struct {
    const char *name;
    unsigned n;
    bench_dh_row j[6];
} bench_dh_robot;

extern const bench_dh_robot bench_puma560;
extern const bench_dh_robot bench_ur5;
extern const bench_dh_robot bench_kr5;
/** KUKA KR6 R700 sixx (bench_host.c): the robot of opw_kinematics' example,
 *  joint limits +-170 deg on every joint (the benchmark's choice), and the
 *  sign from opw's joint values to the table's: q_dh = sign * q_opw. */
extern const bench_dh_robot bench_kr6;
extern const double bench_kr6_sign[6];

/**
 * Plain double-precision standard-DH forward kinematics (no base/tool):
 * for each joint the closed-form link matrix from libm sin/cos of radians
 * (alpha's sin/cos computed every call, as a straightforward implementation
 * would) and a general 4x4 double product. scale multiplies a and d
 * (1 for metres, 1000 for mm). q in degrees. T is column-major m[col][row].
 */
void bench_ref_fk(const bench_dh_robot *r, double scale, const double *q, double T[4][4]);

/**
 * Same, from explicit per-joint parameters (a, d, alpha, theta offset in
 * degrees) - used to evaluate the reference on the parameters exactly as a
 * dh_robot stores them.
 */
void bench_ref_fk_params(unsigned n, const double *a, const double *d, const double *alpha_deg,
                         const double *theta_deg, const double *q, double T[4][4]);

/** A robot prepared for the timed double reference: constants in double,
 *  sin/cos(alpha) computed once (as dhmath and KDL also do). */
typedef struct {
    unsigned n;
    double a[6], d[6], sa[6], ca[6], theta_deg[6];
} bench_ref_model;

void bench_ref_prepare(const bench_dh_robot *r, double scale, bench_ref_model *m);
/** Plain double FK of a prepared model: per joint one libm sin and cos of
 *  radians, the closed-form link matrix, a general 4x4 double product. */
void bench_ref_fk_model(const bench_ref_model *m, const double *q_deg, double T[4][4]);

/** Deterministic xorshift64* generator (uniform in [lo, hi)). */
double bench_rand(uint64_t *state, double lo, double hi);

/* ---- C++ peers (bench_peers.cpp); absent when built without C++ peers --- */

/** Prepare Eigen/KDL inputs from float matrices (column-major 16 floats,
 *  rigid, BENCH_NIN each), a second set, and BENCH_NIN_FK Puma 560 joint
 *  angle sets in degrees. Returns the
 *  number of ops written to ops (at most max). */
int bench_cpp_setup(const float (*A)[16], const float (*B)[16], const double (*q_deg)[6],
                    bench_op *ops, int max);
/** Position of the KDL Puma 560 FK for joint set i (metres), for a sanity
 *  check against the double reference. Returns 0 when KDL is absent. */
int bench_cpp_kdl_fk_pos(uint32_t i, double p[3]);

/* ---- opw_kinematics peer (bench_opw.cpp); absent without OPW_DIR ------- */

/** Prepare the opw inputs from BENCH_NIN_IKC KR6 R700 targets (column-major
 *  16 floats, metres) and write its ops (at most max). Returns their number,
 *  or -1 when the benchmark was built without opw_kinematics. */
int bench_opw_setup(const float (*T)[16], bench_op *ops, int max);
/** Solve target i with opw (dbl: inverse<double>, else <float>) and write
 *  its finite solutions as the DH table's joint values in degrees (not
 *  wrapped). Returns their number (0..8). */
int bench_opw_solutions(uint32_t i, int dbl, double q_dh_deg[8][6]);

#ifdef __cplusplus
}
#endif

#endif /* BENCH_COMMON_H */
