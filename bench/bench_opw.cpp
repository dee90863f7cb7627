/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_opw.cpp - the opw_kinematics peer of the host benchmark:
 * opw_kinematics::inverse<float> and <double> on the KUKA KR6 R700 sixx,
 * with the parameters of opw's own example (makeKukaKR6_R700_sixx in
 * include/opw_kinematics/opw_parameters_examples.h of opw_kinematics). opw
 * is not part of this repository: the benchmark's user clones it
 * (tools/bench.sh, OPW_DIR) and this file is compiled only then
 * (BENCH_HAVE_OPW).
 *
 * Conventions: opw's base and flange frames are the frames of the DH table
 * of bench_host.c (bench_kr6, FK of both agree on the same configuration),
 * so the targets are passed unchanged; opw's joint values are the robot's
 * (radians), the DH table's are q_dh[j] = bench_kr6_sign[j] * q_opw[j] in
 * degrees.
 */
#include "bench_common.h"

#include <cmath>
#include <opw_kinematics/opw_kinematics.h>
#include <opw_kinematics/opw_parameters_examples.h>

namespace {

opw_kinematics::Parameters<float> o_pf;
opw_kinematics::Parameters<double> o_pd;
opw_kinematics::Transform<float> o_Tf[BENCH_NIN_IKC];
opw_kinematics::Transform<double> o_Td[BENCH_NIN_IKC];
opw_kinematics::Solutions<float> o_sf[BENCH_NIN_IKC];
opw_kinematics::Solutions<double> o_sd[BENCH_NIN_IKC];

} // namespace

extern "C" {

BENCH_NOINLINE void bw_opw_inverse_f32(uint32_t i)
{
    i &= BENCH_IKC_MASK;
    o_sf[i] = opw_kinematics::inverse(o_pf, o_Tf[i]);
    bench_sink_f = o_sf[i][0][0];
}

BENCH_NOINLINE void bw_opw_inverse_f64(uint32_t i)
{
    i &= BENCH_IKC_MASK;
    o_sd[i] = opw_kinematics::inverse(o_pd, o_Td[i]);
    bench_sink_d = o_sd[i][0][0];
}

int bench_opw_setup(const float (*T)[16], bench_op *o, int max)
{
    int n = 0;
    o_pf = opw_kinematics::makeKukaKR6_R700_sixx<float>();
    o_pd = opw_kinematics::makeKukaKR6_R700_sixx<double>();
    for (uint32_t i = 0; i < BENCH_NIN_IKC; i++) {
        // both column-major: element (row r, col c) is T[i][4c + r]
        const Eigen::Matrix4f M = Eigen::Map<const Eigen::Matrix4f>(T[i]);
        o_Tf[i].matrix() = M;
        o_Td[i].matrix() = M.cast<double>();
    }
    static const bench_op rows[] = {
        { "opw_inverse_f32", "ikc_kr6", "opw",
          "opw_kinematics::inverse<float>, KUKA KR6 R700 sixx (m), 8 solutions (NaN where none), no limits",
          bw_opw_inverse_f32 },
        { "opw_inverse_f64", "ikc_kr6", "opw",
          "opw_kinematics::inverse<double>, same targets (for information: dhmath's float path beside opw's double)",
          bw_opw_inverse_f64 },
    };
    for (const bench_op &r : rows) {
        if (n < max) o[n++] = r;
    }
    return n;
}

int bench_opw_solutions(uint32_t i, int dbl, double q_dh_deg[8][6])
{
    int n = 0;
    i &= BENCH_IKC_MASK;
    if (dbl) {
        bw_opw_inverse_f64(i);
    } else {
        bw_opw_inverse_f32(i);
    }
    for (int s = 0; s < 8; s++) {
        double q[6];
        bool ok = true;
        for (int j = 0; j < 6; j++) {
            q[j] = dbl ? o_sd[i][s][j] : (double)o_sf[i][s][j];
            ok = ok && std::isfinite(q[j]);
        }
        if (!ok) continue;
        for (int j = 0; j < 6; j++) q_dh_deg[n][j] = bench_kr6_sign[j] * q[j] * (180.0 / 3.14159265358979323846);
        n++;
    }
    return n;
}

} // extern "C"
