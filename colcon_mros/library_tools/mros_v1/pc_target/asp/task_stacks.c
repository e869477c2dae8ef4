/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The board's task stacks on the PC.
 *
 * On the arm target each task's code runs on a stack of exactly the size
 * its CRE_TSK gives, above a guard region: a task that would overrun its
 * stack on the board, where ASP has no guard and the overrun silently
 * corrupts what lies below, stops here with one line. What stands in for
 * the board's platform (the host's locks and sockets under the kernel and
 * lwIP stand-ins, the host C library) runs on the task thread's own host
 * stack instead, through pc_on_host_stack(): on the board those are ASP,
 * lwIP and newlib, whose costs the PC cannot know. Each stack is painted,
 * so that its peak use can be reported when the program is stopped
 * (SIGINT, SIGTERM) and on SIGUSR1.
 *
 * Elsewhere (the native target, with or without sanitizers) tasks keep the
 * 1 MiB host stacks of their threads and nothing here is measured.
 */
#define _GNU_SOURCE
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <ucontext.h>
#include <unistd.h>

#include "kernel.h"
#include "pc_target.h"

#if defined(__arm__)

/* What ASP 1.9.2's ARM port (arch/arm_gcc/common, GR-PEACH's) keeps on a
 * task's own stack beyond the task's frames, at most: an interrupt taken
 * in the task saves lr and spsr (srsdb) and r0-r3, ip, lr there before it
 * moves to the interrupt stack (32 bytes), and a dispatch on its way out
 * saves r4-r11 (32 bytes). A dispatch from a service call saves less
 * (r4-r11, lr: 36 bytes); the port saves no VFP registers, and nested
 * interrupts run on the interrupt stack. */
#define KERNEL_CONTEXT_BYTES 64
/* AAPCS: the stack pointer is 8-byte aligned at every call. */
#define STACK_ALIGNMENT 8
/* Large enough that a frame too big for the stack still lands in it. */
#define GUARD_BYTES (256 * 1024)
#define SIGNAL_STACK_BYTES (64 * 1024)
#define PAINT 0xa5

struct board_stack {
  const struct pc_task_config *config;
  unsigned char *guard; /* GUARD_BYTES, no access, right below low */
  unsigned char *low;   /* the stack is [low, top): the board's size */
  unsigned char *top;
  void *first_sp; /* below the kernel's context */
  int ran;
};

static struct board_stack *stacks;

/* The stack the calling thread's task runs on, and where its host calls
 * run: below what pc_call_on_stack keeps on the thread's host stack. */
static __thread struct board_stack *thread_stack;
static __thread void *host_sp;
static __thread int on_board_stack;

/* Calls function(argument) with the stack pointer at stack_top; when
 * left_sp is not NULL, stores there the stack pointer it left, below the
 * words it keeps to return. */
void pc_call_on_stack(void (*function)(void *), void *argument, void *stack_top, void **left_sp);
__asm__(".text\n"
        ".arm\n"
        ".align 2\n"
        ".global pc_call_on_stack\n"
        ".type pc_call_on_stack, %function\n"
        "pc_call_on_stack:\n"
        "  push {r4, lr}\n"
        "  mov r4, sp\n"
        "  cmp r3, #0\n"
        "  strne sp, [r3]\n"
        "  mov sp, r2\n"
        "  mov r2, r0\n"
        "  mov r0, r1\n"
        "  blx r2\n"
        "  mov sp, r4\n"
        "  pop {r4, pc}\n"
        ".size pc_call_on_stack, .-pc_call_on_stack\n");

static void stop(const char *what) {
  fprintf(stderr, "mROS PC target: %s\n", what);
  exit(70);
}

static void map_stack(struct board_stack *stack, const struct pc_task_config *config) {
  size_t page = (size_t)sysconf(_SC_PAGESIZE);
  size_t size = (config->stack_size + STACK_ALIGNMENT - 1) & ~(size_t)(STACK_ALIGNMENT - 1);
  size_t mapped = (size + page - 1) / page * page;
  unsigned char *region = mmap(NULL, GUARD_BYTES + mapped, PROT_NONE,
                               MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (region == MAP_FAILED || mprotect(region + GUARD_BYTES, mapped, PROT_READ | PROT_WRITE) != 0) {
    stop("cannot map the task stacks");
  }
  stack->config = config;
  stack->guard = region;
  stack->low = region + GUARD_BYTES;
  stack->top = stack->low + size;
  memset(stack->low, PAINT, size);
  stack->first_sp = size > KERNEL_CONTEXT_BYTES ? stack->top - KERNEL_CONTEXT_BYTES : stack->low;
}

static int in_guard(const struct board_stack *stack, uintptr_t address) {
  return address >= (uintptr_t)stack->guard && address < (uintptr_t)stack->low;
}

static size_t rounded(uintptr_t bytes) {
  return (size_t)((bytes + STACK_ALIGNMENT - 1) & ~(uintptr_t)(STACK_ALIGNMENT - 1));
}

/* A guard hit stops the program with one line; any other fault takes its
 * default action when the faulting instruction runs again. */
static void on_fault(int signal_number, siginfo_t *info, void *context) {
  const struct board_stack *stack = thread_stack;
  uintptr_t address = (uintptr_t)info->si_addr;
  uintptr_t sp = ((const ucontext_t *)context)->uc_mcontext.arm_sp;
  if (stack != NULL && (in_guard(stack, address) || in_guard(stack, sp))) {
    char line[512];
    uintptr_t deepest = address < sp && in_guard(stack, address) ? address : sp;
    int length = snprintf(line, sizeof line,
                          "mROS PC target: task %s overflowed its stack of %u bytes (%s); it needs "
                          "at least %u bytes\n",
                          stack->config->name, (unsigned)stack->config->stack_size,
                          stack->config->stack_origin,
                          (unsigned)rounded((uintptr_t)stack->top - deepest));
    if (write(STDERR_FILENO, line, (size_t)length) < 0) {
      /* Nowhere left to report it. */
    }
    _exit(70);
  }
  signal(signal_number, SIG_DFL);
}

void pc_task_stacks_init(void) {
  struct sigaction action;
  uint_t index;
  stacks = calloc(pc_task_count + 1, sizeof *stacks);
  if (stacks == NULL) stop("out of memory");
  for (index = 0; index < pc_task_count; index++) map_stack(&stacks[index], &pc_task_configs[index]);
  memset(&action, 0, sizeof action);
  action.sa_sigaction = on_fault;
  action.sa_flags = SA_SIGINFO | SA_ONSTACK;
  sigemptyset(&action.sa_mask);
  sigaction(SIGSEGV, &action, NULL);
}

void pc_task_thread_init(ID id) {
  stack_t signal_stack;
  signal_stack.ss_sp = malloc(SIGNAL_STACK_BYTES);
  signal_stack.ss_size = SIGNAL_STACK_BYTES;
  signal_stack.ss_flags = 0;
  if (signal_stack.ss_sp == NULL || sigaltstack(&signal_stack, NULL) != 0) {
    stop("cannot set up a signal stack");
  }
  thread_stack = &stacks[id - 1];
}

void pc_run_task(void (*body)(void *), void *argument) {
  thread_stack->ran = 1;
  on_board_stack = 1;
  pc_call_on_stack(body, argument, thread_stack->first_sp, &host_sp);
  on_board_stack = 0;
}

void pc_on_host_stack(void (*function)(void *), void *argument) {
  if (!on_board_stack) {
    function(argument);
    return;
  }
  on_board_stack = 0;
  pc_call_on_stack(function, argument, host_sp, NULL);
  on_board_stack = 1;
}

/* From the lowest byte that is no longer paint to the top; at least the
 * kernel's context, which an interrupt may save at any time. */
static size_t peak_use(const struct board_stack *stack) {
  const volatile unsigned char *byte = stack->low;
  size_t used;
  while (byte < stack->top && *byte == PAINT) byte++;
  used = (size_t)(stack->top - (const unsigned char *)byte);
  return used > KERNEL_CONTEXT_BYTES ? used : KERNEL_CONTEXT_BYTES;
}

void pc_report_stacks(void) {
  uint_t index;
  fprintf(stderr,
          "mROS PC target: task stacks, peak use of the board's size (ASP's context save of %d "
          "bytes included):\n",
          KERNEL_CONTEXT_BYTES);
  for (index = 0; index < pc_task_count; index++) {
    const struct board_stack *stack = &stacks[index];
    size_t size = (size_t)(stack->top - stack->low);
    if (!stack->ran) {
      fprintf(stderr, "  %-16s     - of %5u bytes  (never ran)\n", stack->config->name,
              (unsigned)size);
    } else {
      size_t peak = peak_use(stack);
      fprintf(stderr, "  %-16s %5u of %5u bytes  %3u%%\n", stack->config->name, (unsigned)peak,
              (unsigned)size, (unsigned)(size > 0 ? peak * 100u / size : 100u));
    }
  }
}

#else /* host stacks */

void pc_task_stacks_init(void) {}

void pc_task_thread_init(ID id) { (void)id; }

void pc_run_task(void (*body)(void *), void *argument) { body(argument); }

void pc_on_host_stack(void (*function)(void *), void *argument) { function(argument); }

void pc_report_stacks(void) {}

#endif
