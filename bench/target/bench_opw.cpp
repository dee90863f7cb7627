/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_opw.cpp - the opw_kinematics peer of the on-target benchmark
 * (Cortex-M4F/M7): opw_kinematics::inverse<float> on the KUKA KR6 R700 sixx
 * with the parameters of opw's own example (makeKukaKR6_R700_sixx,
 * include/opw_kinematics/opw_parameters_examples.h of opw_kinematics).
 * opw is not part of this repository: compiled only when the user gives a
 * clone (BENCH_OPW_DIR, tools/target_bench.sh's OPW_DIR); C++17 in GNU mode
 * (newlib declares M_PI only there), Eigen, newlib's libstdc++.
 *
 * opw's base and flange frames are those of the DH table of bench_target.c
 * (bt_kr6_tab), so targets pass unchanged; its joint values are the
 * robot's (radians), the table's q_dh[j] = sign[j] * q_opw[j] in degrees.
 */
#include "bench_target.h"

#include <cmath>
#include <opw_kinematics/opw_kinematics.h>
#include <opw_kinematics/opw_parameters_examples.h>

namespace {

opw_kinematics::Parameters<float> o_p;
opw_kinematics::Transform<float> o_T[BT_NOPW];
opw_kinematics::Solutions<float> o_sol;
const float o_sign[6] = { -1.0f, 1.0f, 1.0f, -1.0f, 1.0f, -1.0f };

} // namespace

extern "C" {

uint32_t bt_opw_setup(const dh_mat4_f32 *T, uint32_t n)
{
    o_p = opw_kinematics::makeKukaKR6_R700_sixx<float>();
    if (n > BT_NOPW) {
        n = BT_NOPW;
    }
    for (uint32_t k = 0; k < n; k++) {
        for (int c = 0; c < 4; c++) {
            for (int r = 0; r < 4; r++) {
                o_T[k].matrix()(r, c) = T[k].m[c][r];   // dh_mat4_f32: m[col][row]
            }
        }
    }
    return n;
}

BT_NOINLINE void bt_opw_solve(uint32_t k)
{
    o_sol = opw_kinematics::inverse(o_p, o_T[k]);
}

uint32_t bt_opw_solutions(float q_dh_deg[8][6])
{
    uint32_t n = 0;
    for (int s = 0; s < 8; s++) {
        bool ok = true;
        for (int j = 0; j < 6; j++) {
            ok = ok && std::isfinite(o_sol[s][j]);
        }
        if (!ok) {
            continue;
        }
        for (int j = 0; j < 6; j++) {
            q_dh_deg[n][j] = o_sign[j] * o_sol[s][j] * (180.0f / 3.14159265358979f);
        }
        n++;
    }
    return n;
}

} // extern "C"
