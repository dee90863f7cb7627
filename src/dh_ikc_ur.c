/*
 * dh_ikc_ur.c - closed-form inverse kinematics, float: the families
 * DH_IKC_PARALLEL_234 (Universal Robots) and DH_IKC_SCARA. Not yet
 * recognised: the detectors say no, so dh_ikc_analyse_f32 reports these
 * robots as having no closed form.
 */
#include "dh_ikc_impl.h"

int dh_ikc_detect_par234_f32_(dh_ikc_model_f32 *m)
{
    (void)m;
    return 0;
}

int dh_ikc_detect_scara_f32_(dh_ikc_model_f32 *m)
{
    (void)m;
    return 0;
}

uint32_t dh_ikc_par234_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                            dh_ikc_sol_f32 *sol)
{
    (void)m;
    (void)T;
    (void)q_ref;
    (void)sol;
    return 0u;
}

uint32_t dh_ikc_scara_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *q_ref,
                           dh_ikc_sol_f32 *sol)
{
    (void)m;
    (void)T;
    (void)q_ref;
    (void)sol;
    return 0u;
}
