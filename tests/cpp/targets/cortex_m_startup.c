/* SPDX-License-Identifier: BSD-3-Clause */
/* Start-up code of the Cortex-M test programs: the vector table, zeroed
 * .bss, newlib's semihosting handles and static constructors, then main().
 * The linker scripts beside this file place .data in RAM directly (QEMU
 * loads it there), so nothing is copied from flash. A fault prints one line
 * and ends the run with status 99, so the host never waits for a hung CPU. */
#include <stdlib.h>
#include <unistd.h>

extern unsigned long __bss_start__[];
extern unsigned long __bss_end__[];
extern unsigned long __stack_top[];

extern void initialise_monitor_handles(void);
extern void __libc_init_array(void);
extern int main(void);

/* What crti.o and crtbegin.o would give (-nostartfiles): the hooks
 * __libc_init_array calls, and the handle libstdc++'s atexit calls name. */
void _init(void) {}
void _fini(void) {}
void* __dso_handle = 0;

void Reset_Handler(void) {
  unsigned long* word;
#if defined(__ARM_FP)
  /* Code built for the FPU (Cortex-M4F) needs it switched on first: full
   * access to coprocessors 10 and 11 in CPACR. */
  *(volatile unsigned long*)0xE000ED88 |= 0xFUL << 20;
  __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
  for (word = __bss_start__; word < __bss_end__; ++word) *word = 0;
  initialise_monitor_handles();
  __libc_init_array();
  exit(main());
}

void Fault_Handler(void) {
  static const char message[] = "FAULT: the CPU took an exception\n";
  write(2, message, sizeof message - 1);
  _exit(99);
}

typedef void (*Vector)(void);

/* Initial stack pointer, reset, then NMI, HardFault and the configurable
 * faults (MemManage, BusFault, UsageFault: Cortex-M3 and later). */
__attribute__((section(".vectors"), used)) static const Vector vectors[7] = {
    (Vector)__stack_top, Reset_Handler, Fault_Handler, Fault_Handler,
    Fault_Handler, Fault_Handler, Fault_Handler,
};
