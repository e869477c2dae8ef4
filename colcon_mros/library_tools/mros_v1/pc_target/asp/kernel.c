/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * TOPPERS/ASP's task scheduling on POSIX threads, for running the unchanged
 * mROS v1 library and its apps on a PC.
 *
 * mROS v1's only mutual exclusion is raising a task's priority
 * (mros_exclusive_area.c), which is correct only under ASP's rules, so this
 * keeps them: every task is a thread, but exactly one holds the CPU
 * (`kernel_running`); the others wait on their own condition variable. The highest
 * priority ready task runs, FIFO within a priority; a task that is preempted
 * keeps its place at the head of its queue, one that wakes up or changes its
 * priority goes to the tail. A switch happens only inside a service call (or
 * a call into the lwIP and mbed stand-ins, see pc_target.h): as on the
 * board, a task that spins without calling the kernel starves every task of
 * lower or equal priority. Activation and wake-up requests queue up to 1.
 *
 * Interrupt-level code (cyclic handlers, mbed's Ticker and InterruptIn) runs
 * in one handler thread that holds the CPU above every task, one handler at a
 * time; a handler that falls due while a task runs is taken at that task's
 * next service call. One timer thread turns time-outs and timer expiries into
 * ready tasks and pending handlers.
 *
 * Where each part is: this file starts the kernel, as ASP's does before the
 * first task runs (the tables of kernel_cfg.c, the threads, the signals);
 * kernel_scheduler.c holds the lock, the ready queues, switching, blocking
 * and waking, and the lwIP and mbed stand-ins' hooks; kernel_tasks.c the
 * task threads and the task services; kernel_semaphores.c the semaphores;
 * kernel_timers.c the clock, timers, raised interrupts, cyclic handlers
 * and the handler and timer threads. What they share is
 * kernel_internal.h's. syslog, ASP's system log service, is syslog.c's.
 *
 * A task's code runs on the board's stack size where task_stacks.c
 * provides it; the host's lock, condition variables and clock, which stand
 * for ASP's interrupt masking, run on the task thread's host stack
 * (pc_on_host_stack), so that only the kernel's own frames count there.
 */
#define _GNU_SOURCE
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "kernel.h"
#include "kernel_internal.h"
#include "pc_target.h"

/* Host threads need far more stack than the cfg's few KiB for the board. */
#define TASK_THREAD_STACK (1024 * 1024)

static void fatal(const char *what) {
  fprintf(stderr, "mROS PC target: %s\n", what);
  exit(70);
}

/* ---- start-up: what ASP's kernel does before the first task runs ---- */

static void start_thread(void *(*body)(void *), void *argument) {
  pthread_t thread;
  pthread_attr_t attributes;
  pthread_attr_init(&attributes);
  pthread_attr_setstacksize(&attributes, TASK_THREAD_STACK);
  pthread_attr_setdetachstate(&attributes, PTHREAD_CREATE_DETACHED);
  if (pthread_create(&thread, &attributes, body, argument) != 0) fatal("cannot start a thread");
  pthread_attr_destroy(&attributes);
}

static void init_cond(pthread_cond_t *cond, int monotonic) {
  pthread_condattr_t attributes;
  pthread_condattr_init(&attributes);
  if (monotonic) pthread_condattr_setclock(&attributes, CLOCK_MONOTONIC);
  pthread_cond_init(cond, &attributes);
  pthread_condattr_destroy(&attributes);
}

/* The main thread takes SIGINT, SIGTERM and SIGUSR1 for the whole program
 * (every other thread blocks them): SIGUSR1 reports the task stacks, the
 * others, which end a node, report them and end the program as they would
 * have. A program that stops itself (exit) has said why in its own line. */
static void served_signals(sigset_t *signals) {
  sigemptyset(signals);
  sigaddset(signals, SIGINT);
  sigaddset(signals, SIGTERM);
  sigaddset(signals, SIGUSR1);
}

static void serve_signals(void) {
  sigset_t signals;
  int received;
  served_signals(&signals);
  for (;;) {
    if (sigwait(&signals, &received) != 0) continue;
    if (received == SIGUSR1) {
      pc_report_stacks();
      continue;
    }
    pc_report_stacks();
    signal(received, SIG_DFL);
    pthread_sigmask(SIG_UNBLOCK, &signals, NULL);
    raise(received);
  }
}

int main(void) {
  uint_t index;
  sigset_t served;
  signal(SIGPIPE, SIG_IGN);
  served_signals(&served);
  pthread_sigmask(SIG_BLOCK, &served, NULL);
  kernel_start_clock();
  init_cond(&kernel_timer_wakeup, 1);

  kernel_tasks = calloc(pc_task_count + 1, sizeof *kernel_tasks);
  kernel_semaphores = calloc(pc_semaphore_count + 1, sizeof *kernel_semaphores);
  kernel_cyclic_timers = calloc(pc_cyclic_count + 1, sizeof *kernel_cyclic_timers);
  if (kernel_tasks == NULL || kernel_semaphores == NULL || kernel_cyclic_timers == NULL) {
    fatal("out of memory");
  }
  for (index = 0; index < pc_task_count; index++) {
    struct tcb *task = &kernel_tasks[index];
    task->id = (ID)index + 1;
    task->config = &pc_task_configs[index];
    task->priority = task->base_priority = task->config->priority;
    if (task->priority < TMIN_TPRI || task->priority > TMAX_TPRI) {
      fprintf(stderr, "mROS PC target: task %s: priority %d is outside %d..%d\n",
              task->config->name, task->priority, TMIN_TPRI, TMAX_TPRI);
      return 70;
    }
    task->state = DORMANT;
    init_cond(&task->dispatched, 0);
  }
  kernel_handler_tcb.priority = kernel_handler_tcb.base_priority = HANDLER_PRIORITY;
  kernel_handler_tcb.state = WAITING;
  init_cond(&kernel_handler_tcb.dispatched, 0);
  for (index = 0; index < pc_semaphore_count; index++) {
    kernel_semaphores[index].config = &pc_semaphore_configs[index];
    kernel_semaphores[index].count = pc_semaphore_configs[index].initial_count;
  }
  for (index = 0; index < pc_cyclic_count; index++) kernel_cyclic_timers[index] = -1;
  pc_task_stacks_init();

  for (index = 0; index < pc_initializer_count; index++) {
    pc_initializer_configs[index].routine(pc_initializer_configs[index].exinf);
  }
  for (index = 0; index < pc_task_count; index++) {
    start_thread(kernel_task_thread, &kernel_tasks[index]);
  }
  start_thread(kernel_handler_thread, NULL);
  start_thread(kernel_timer_thread, NULL);
  for (index = 0; index < pc_cyclic_count; index++) {
    if (pc_cyclic_configs[index].attr & TA_STA) kernel_start_cyclic(index);
  }
  kernel_enter();
  for (index = 0; index < pc_task_count; index++) {
    if (kernel_tasks[index].config->attr & TA_ACT) kernel_make_ready(&kernel_tasks[index], 0);
  }
  kernel_schedule();
  kernel_unlock();
  serve_signals();
  return 0;
}
