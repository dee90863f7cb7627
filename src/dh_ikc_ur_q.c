/*
 * dh_ikc_ur_q.c - fixed-point closed-form families DH_IKC_PARALLEL_234 and
 * DH_IKC_SCARA (private interface: dh_ikc_impl.h). Placeholder: neither
 * family is detected yet on the fixed path, so such robots analyse to
 * DH_IKC_NONE (reason from the front end); the solvers return no solution.
 */
#include "dh_ikc_impl.h"
#include "dh_internal.h"

int dh_ikc_detect_par234_q_(dh_ikc_model_q *m)
{
    (void)m;
    return 0;
}

int dh_ikc_detect_scara_q_(dh_ikc_model_q *m)
{
    (void)m;
    return 0;
}

dh_status dh_ikc_par234_q_(const dh_ikc_model_q *m, const int32_t *q_ref, dh_ikc_sol_q *sol, uint32_t *count)
{
    (void)m;
    (void)q_ref;
    (void)sol;
    *count = 0;
    return DH_OK;
}

dh_status dh_ikc_scara_q_(const dh_ikc_model_q *m, const int32_t *q_ref, dh_ikc_sol_q *sol, uint32_t *count)
{
    (void)m;
    (void)q_ref;
    (void)sol;
    *count = 0;
    return DH_OK;
}
