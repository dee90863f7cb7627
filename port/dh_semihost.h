/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_semihost.h - the semihosting calls of dhmath's test and example
 * firmware, shared by port/startup_cm.c (Cortex-M) and port/startup_rv.c
 * (RV32). Not part of the library.
 *
 * The including startup file defines, before including this header,
 *   static uintptr_t dh_semihost(uintptr_t op, uintptr_t arg);
 * (the architecture's semihosting trap), and includes it exactly once: it
 * defines _exit().
 *
 * Operation numbers and reason codes: Arm, "Semihosting for AArch32 and
 * AArch64" (ARM IHI 0073); RV32 semihosting uses the same numbers and the
 * AArch32 conventions (docs/references.md).
 */
#ifndef DH_PORT_SEMIHOST_H
#define DH_PORT_SEMIHOST_H

#include <stdint.h>

#define DH_SH_SYS_WRITE0 0x04
#define DH_SH_SYS_EXIT 0x18
#define DH_SH_SYS_EXIT_EXTENDED 0x20
#define DH_SH_ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define DH_SH_ADP_STOPPED_RUNTIME_ERROR 0x20023u

void _exit(int status);

/* Writes a NUL-terminated string to the host's console (no stdio: the
 * fault handlers use it when stdio's state may be what got corrupted). */
static void dh_sh_puts(const char *s)
{
    (void)dh_semihost(DH_SH_SYS_WRITE0, (uintptr_t)s);
}

/* Ends the emulation with `status` as QEMU's exit status. */
void _exit(int status)
{
    uint32_t block[2];
    block[0] = DH_SH_ADP_STOPPED_APPLICATION_EXIT;
    block[1] = (uint32_t)status;
    (void)dh_semihost(DH_SH_SYS_EXIT_EXTENDED, (uintptr_t)block);
    /* Only reached if SYS_EXIT_EXTENDED is not implemented: the classic
     * call cannot carry a status on 32-bit targets, so report success as
     * "application exit" and anything else as a run-time error (QEMU exits
     * with 1 for that). */
    (void)dh_semihost(DH_SH_SYS_EXIT,
                      status == 0 ? DH_SH_ADP_STOPPED_APPLICATION_EXIT
                                  : DH_SH_ADP_STOPPED_RUNTIME_ERROR);
    for (;;) {
    }
}

/* "0x" and 8 hex digits of v, NUL-terminated, into out[11]. */
static void dh_put_hex(char *out, uint32_t v)
{
    int i;
    out[0] = '0';
    out[1] = 'x';
    for (i = 0; i < 8; i++) {
        uint32_t nib = (v >> (28 - 4 * i)) & 0xFu;
        out[2 + i] = (char)(nib < 10u ? '0' + nib : 'a' + nib - 10u);
    }
    out[10] = '\0';
}

#endif /* DH_PORT_SEMIHOST_H */
