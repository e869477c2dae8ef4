/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * What the files of the ASP kernel's stand-in share with each other, and
 * nothing else does: the task control block, the ready queues and the rest
 * of the kernel's state, and the scheduling steps every service call is made
 * of. It is not part of ASP's API (kernel.h) nor of what the stand-ins share
 * (pc_target.h): only kernel.c, kernel_scheduler.c, kernel_tasks.c,
 * kernel_semaphores.c and kernel_timers.c include it. Everything declared
 * here is named kernel_..., so that none of it meets a name of the app's or
 * the library's in the link.
 *
 * Unless a comment says otherwise, the functions here are called, and the
 * state is read and written, with kernel_lock held (between kernel_enter and
 * kernel_unlock or kernel_leave).
 */
#ifndef MROS_PC_TARGET_KERNEL_INTERNAL_H
#define MROS_PC_TARGET_KERNEL_INTERNAL_H

#include <pthread.h>
#include <setjmp.h>
#include <stdint.h>

#include "kernel.h"
#include "pc_target.h"

/* The handler thread's place in the ready queues: above every task. */
#define HANDLER_PRIORITY 0

enum task_state { DORMANT, READY, RUNNING, WAITING, IN_HOST_CALL };
enum wait_reason { WAIT_NONE, WAIT_SLEEP, WAIT_DELAY, WAIT_SEMAPHORE };

struct tcb {
  ID id;
  const struct pc_task_config *config;
  PRI base_priority;
  PRI priority;
  enum task_state state;
  unsigned activation_requests;
  unsigned wakeup_requests;
  struct tcb *next_in_queue; /* a ready queue or a semaphore's waiters, never both */
  pthread_cond_t dispatched;
  jmp_buf exit_point;
  enum wait_reason wait;
  struct semaphore *waiting_on;
  int has_deadline;
  uint64_t deadline_us;
  ER wait_result;
};

/* Tasks in FIFO order, linked through next_in_queue. */
struct task_queue {
  struct tcb *first;
  struct tcb *last;
};

struct semaphore {
  const struct pc_semaphore_config *config;
  uint_t count;
  struct task_queue waiters;
};

/* ---- the kernel's state ---- */

/* kernel_scheduler.c: the lock that stands for ASP's interrupt masking,
 * the task that holds the CPU (NULL: the CPU is free) and the ready queues,
 * one per priority. */
extern pthread_mutex_t kernel_lock;
extern struct tcb *kernel_running;
extern struct task_queue kernel_ready[TMAX_TPRI + 1];
/* The calling thread's task, or kernel_handler_tcb in the handler thread;
 * NULL in threads that are neither (main, the timer thread, the host's). */
extern __thread struct tcb *kernel_current;

/* kernel_tasks.c: the cfg's tasks (ID - 1). */
extern struct tcb *kernel_tasks;

/* kernel_semaphores.c: the cfg's semaphores (ID - 1). */
extern struct semaphore *kernel_semaphores;

/* kernel_timers.c: the handler thread's place among the tasks (it runs
 * interrupt-level code above them), what wakes the timer thread when a
 * deadline comes nearer, and each cyclic handler's timer handle (-1:
 * stopped; set without kernel_lock, by start-up, sta_cyc and stp_cyc). */
extern struct tcb kernel_handler_tcb;
extern pthread_cond_t kernel_timer_wakeup;
extern int *kernel_cyclic_timers;

/* ---- kernel_scheduler.c: the lock, the ready queues, switching ---- */

/* Take and give back kernel_lock (on the host stack); kernel_enter and
 * kernel_unlock are called without it, and kernel_signal_condition with it. */
void kernel_enter(void);
void kernel_unlock(void);
void kernel_signal_condition(pthread_cond_t *condition);

void kernel_queue_add(struct task_queue *queue, struct tcb *task, int at_head);
void kernel_queue_remove(struct task_queue *queue, struct tcb *task);
void kernel_make_ready(struct tcb *task, int at_head);
void kernel_remove_ready(struct tcb *task);
/* Gives the free CPU to the highest priority ready task, if any. */
void kernel_schedule(void);
/* Returns when self holds the CPU. */
void kernel_wait_for_cpu(struct tcb *self);
/* The caller gives up the CPU (it is already queued or waiting) and runs
 * again when it is dispatched. */
void kernel_switch_away(struct tcb *self);
/* A ready task, or the CPU being free, after an event outside any task. */
void kernel_wake(struct tcb *task);
/* The end of a service call: a switch point, then kernel_lock is given
 * back; returns result. */
ER kernel_leave(ER result);
/* Blocks the calling task until it is woken or the time-out passes. */
ER kernel_block(struct tcb *self, enum wait_reason reason, TMO timeout);
/* Wakes a waiting task, whose kernel_block returns result. */
void kernel_end_wait(struct tcb *task, ER result);

/* ---- the threads and what start-up calls (kernel.c's main) ---- */

/* The threads' bodies, which main starts. kernel_tasks.c: the thread of
 * the task it is given. */
void *kernel_task_thread(void *argument);
/* kernel_timers.c: the handler thread, the timer thread, and the start of
 * the clock and of a cyclic handler (both called without kernel_lock). */
void *kernel_handler_thread(void *unused);
void *kernel_timer_thread(void *unused);
void kernel_start_clock(void);
ER kernel_start_cyclic(uint_t index);

#endif /* MROS_PC_TARGET_KERNEL_INTERNAL_H */
