/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_peers.cpp - the C++ peers of the host benchmark: Eigen (Matrix4f,
 * Isometry3f) and Orocos KDL (Frame, ChainFkSolverPos_recursive). Each
 * operation is an extern "C" non-inlined wrapper bw_<id>(i) like the C ones
 * in bench_host.c. Compiled only when a C++ compiler and Eigen and/or KDL
 * were found (BENCH_HAVE_EIGEN, BENCH_HAVE_KDL).
 */
#include "bench_common.h"

#include <cstdio>
#include <cstring>

#if BENCH_HAVE_EIGEN
#include <Eigen/Dense>
#include <Eigen/Geometry>
#endif
#if BENCH_HAVE_KDL
#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/frames.hpp>
#include <kdl/jntarray.hpp>
#endif

namespace {

#if BENCH_HAVE_EIGEN
Eigen::Matrix4f e_A[BENCH_NIN], e_B[BENCH_NIN], e_out[BENCH_NIN];
Eigen::Isometry3f e_IA[BENCH_NIN], e_IB[BENCH_NIN], e_Iout[BENCH_NIN];
#endif

#if BENCH_HAVE_KDL
KDL::Frame k_A[BENCH_NIN], k_B[BENCH_NIN], k_out[BENCH_NIN_FK];
KDL::Chain *k_chain;
KDL::ChainFkSolverPos_recursive *k_fk;
KDL::JntArray *k_q;   // BENCH_NIN joint arrays, in radians
int k_status[BENCH_NIN_FK];
#endif

} // namespace

extern "C" {

#if BENCH_HAVE_EIGEN
BENCH_NOINLINE void bw_eigen_mat4_mul(uint32_t i)
{
    i &= BENCH_MASK;
    e_out[i].noalias() = e_A[i] * e_B[i];
    bench_sink_f = e_out[i](0, 3);
}

BENCH_NOINLINE void bw_eigen_iso_mul(uint32_t i)
{
    i &= BENCH_MASK;
    e_Iout[i] = e_IA[i] * e_IB[i];
    bench_sink_f = e_Iout[i](0, 3);
}

BENCH_NOINLINE void bw_eigen_iso_inv(uint32_t i)
{
    i &= BENCH_MASK;
    e_Iout[i] = e_IA[i].inverse(Eigen::Isometry);
    bench_sink_f = e_Iout[i](0, 3);
}

BENCH_NOINLINE void bw_eigen_mat4_inv(uint32_t i)
{
    i &= BENCH_MASK;
    e_out[i] = e_A[i].inverse();
    bench_sink_f = e_out[i](0, 3);
}
#endif

#if BENCH_HAVE_KDL
BENCH_NOINLINE void bw_kdl_frame_mul(uint32_t i)
{
    i &= BENCH_MASK;
    k_out[i] = k_A[i] * k_B[i];
    bench_sink_d = k_out[i].p.x();
}

BENCH_NOINLINE void bw_kdl_frame_inv(uint32_t i)
{
    i &= BENCH_MASK;
    k_out[i] = k_A[i].Inverse();
    bench_sink_d = k_out[i].p.x();
}

BENCH_NOINLINE void bw_kdl_fk(uint32_t i)
{
    i &= BENCH_FK_MASK;
    k_status[i] = k_fk->JntToCart(k_q[i], k_out[i]);
    bench_sink_d = k_out[i].p.x();
}
#endif

static void put(bench_op *o, int &n, int max, const char *id, const char *group, const char *lib,
                const char *desc, bench_fn fn)
{
    if (n < max) {
        o[n].id = id;
        o[n].group = group;
        o[n].lib = lib;
        o[n].desc = desc;
        o[n].fn = fn;
        n++;
    }
}

int bench_cpp_setup(const float (*A)[16], const float (*B)[16], const double (*q_deg)[6], bench_op *o,
                    int max)
{
    int n = 0;
    (void)A; (void)B; (void)q_deg;
#if BENCH_HAVE_EIGEN
    for (uint32_t i = 0; i < BENCH_NIN; i++) {
        // both column-major: element (row r, col c) is x[4c + r]
        e_A[i] = Eigen::Map<const Eigen::Matrix4f>(A[i]);
        e_B[i] = Eigen::Map<const Eigen::Matrix4f>(B[i]);
        e_IA[i].matrix() = e_A[i];
        e_IB[i].matrix() = e_B[i];
    }
    put(o, n, max, "eigen_iso_mul", "compose", "Eigen", "Isometry3f * Isometry3f", bw_eigen_iso_mul);
    put(o, n, max, "eigen_mat4_mul", "mul4", "Eigen", "Matrix4f * Matrix4f (noalias)", bw_eigen_mat4_mul);
    put(o, n, max, "eigen_iso_inv", "inv_rigid", "Eigen", "Isometry3f::inverse(Eigen::Isometry)", bw_eigen_iso_inv);
    put(o, n, max, "eigen_mat4_inv", "inv_general", "Eigen", "Matrix4f::inverse() (no singularity report)",
        bw_eigen_mat4_inv);
#else
    std::printf("skipped: Eigen (libeigen3-dev not found at configure time)\n");
#endif
#if BENCH_HAVE_KDL
    for (uint32_t i = 0; i < BENCH_NIN; i++) {
        KDL::Rotation Ra(A[i][0], A[i][4], A[i][8], A[i][1], A[i][5], A[i][9], A[i][2], A[i][6], A[i][10]);
        KDL::Rotation Rb(B[i][0], B[i][4], B[i][8], B[i][1], B[i][5], B[i][9], B[i][2], B[i][6], B[i][10]);
        k_A[i] = KDL::Frame(Ra, KDL::Vector(A[i][12], A[i][13], A[i][14]));
        k_B[i] = KDL::Frame(Rb, KDL::Vector(B[i][12], B[i][13], B[i][14]));
    }
    k_chain = new KDL::Chain();
    for (unsigned j = 0; j < bench_puma560.n; j++) {
        const bench_dh_row &r = bench_puma560.j[j];
        const double d2r = 3.14159265358979323846 / 180.0;
        // KDL's standard DH: joint about z at the segment root, tip frame
        // Frame::DH(a, alpha, d, theta) = Rz(theta) Tz(d) Tx(a) Rx(alpha)
        k_chain->addSegment(KDL::Segment(KDL::Joint(KDL::Joint::RotZ),
                                         KDL::Frame::DH(r.a, r.alpha_deg * d2r, r.d, r.theta_deg * d2r)));
    }
    k_fk = new KDL::ChainFkSolverPos_recursive(*k_chain);
    k_q = new KDL::JntArray[BENCH_NIN_FK];
    for (uint32_t i = 0; i < BENCH_NIN_FK; i++) {
        k_q[i].resize(bench_puma560.n);
        for (unsigned j = 0; j < bench_puma560.n; j++) k_q[i](j) = q_deg[i][j] * (3.14159265358979323846 / 180.0);
    }
    put(o, n, max, "kdl_frame_mul", "compose", "KDL", "KDL::Frame * KDL::Frame (double)", bw_kdl_frame_mul);
    put(o, n, max, "kdl_frame_inv", "inv_rigid", "KDL", "KDL::Frame::Inverse() (double)", bw_kdl_frame_inv);
    put(o, n, max, "kdl_fk", "fk_puma", "KDL", "ChainFkSolverPos_recursive::JntToCart, Puma 560 (double)",
        bw_kdl_fk);
#else
    std::printf("skipped: Orocos KDL (liborocos-kdl-dev not found at configure time)\n");
#endif
    return n;
}

int bench_cpp_kdl_fk_pos(uint32_t i, double p[3])
{
#if BENCH_HAVE_KDL
    bw_kdl_fk(i);
    p[0] = k_out[i].p.x();
    p[1] = k_out[i].p.y();
    p[2] = k_out[i].p.z();
    return k_status[i] >= 0;
#else
    (void)i; (void)p;
    return 0;
#endif
}

} // extern "C"
