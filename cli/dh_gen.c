/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_gen.c - `dhmath gen ROBOT NAME`: the robot built by the library's
 * setters, printed as a C designated initialiser of a const dh_robot.
 *
 * Exactness: every float is printed with %a (C99 hexadecimal floating
 * constant of the float's value converted to double, which is exact) and
 * the suffix f; a float constant whose value is representable is that float
 * exactly, and -0 is written as -0x0p+0f (negation of +0, so -0). Integers
 * are printed in decimal, INT32_MIN as (-2147483647 - 1). Every member is
 * named (designated initialisers): a renamed member breaks the compilation,
 * and the size check catches an added one.
 */
#include <stdint.h>
#include <string.h>

#include "dh_gen.h"

const char *dh_gen_name_problem(const char *name)
{
    static const char *const keywords[] = {
        "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else",
        "enum", "extern", "float", "for", "goto", "if", "inline", "int", "long", "register",
        "restrict", "return", "short", "signed", "sizeof", "static", "struct", "switch", "typedef",
        "union", "unsigned", "void", "volatile", "while", "_Bool", "_Complex", "_Imaginary"
    };
    size_t k, len = strlen(name);
    if (len == 0u) return "it is empty";
    if (len > (size_t)DH_GEN_MAX_NAME) return "it is longer than 63 characters";
    for (k = 0; k < len; k++) {
        const char c = name[k];
        const int alpha = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
        if (!alpha && (k == 0u || c < '0' || c > '9'))
            return k == 0u ? "it must start with a letter or '_'" : "it may hold only letters, digits and '_'";
    }
    if (name[0] == '_' && (name[1] == '_' || (name[1] >= 'A' && name[1] <= 'Z')))
        return "identifiers starting with '__' or '_' and an uppercase letter are reserved";
    for (k = 0; k < sizeof keywords / sizeof keywords[0]; k++)
        if (strcmp(name, keywords[k]) == 0) return "it is a C keyword";
    return NULL;
}

/* +inf (an unlimited rate) as C99's INFINITY of <math.h>, a constant
 * expression of type float */
static void put_f(FILE *out, float x)
{
    if (x > 3.4028235e38f) fputs("INFINITY", out);
    else fprintf(out, "%af", (double)x);
}

static void put_i(FILE *out, int32_t v)
{
    if (v == INT32_MIN) fputs("(-2147483647 - 1)", out);
    else fprintf(out, "%ld", (long)v);
}

/* nl: the line break, " \\\n" inside a macro; four members per line */
static void put_joint(FILE *out, const dh_joint *j, const char *nl)
{
    static const char *const fname[10] = { "a", "d", "alpha_deg", "theta_deg", "qmin", "qmax", "sa", "ca",
                                           "vmax", "amax" };
    static const char *const iname[10] = { "a_q", "d_q", "alpha_q", "theta_q", "sa_q", "ca_q", "qmin_q", "qmax_q",
                                           "vmax_q", "amax_q" };
    const float fv[10] = { j->a, j->d, j->alpha_deg, j->theta_deg, j->qmin, j->qmax, j->sa, j->ca, j->vmax, j->amax };
    const int32_t iv[10] = { j->a_q, j->d_q, j->alpha_q, j->theta_q, j->sa_q, j->ca_q, j->qmin_q, j->qmax_q,
                             j->vmax_q, j->amax_q };
    unsigned k;
    fprintf(out, "{ .type = %s,", j->type == DH_JOINT_PRISMATIC ? "DH_JOINT_PRISMATIC" : "DH_JOINT_REVOLUTE");
    for (k = 0; k < 20u; k++) {
        fprintf(out, (k % 4u == 0u) ? "%s          .%s = " : ", .%s%s = ", (k % 4u == 0u) ? nl : "",
                (k < 10u) ? fname[k] : iname[k - 10u]);
        if (k < 10u) put_f(out, fv[k]);
        else put_i(out, iv[k - 10u]);
        if (k % 4u == 3u && k < 19u) fputc(',', out);
    }
    fputs(" }", out);
}

/* column-major m[col][row], one column per line */
static void put_mat(FILE *out, const char *member, const dh_mat4_f32 *M)
{
    unsigned c, k;
    fprintf(out, "    .%s = { .m = {\n", member);
    for (c = 0; c < 4u; c++) {
        fputs("        { ", out);
        for (k = 0; k < 4u; k++) {
            put_f(out, M->m[c][k]);
            fputs(k < 3u ? ", " : " }", out);
        }
        fputs(c < 3u ? ",\n" : " } },\n", out);
    }
}

static void put_frame(FILE *out, const char *member, const dh_frame_q *F)
{
    unsigned c, k;
    fprintf(out, "    .%s = { .r = { ", member);
    for (c = 0; c < 3u; c++) {
        fputs("{ ", out);
        for (k = 0; k < 3u; k++) {
            put_i(out, F->r[c][k]);
            fputs(k < 2u ? ", " : " }", out);
        }
        fputs(c < 2u ? ", " : " },\n", out);
    }
    fputs("                 .p = { ", out);
    for (k = 0; k < 3u; k++) {
        put_i(out, F->p[k]);
        fputs(k < 2u ? ", " : " } },\n", out);
    }
}

static void put_flags(FILE *out, uint32_t f)
{
    static const struct { uint32_t bit; const char *name; } names[] = {
        { DH_ROBOT_HAS_F32, "HAS_F32" }, { DH_ROBOT_HAS_Q, "HAS_Q" },
        { DH_ROBOT_F32_NO_JOINT, "F32_NO_JOINT" }, { DH_ROBOT_F32_NO_BASE, "F32_NO_BASE" },
        { DH_ROBOT_F32_NO_TOOL, "F32_NO_TOOL" }, { DH_ROBOT_Q_NO_JOINT, "Q_NO_JOINT" },
        { DH_ROBOT_Q_NO_BASE, "Q_NO_BASE" }, { DH_ROBOT_Q_NO_TOOL, "Q_NO_TOOL" },
        { DH_ROBOT_BASE_ID_F32, "BASE_ID_F32" }, { DH_ROBOT_TOOL_ID_F32, "TOOL_ID_F32" },
        { DH_ROBOT_BASE_ID_Q, "BASE_ID_Q" }, { DH_ROBOT_TOOL_ID_Q, "TOOL_ID_Q" },
        { DH_ROBOT_BASE_SMALL_Q, "BASE_SMALL_Q" }
    };
    size_t k;
    const char *sep = "";
    fprintf(out, "    .flags = 0x%05lxu, /* ", (unsigned long)f);
    for (k = 0; k < sizeof names / sizeof names[0]; k++)
        if (f & names[k].bit) {
            fprintf(out, "%s%s", sep, names[k].name);
            sep = " ";
        }
    fputs(" */\n", out);
}

void dh_gen_write(FILE *out, const dh_robot *r, const char *name, const char *src)
{
    dh_robot empty;
    const char *base = src;
    const char *p;
    unsigned i;
    size_t fixed_part = sizeof(dh_robot) - (size_t)DH_MAX_JOINTS * sizeof(dh_joint);
    (void)dh_robot_init(&empty, DH_CONV_STANDARD);
    for (p = src; *p; p++)
        if (*p == '/' || *p == '\\') base = p + 1;
    fputs("/*\n * Generated by `dhmath gen` from the robot file ", out);
    for (p = base; *p; p++) /* printable, and no end of comment */
        fputc((*p >= ' ' && *p <= '~' && !(p[0] == '*' && p[1] == '/')) ? *p : '?', out);
    fprintf(out, ": the dh_robot\n"
                 " * that dh_robot_init, dh_robot_add_joint_f32, dh_robot_set_limits_f32,\n"
                 " * dh_robot_set_rates_f32 and dh_robot_set_base_f32 / dh_robot_set_tool_f32\n"
                 " * build from it, every field\n"
                 " * written out exactly, so that %s lives in flash (.rodata), needs no\n"
                 " * setter at run time, passes dh_robot_check() and gives the same FK, bit for\n"
                 " * bit, as the robot built at run time. Regenerate instead of editing.\n"
                 " */\n", name);
    fputs("#include <math.h> /* INFINITY: unlimited rates */\n\n#include \"dhmath/dhmath.h\"\n\n", out);
    fprintf(out, "#if DH_QPOS_FRAC != %d\n"
                 "#error \"generated for DH_QPOS_FRAC %d: the fixed-point constants differ\"\n"
                 "#endif\n", DH_QPOS_FRAC, DH_QPOS_FRAC);
    fprintf(out, "#if DH_MAX_JOINTS < %lu\n"
                 "#error \"the robot has %lu joints: DH_MAX_JOINTS must be at least %lu\"\n"
                 "#endif\n", (unsigned long)r->n, (unsigned long)r->n, (unsigned long)r->n);
    fprintf(out, "/* dh_robot of the layout this was generated for */\n"
                 "typedef char %s_layout_check[(sizeof(dh_joint) == %luu &&\n"
                 "                              sizeof(dh_robot) == %luu + DH_MAX_JOINTS * %luu) ? 1 : -1];\n\n",
            name, (unsigned long)sizeof(dh_joint), (unsigned long)fixed_part, (unsigned long)sizeof(dh_joint));
    fprintf(out, "/* the empty joint that dh_robot_init writes to every slot */\n#define %s_EMPTY_JOINT ", name);
    put_joint(out, &empty.joint[0], " \\\n");
    fprintf(out, "\n\nextern const dh_robot %s;\nconst dh_robot %s = {\n", name, name);
    fprintf(out, "    .conv = %s,\n", r->conv == DH_CONV_MODIFIED ? "DH_CONV_MODIFIED" : "DH_CONV_STANDARD");
    fprintf(out, "    .n = %luu,\n", (unsigned long)r->n);
    put_flags(out, r->flags);
    fputs("    .joint = {\n", out);
    for (i = 0; i < r->n; i++) {
        const dh_joint *j = &r->joint[i];
        fprintf(out, "        /* joint %u: %s a=%.9g d=%.9g alpha=%.9g theta=%.9g */\n        [%u] = ", i + 1u,
                j->type == DH_JOINT_PRISMATIC ? "P" : "R", (double)j->a, (double)j->d, (double)j->alpha_deg,
                (double)j->theta_deg, i);
        put_joint(out, j, "\n");
        fputs(",\n", out);
    }
    for (i = r->n; i < 32u; i++) /* 32: the largest DH_MAX_JOINTS (config.h) */
        fprintf(out, "#if DH_MAX_JOINTS > %u\n        [%u] = %s_EMPTY_JOINT,\n#endif\n", i, i, name);
    fputs("    },\n", out);
    put_mat(out, "base", &r->base);
    put_mat(out, "tool", &r->tool);
    put_frame(out, "base_q", &r->base_q);
    put_frame(out, "tool_q", &r->tool_q);
    fprintf(out, "};\n\n#undef %s_EMPTY_JOINT\n", name);
}
