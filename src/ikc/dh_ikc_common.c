/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_ikc_common.c - closed-form IK, float: the helpers that every family
 * solver calls (vectors of T06); interface in ikc_impl.h. Calls no solver
 * and no front end.
 */
#include "ikc_impl.h"
#include "../internal/dh_floatops.h"


void dh_ikc_t06_vec_f32_(const dh_ikc_model_f32 *m, const dh_mat4_f32 *T, const float *v, float w, float *out)
{
    out[0] = v[0];
    out[1] = v[1];
    out[2] = v[2];
    if (!dh_ikc_is_identity_f32_(&m->post_inv)) dh_ikc_xform_f32_(&m->post_inv, out, w, out);
    dh_ikc_xform_f32_(T, out, w, out);
    if (!dh_ikc_is_identity_f32_(&m->pre_inv)) dh_ikc_xform_f32_(&m->pre_inv, out, w, out);
}

