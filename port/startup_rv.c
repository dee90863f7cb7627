/* SPDX-License-Identifier: Apache-2.0 */
/*
 * startup_rv.c - reset and trap handling for dhmath's RISC-V (RV32) test and
 * example firmware under QEMU's `virt` machine, machine mode, bare metal.
 *
 * Not part of the library: linked into target executables by
 * port/dh_target.cmake with picolibc (--specs=picolibc.specs, its
 * semihosting library for stdio) and port/qemu-virt-rv32.ld.
 *
 * Why our own startup instead of picolibc's crt0:
 *  - a trap (DH_ASSERT's __builtin_trap is an ebreak, a bad pointer is an
 *    access fault) must end the emulator with status 3 and a message, as
 *    on Cortex-M (port/startup_cm.c); picolibc's semihost crt0 ends it with
 *    status 1, which the test runner also uses for "one case failed";
 *  - main's return value must become QEMU's exit status: SYS_EXIT_EXTENDED
 *    carries it (RV32 semihosting follows the AArch32 conventions, where
 *    plain SYS_EXIT carries only a reason code).
 *
 * Sequence: _start sets the stack and global pointers and mtvec, enables
 * the FPU when compiled for one (mstatus.FS = initial), then dh_rv_cstart
 * copies .data/.tdata from flash, zeroes .tbss/.bss, sets the thread
 * pointer (picolibc keeps errno in TLS), runs the init arrays, calls main
 * and passes its result to exit() (which flushes stdio and ends in _exit).
 *
 * Semihosting calls: RISC-V Semihosting specification (RISC-V
 * International, version 0.2), operation numbers from ARM IHI 0073
 * "Semihosting for AArch32 and AArch64".
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

extern int main(void);
extern void __libc_init_array(void);
extern void _set_tls(void *tls);

/* symbols of picolibc.ld */
extern char __data_start[];
extern char __data_source[];
extern char __data_size[];
extern char __bss_start[];
extern char __bss_size[];
extern char __tls_base[];

void _start(void);
void dh_rv_cstart(void);
void dh_rv_trap_entry(void);
void dh_rv_trap_report(void);

/* The CSR instructions are the Zicsr extension, which newer assemblers
 * want named; the library itself never uses them. */
#define DH_RV_ZICSR ".option push\n\t.option arch, +zicsr\n\t"

/* The semihosting trap: an ebreak between two hint instructions (slli x0 /
 * srai x0), uncompressed and within one 4-byte aligned block so that the
 * emulator can tell it from a plain breakpoint. */
static uintptr_t dh_semihost(uintptr_t op, uintptr_t arg)
{
    register uintptr_t a0 __asm__("a0") = op;
    register uintptr_t a1 __asm__("a1") = arg;
    __asm__ volatile(".option push\n\t"
                     ".option norvc\n\t"
                     ".balign 16\n\t"
                     "slli x0, x0, 0x1f\n\t"
                     "ebreak\n\t"
                     "srai x0, x0, 7\n\t"
                     ".option pop"
                     : "+r"(a0)
                     : "r"(a1)
                     : "memory");
    return a0;
}

/* dh_sh_puts, dh_put_hex and _exit (main's status becomes QEMU's) */
#include "dh_semihost.h"

/* Entry point (first in flash: picolibc.ld puts .text.init.enter there and
 * QEMU's virt machine jumps to the ELF entry with -bios none). */
__attribute__((naked, section(".text.init.enter"))) void _start(void)
{
    __asm__ volatile(DH_RV_ZICSR
                     ".option norelax\n\t"
                     "la gp, __global_pointer$\n\t"
                     "la sp, __stack\n\t"
                     "la t0, dh_rv_trap_entry\n\t"
                     "csrw mtvec, t0\n\t"
#if defined(__riscv_flen)
                     "li t0, 0x2000\n\t" /* mstatus.FS = 01 (initial) */
                     "csrs mstatus, t0\n\t"
                     "csrw fcsr, zero\n\t"
#endif
                     ".option pop\n\t"
                     "j dh_rv_cstart\n\t");
}

void dh_rv_cstart(void)
{
    /* .data and .tdata are one block in flash and in RAM (picolibc.ld
     * checks that both sizes match); .tbss and .bss likewise. */
    memcpy(__data_start, __data_source, (size_t)(uintptr_t)__data_size);
    memset(__bss_start, 0, (size_t)(uintptr_t)__bss_size);
    _set_tls(__tls_base);
    __libc_init_array();
    exit(main());
}

/* Called by dh_rv_trap_entry for every trap (nothing enables interrupts, so
 * each one is an exception). Prints the cause through semihosting (no
 * stdio: its state may be what got corrupted) and ends the run with
 * status 3. Cause names: RISC-V Privileged Architecture, table "Machine
 * cause register (mcause) values after trap". */
void dh_rv_trap_report(void)
{
    static const char *const names[] = { "instruction address misaligned",
                                          "instruction access fault",
                                          "illegal instruction",
                                          "breakpoint",
                                          "load address misaligned",
                                          "load access fault",
                                          "store address misaligned",
                                          "store access fault" };
    char hex[11];
    uint32_t cause, epc, tval;
    __asm__ volatile(DH_RV_ZICSR "csrr %0, mcause\n\t.option pop" : "=r"(cause));
    __asm__ volatile(DH_RV_ZICSR "csrr %0, mepc\n\t.option pop" : "=r"(epc));
    __asm__ volatile(DH_RV_ZICSR "csrr %0, mtval\n\t.option pop" : "=r"(tval));
    dh_sh_puts("\n*** dhmath target: ");
    if (cause < sizeof names / sizeof names[0]) {
        dh_sh_puts(names[cause]);
    } else {
        dh_sh_puts("unexpected trap, mcause ");
        dh_put_hex(hex, cause);
        dh_sh_puts(hex);
    }
    dh_sh_puts(" at pc ");
    dh_put_hex(hex, epc);
    dh_sh_puts(hex);
    dh_sh_puts(", mtval ");
    dh_put_hex(hex, tval);
    dh_sh_puts(hex);
    dh_sh_puts("\n*** (a breakpoint at pc is DH_ASSERT or __builtin_trap; "
               "riscv64-unknown-elf-addr2line -e <test> <pc> names the line)\n");
    _exit(3);
}

/* mtvec target (direct mode: 4-byte aligned). The trapped context is not
 * resumed, so a fresh stack at the top of RAM is safe even when the trap
 * came from a stack overflow. */
__attribute__((naked, aligned(4))) void dh_rv_trap_entry(void)
{
    __asm__ volatile("la sp, __stack\n\t"
                     "j dh_rv_trap_report\n\t");
}
