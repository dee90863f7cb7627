/* SPDX-License-Identifier: Apache-2.0 */
/*
 * startup_cm.c - reset and fault handling for dhmath's Cortex-M test and
 * benchmark firmware under QEMU (any ARMv6-M / ARMv7-M / ARMv7E-M core).
 *
 * Not part of the library: it is linked into target test executables by
 * port/dh_target.cmake (with a port/<board>.ld linker script and newlib's
 * semihosting "rdimon" syscalls).
 *
 * Why our own startup instead of newlib's rdimon crt0:
 *  - crt0 neither copies .data from flash to RAM nor enables the FPU, so a
 *    hard-float image would fault on its first float instruction;
 *  - a fault (bad pointer, DH_ASSERT's trap, unaligned access, undefined
 *    instruction) must end the emulator with a non-zero status and a
 *    message, not spin forever until the ctest timeout;
 *  - main's return value must become QEMU's exit status. We do that
 *    ourselves with SYS_EXIT_EXTENDED rather than trusting the libgloss
 *    version, and fall back to SYS_EXIT's "run-time error" reason (QEMU
 *    maps it to status 1) if the extended call is not implemented.
 *
 * Sequence: Reset_Handler enables the FPU (when compiled for one), copies
 * .data, zeroes .bss, opens the semihosting standard streams, calls main
 * and passes its result to exit() (which flushes stdio and ends in our
 * _exit below).
 */
#include <errno.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

extern int main(void);
extern void initialise_monitor_handles(void);

extern uint32_t __data_load__[];
extern uint32_t __data_start__[];
extern uint32_t __data_end__[];
extern uint32_t __bss_start__[];
extern uint32_t __bss_end__[];
extern uint32_t __stack_top__[];

/*
 * Heap for newlib (stdio buffers, dtoa) in the test runner only: from `end`
 * (after .bss) up to __stack_limit__, the bottom of the DH_STACK_SIZE bytes
 * the linker script keeps for the stack. Replaces libgloss's weak _sbrk,
 * which would let the heap grow into the stack.
 */
extern char end[];
extern char __stack_limit__[];

void *_sbrk(ptrdiff_t incr);
void *_sbrk(ptrdiff_t incr)
{
    static char *brk;
    char *prev;
    if (brk == NULL) {
        brk = end;
    }
    if (incr > __stack_limit__ - brk || incr < end - brk) {
        errno = ENOMEM;
        return (void *)-1;
    }
    prev = brk;
    brk += incr;
    return prev;
}

void Reset_Handler(void);
void dh_fault_entry(void);
void dh_fault_report(const uint32_t *frame);
/* The Arm semihosting trap (ARM IHI 0073: BKPT 0xAB on M-profile). */
static uintptr_t dh_semihost(uintptr_t op, uintptr_t arg)
{
    register uintptr_t r0 __asm__("r0") = op;
    register uintptr_t r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

/* dh_sh_puts, dh_put_hex and _exit (main's status becomes QEMU's) */
#include "dh_semihost.h"

/* With -nostartfiles there is no crti.o: newlib's exit() still calls
 * __libc_fini_array, which calls _fini. C has no static destructors, so
 * both hooks are empty. */
void _init(void);
void _fini(void);
void _init(void)
{
}
void _fini(void)
{
}

void Reset_Handler(void)
{
    volatile uint32_t *dst;
    const volatile uint32_t *src;
#if defined(__ARM_FP)
    /* CPACR: full access to coprocessors 10 and 11 (the FPU) before any
     * floating-point instruction runs. */
    volatile uint32_t *cpacr = (volatile uint32_t *)0xE000ED88u;
    *cpacr |= (0xFu << 20);
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
    /* volatile pointers: keep the compiler from turning these loops into
     * memcpy/memset calls (which could use the FPU or the not yet
     * initialised .data). */
    src = __data_load__;
    for (dst = __data_start__; dst < __data_end__; dst++, src++) {
        *dst = *src;
    }
    for (dst = __bss_start__; dst < __bss_end__; dst++) {
        *dst = 0u;
    }
    initialise_monitor_handles();
    exit(main());
}

/* Called by dh_fault_entry with the exception stack frame (r0-r3, r12, lr,
 * pc, xpsr) the core pushed on the main stack. Prints what happened through
 * semihosting (no stdio: its state may be what got corrupted) and ends the
 * run with status 3 (any non-zero status fails the ctest; the log tells a
 * crash from failed checks). */
void dh_fault_report(const uint32_t *frame)
{
    static const char *const names[] = { "thread", "reset", "NMI", "HardFault",
                                          "MemManage fault", "BusFault",
                                          "UsageFault" };
    char hex[11];
    uint32_t ipsr;
    __asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
    ipsr &= 0x1FFu;
    dh_sh_puts("\n*** dhmath target: ");
    if (ipsr < sizeof names / sizeof names[0]) {
        dh_sh_puts(names[ipsr]);
    } else {
        dh_sh_puts("unexpected exception/interrupt ");
        dh_put_hex(hex, ipsr);
        dh_sh_puts(hex);
    }
    dh_sh_puts(" at pc ");
    dh_put_hex(hex, frame[6]);
    dh_sh_puts(hex);
    dh_sh_puts(", lr ");
    dh_put_hex(hex, frame[5]);
    dh_sh_puts(hex);
#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__)
    dh_sh_puts(", CFSR ");
    dh_put_hex(hex, *(volatile const uint32_t *)0xE000ED28u);
    dh_sh_puts(hex);
    dh_sh_puts(", HFSR ");
    dh_put_hex(hex, *(volatile const uint32_t *)0xE000ED2Cu);
    dh_sh_puts(hex);
    dh_sh_puts(", MMFAR ");
    dh_put_hex(hex, *(volatile const uint32_t *)0xE000ED34u);
    dh_sh_puts(hex);
    dh_sh_puts(", BFAR ");
    dh_put_hex(hex, *(volatile const uint32_t *)0xE000ED38u);
    dh_sh_puts(hex);
#endif
    dh_sh_puts("\n*** (a trap at pc is DH_ASSERT or __builtin_trap; "
               "arm-none-eabi-addr2line -e <test> <pc> names the line)\n");
    _exit(3);
}

/* Every fault and unexpected interrupt lands here. Nothing in the firmware
 * uses the process stack, so the exception frame is on the main stack; it
 * is read before this function touches the stack. */
__attribute__((naked)) void dh_fault_entry(void)
{
    __asm__ volatile("mrs r0, msp\n\t"
                     "ldr r1, =dh_fault_report\n\t"
                     "bx r1\n\t"
                     ".ltorg\n");
}

/* Handlers a firmware may override (the benchmark defines SysTick_Handler). */
void NMI_Handler(void) __attribute__((weak, alias("dh_fault_entry")));
void HardFault_Handler(void) __attribute__((weak, alias("dh_fault_entry")));
void MemManage_Handler(void) __attribute__((weak, alias("dh_fault_entry")));
void BusFault_Handler(void) __attribute__((weak, alias("dh_fault_entry")));
void UsageFault_Handler(void) __attribute__((weak, alias("dh_fault_entry")));
void SVC_Handler(void) __attribute__((weak, alias("dh_fault_entry")));
void DebugMon_Handler(void) __attribute__((weak, alias("dh_fault_entry")));
void PendSV_Handler(void) __attribute__((weak, alias("dh_fault_entry")));
void SysTick_Handler(void) __attribute__((weak, alias("dh_fault_entry")));

typedef void (*dh_vector)(void);

/* 16 system vectors + 32 external interrupts (enough for every board we
 * run on; an unexpected interrupt reports itself and stops). The first
 * entry is the initial main stack pointer. */
#define DH_N_IRQ 32
__attribute__((section(".vectors"), used))
const dh_vector dh_vector_table[16 + DH_N_IRQ] = {
    (dh_vector)(uintptr_t)__stack_top__,
    Reset_Handler,
    NMI_Handler,
    HardFault_Handler,
    MemManage_Handler,
    BusFault_Handler,
    UsageFault_Handler,
    0, 0, 0, 0,
    SVC_Handler,
    DebugMon_Handler,
    0,
    PendSV_Handler,
    SysTick_Handler,
    /* external interrupts */
    dh_fault_entry, dh_fault_entry, dh_fault_entry, dh_fault_entry,
    dh_fault_entry, dh_fault_entry, dh_fault_entry, dh_fault_entry,
    dh_fault_entry, dh_fault_entry, dh_fault_entry, dh_fault_entry,
    dh_fault_entry, dh_fault_entry, dh_fault_entry, dh_fault_entry,
    dh_fault_entry, dh_fault_entry, dh_fault_entry, dh_fault_entry,
    dh_fault_entry, dh_fault_entry, dh_fault_entry, dh_fault_entry,
    dh_fault_entry, dh_fault_entry, dh_fault_entry, dh_fault_entry,
    dh_fault_entry, dh_fault_entry, dh_fault_entry, dh_fault_entry,
};
