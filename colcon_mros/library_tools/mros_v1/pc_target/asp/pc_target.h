/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * What the PC target's parts share beyond ASP's own API: the kernel object
 * tables the configurator writes from app.cfg (kernel_cfg.c), and the hooks
 * the lwIP and mbed stand-ins use to keep ASP's scheduling when they block in
 * the host OS or raise an interrupt.
 */
#ifndef MROS_PC_TARGET_H
#define MROS_PC_TARGET_H

#include <stddef.h>
#include <stdint.h>

#include "kernel.h"

#ifdef __cplusplus
extern "C" {
#endif

/* CRE_TSK(ID, { attr, exinf, task, priority, stack size, stack }) */
struct pc_task_config {
  const char *name;
  ATR attr;
  intptr_t exinf;
  TASK task;
  PRI priority;
  size_t stack_size;
  const char *stack_origin; /* where stack_size is set: "MACRO at FILE:LINE; CRE_TSK at FILE:LINE" */
};

/* CRE_SEM(ID, { attr, initial count, maximum count }) */
struct pc_semaphore_config {
  const char *name;
  ATR attr;
  uint_t initial_count;
  uint_t max_count;
};

/* CRE_CYC(ID, { attr, exinf, handler, period, phase }) */
struct pc_cyclic_config {
  const char *name;
  ATR attr;
  intptr_t exinf;
  CYCHDR handler;
  RELTIM period;
  RELTIM phase;
};

/* ATT_INI({ attr, exinf, routine }) */
struct pc_initializer_config {
  ATR attr;
  intptr_t exinf;
  INIRTN routine;
};

/* Written by the configurator; each array ends with an all-zero entry. */
extern const struct pc_task_config pc_task_configs[];
extern const uint_t pc_task_count;
extern const struct pc_semaphore_config pc_semaphore_configs[];
extern const uint_t pc_semaphore_count;
extern const struct pc_cyclic_config pc_cyclic_configs[];
extern const uint_t pc_cyclic_count;
extern const struct pc_initializer_config pc_initializer_configs[];
extern const uint_t pc_initializer_count;

/* A task that is about to block in the host OS (a socket call) gives up
 * the CPU, as an ASP task blocked in lwIP does, and takes it back in
 * priority order when the call returns. */
void pc_host_call_begin(void);
void pc_host_call_end(void);

/* A point where ASP could switch: a task of higher priority that became
 * ready, or a pending handler, runs first. Every service call is one; the
 * stand-ins call it from their own calls (mbed's DigitalIn::read, say). */
void pc_dispatch_point(void);

/* Interrupt-level code: handlers run one at a time, above every task. */
typedef void (*pc_handler)(void *arg);
/* Calls handler every period_us (0: once) from first_us from now; returns
 * the timer's handle for pc_timer_stop, or -1 when every timer is in use. A
 * one-shot timer is gone once it fired: its handle then stops nothing. */
int pc_timer_start(pc_handler handler, void *arg, uint64_t first_us, uint64_t period_us);
void pc_timer_stop(int handle);
/* Calls handler once, at interrupt level, as soon as the CPU allows. */
void pc_raise_interrupt(pc_handler handler, void *arg);

/* Microseconds on a monotonic clock since start-up. */
uint64_t pc_now_us(void);

/* The board's task stacks (task_stacks.c). On the arm target each task runs
 * on a stack of its CRE_TSK size above a guard, and the host's own work
 * (locks, sockets, the C library) runs on the task thread's host stack;
 * elsewhere tasks keep their threads' host stacks and these are plain calls.
 * pc_task_stacks_init maps the stacks (before any task thread starts),
 * pc_task_thread_init sets up the calling thread as task id's, and
 * pc_run_task runs its code on its stack. */
void pc_task_stacks_init(void);
void pc_task_thread_init(ID id);
void pc_run_task(void (*body)(void *), void *argument);
/* Calls function(argument) on the calling task thread's host stack. */
void pc_on_host_stack(void (*function)(void *), void *argument);
/* Each task's peak stack use against its size, to stderr. */
void pc_report_stacks(void);

#ifdef __cplusplus
}
#endif

#endif /* MROS_PC_TARGET_H */
