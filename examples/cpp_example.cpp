/* SPDX-License-Identifier: Apache-2.0 */
// cpp_example.cpp - using dhmath from C++ (host, g++): the headers are
// plain C with extern "C" guards, so the library links unchanged.
//
// Forward kinematics of a UR5 (examples/robots/ur5.dh, metres) at q = 0
// and with the base joint turned by 90 degrees. The test in
// examples/CMakeLists.txt checks the printed positions against the robot's
// published data: at q = 0 the tool is at (-0.81725, -0.19145, -0.005491)
// m, and turning joint 1 (about the base z axis) by 90 degrees maps (x, y)
// to (-y, x).
#include <array>
#include <cstdio>

#include "dhmath/dhmath.h"

namespace {

struct Link {
    float d, a, alpha;
};

constexpr std::array<Link, 6> kUr5{ { { 0.089159f, 0.0f, 90.0f },
                                      { 0.0f, -0.425f, 0.0f },
                                      { 0.0f, -0.39225f, 0.0f },
                                      { 0.10915f, 0.0f, 90.0f },
                                      { 0.09465f, 0.0f, -90.0f },
                                      { 0.0823f, 0.0f, 0.0f } } };

bool print_tool(const dh_robot &arm, const std::array<float, 6> &q)
{
    dh_mat4_f32 T;
    const dh_status st = dh_fk_f32(&arm, q.data(), &T);
    if (st != DH_OK) {
        std::fprintf(stderr, "dh_fk_f32: %s\n", dh_status_str(st));
        return false;
    }
    std::printf("q1=%g tool at %.5f %.5f %.5f\n", static_cast<double>(q[0]),
                static_cast<double>(DH_M4(&T, 0, 3)), static_cast<double>(DH_M4(&T, 1, 3)),
                static_cast<double>(DH_M4(&T, 2, 3)));
    return true;
}

} // namespace

int main()
{
    dh_robot arm;
    if (dh_robot_init(&arm, DH_CONV_STANDARD) != DH_OK) return 1;
    for (const Link &l : kUr5) {
        if (dh_robot_add_joint_f32(&arm, DH_JOINT_REVOLUTE, 0.0f, l.d, l.a, l.alpha) != DH_OK)
            return 1;
    }
    if (!print_tool(arm, { 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f })) return 1;
    if (!print_tool(arm, { 90.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f })) return 1;
    return 0;
}
