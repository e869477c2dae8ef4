/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The ASP kernel stand-in's scheduling (kernel.c says how it keeps ASP's
 * rules): the lock that stands for ASP's interrupt masking, the ready
 * queues, dispatching, blocking and waking, and the hooks that let the lwIP
 * and mbed stand-ins give up the CPU around a host call or make a switch
 * point. The service calls are built from these (kernel_tasks.c,
 * kernel_semaphores.c, kernel_timers.c).
 */
#define _GNU_SOURCE
#include <pthread.h>
#include <stddef.h>
#include <stdint.h>

#include "kernel.h"
#include "kernel_internal.h"
#include "pc_target.h"

pthread_mutex_t kernel_lock = PTHREAD_MUTEX_INITIALIZER;
struct tcb *kernel_running;
struct task_queue kernel_ready[TMAX_TPRI + 1];
__thread struct tcb *kernel_current;

/* ---- the host's lock and condition variables, on the host stack ---- */

static void lock_on_host(void *unused) {
  (void)unused;
  pthread_mutex_lock(&kernel_lock);
}

static void unlock_on_host(void *unused) {
  (void)unused;
  pthread_mutex_unlock(&kernel_lock);
}

static void signal_on_host(void *condition) { pthread_cond_signal(condition); }

void kernel_enter(void) { pc_on_host_stack(lock_on_host, NULL); }

void kernel_unlock(void) { pc_on_host_stack(unlock_on_host, NULL); }

void kernel_signal_condition(pthread_cond_t *condition) {
  pc_on_host_stack(signal_on_host, condition);
}

/* ---- ready queues and dispatching (kernel_lock held) ---- */

void kernel_queue_add(struct task_queue *queue, struct tcb *task, int at_head) {
  task->next_in_queue = NULL;
  if (queue->first == NULL) {
    queue->first = queue->last = task;
  } else if (at_head) {
    task->next_in_queue = queue->first;
    queue->first = task;
  } else {
    queue->last->next_in_queue = task;
    queue->last = task;
  }
}

void kernel_queue_remove(struct task_queue *queue, struct tcb *task) {
  struct tcb **link = &queue->first;
  struct tcb *previous = NULL;
  while (*link != NULL && *link != task) {
    previous = *link;
    link = &(*link)->next_in_queue;
  }
  if (*link == NULL) return;
  *link = task->next_in_queue;
  if (queue->last == task) queue->last = previous;
  task->next_in_queue = NULL;
}

void kernel_make_ready(struct tcb *task, int at_head) {
  task->state = READY;
  kernel_queue_add(&kernel_ready[task->priority], task, at_head);
}

void kernel_remove_ready(struct tcb *task) {
  kernel_queue_remove(&kernel_ready[task->priority], task);
}

static struct tcb *highest_ready(void) {
  PRI priority;
  for (priority = HANDLER_PRIORITY; priority <= TMAX_TPRI; priority++) {
    if (kernel_ready[priority].first != NULL) return kernel_ready[priority].first;
  }
  return NULL;
}

/* Gives the free CPU to the highest priority ready task, if any. */
void kernel_schedule(void) {
  struct tcb *next = highest_ready();
  kernel_running = next;
  if (next != NULL) {
    kernel_remove_ready(next);
    next->state = RUNNING;
    kernel_signal_condition(&next->dispatched);
  }
}

static void wait_for_cpu_on_host(void *task) {
  struct tcb *self = task;
  while (kernel_running != self) pthread_cond_wait(&self->dispatched, &kernel_lock);
}

void kernel_wait_for_cpu(struct tcb *self) { pc_on_host_stack(wait_for_cpu_on_host, self); }

/* The caller gives up the CPU (it is already queued or waiting) and runs
 * again when it is dispatched. */
void kernel_switch_away(struct tcb *self) {
  kernel_running = NULL;
  kernel_schedule();
  kernel_wait_for_cpu(self);
}

/* A ready task, or the CPU being free, after an event outside any task. */
void kernel_wake(struct tcb *task) {
  kernel_make_ready(task, 0);
  if (kernel_running == NULL) kernel_schedule();
}

/* A switch point: a higher priority task that is ready runs first; the
 * caller keeps its place at the head of its priority. */
static void preempt_if_needed(struct tcb *self) {
  struct tcb *highest;
  if (self == NULL || kernel_running != self) return;
  highest = highest_ready();
  if (highest != NULL && highest->priority < self->priority) {
    kernel_make_ready(self, 1);
    kernel_switch_away(self);
  }
}

ER kernel_leave(ER result) {
  preempt_if_needed(kernel_current);
  kernel_unlock();
  return result;
}

/* Blocks the calling task until it is woken or the time-out passes. */
ER kernel_block(struct tcb *self, enum wait_reason reason, TMO timeout) {
  self->state = WAITING;
  self->wait = reason;
  self->wait_result = E_OK;
  self->has_deadline = timeout != TMO_FEVR;
  if (self->has_deadline) {
    self->deadline_us = pc_now_us() + (uint64_t)timeout * 1000u;
    kernel_signal_condition(&kernel_timer_wakeup);
  }
  kernel_switch_away(self);
  self->wait = WAIT_NONE;
  return self->wait_result;
}

void kernel_end_wait(struct tcb *task, ER result) {
  task->wait_result = result;
  task->has_deadline = 0;
  kernel_wake(task);
}

/* ---- the hooks of the lwIP and mbed stand-ins ---- */

void pc_host_call_begin(void) {
  struct tcb *self = kernel_current;
  if (self == NULL || self == &kernel_handler_tcb) return;
  kernel_enter();
  self->state = IN_HOST_CALL;
  kernel_running = NULL;
  kernel_schedule();
  kernel_unlock();
}

void pc_host_call_end(void) {
  struct tcb *self = kernel_current;
  if (self == NULL || self == &kernel_handler_tcb) return;
  kernel_enter();
  kernel_wake(self);
  kernel_wait_for_cpu(self);
  kernel_unlock();
}

void pc_dispatch_point(void) {
  kernel_enter();
  kernel_leave(E_OK);
}
