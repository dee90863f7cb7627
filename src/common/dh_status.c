/* SPDX-License-Identifier: Apache-2.0 */
#include "dhmath/common.h"

const char *dh_status_str(dh_status st)
{
    switch (st) {
    case DH_OK: return "ok";
    case DH_ERR_ARG: return "bad argument";
    case DH_ERR_NAN: return "NaN or infinite input";
    case DH_ERR_SINGULAR: return "singular matrix";
    case DH_ERR_NOT_RIGID: return "not a rigid transform";
    case DH_ERR_ZERO_AXIS: return "zero rotation axis";
    case DH_ERR_DOMAIN: return "domain error";
    case DH_ERR_OVERFLOW: return "overflow (result out of range)";
    case DH_ERR_NO_CONVERGENCE: return "no convergence";
    case DH_ERR_UNREACHABLE: return "target unreachable";
    case DH_ERR_LIMIT: return "joint limit";
    case DH_ERR_UNAVAILABLE: return "robot path unavailable";
    case DH_ERR_INCONSISTENT: return "inconsistent robot description";
    default: return "unknown status";
    }
}
