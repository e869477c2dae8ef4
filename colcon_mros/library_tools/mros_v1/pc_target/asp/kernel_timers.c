/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The ASP kernel stand-in's time and interrupt-level code: the clock
 * (get_tim), timers (pc_timer_start, pc_timer_stop) and raised interrupts
 * (pc_raise_interrupt) for the mbed stand-in, cyclic handlers (sta_cyc,
 * stp_cyc), the handler thread, which runs them one at a time above every
 * task, and the timer thread, which turns time-outs and timer expiries into
 * ready tasks and pending handlers.
 */
#define _GNU_SOURCE
#include <limits.h>
#include <pthread.h>
#include <stddef.h>
#include <stdint.h>
#include <time.h>

#include "kernel.h"
#include "kernel_internal.h"
#include "pc_target.h"

#define MAX_TIMERS 64
#define MAX_RAISED 64

struct timer {
  int in_use;
  unsigned taken; /* how often the slot was taken: its handles tell them apart */
  pc_handler handler;
  void *arg;
  uint64_t deadline_us;
  uint64_t period_us;
  int pending;
};

struct raised_interrupt {
  pc_handler handler;
  void *arg;
};

struct tcb kernel_handler_tcb;
pthread_cond_t kernel_timer_wakeup;
int *kernel_cyclic_timers;
static struct timer timers[MAX_TIMERS];
static struct raised_interrupt raised[MAX_RAISED];
static unsigned raised_first, raised_count;
static struct timespec start_time;

/* ---- the clock ---- */

static pthread_once_t clock_started = PTHREAD_ONCE_INIT;

static void start_clock(void) { clock_gettime(CLOCK_MONOTONIC, &start_time); }

void kernel_start_clock(void) { pthread_once(&clock_started, start_clock); }

static void read_clock(void *now) {
  pthread_once(&clock_started, start_clock);
  clock_gettime(CLOCK_MONOTONIC, now);
}

/* Also right for a ticker an app starts from a static constructor, before
 * main(). */
uint64_t pc_now_us(void) {
  struct timespec now;
  pc_on_host_stack(read_clock, &now);
  return (uint64_t)(now.tv_sec - start_time.tv_sec) * 1000000u +
         (uint64_t)((now.tv_nsec - start_time.tv_nsec) / 1000);
}

/* ---- interrupt-level code ---- */

ER get_tim(SYSTIM *p_systim) {
  *p_systim = (SYSTIM)(pc_now_us() / 1000u);
  return E_OK;
}

bool_t sns_ctx(void) { return kernel_current == &kernel_handler_tcb; }

static void request_handler_thread(void) {
  if (kernel_handler_tcb.state == WAITING) kernel_wake(&kernel_handler_tcb);
}

/* A timer's handle: its slot and how often the slot was taken, so that the
 * handle of a one-shot timer that fired (and gave its slot back) stops
 * nothing when another timer has the slot now. */
static int timer_handle(int timer) {
  return (int)(timers[timer].taken % (unsigned)(INT_MAX / MAX_TIMERS)) * MAX_TIMERS + timer;
}

int pc_timer_start(pc_handler handler, void *arg, uint64_t first_us, uint64_t period_us) {
  int timer;
  kernel_enter();
  for (timer = 0; timer < MAX_TIMERS; timer++) {
    if (!timers[timer].in_use) break;
  }
  if (timer == MAX_TIMERS) {
    kernel_unlock();
    return -1;
  }
  timers[timer].in_use = 1;
  timers[timer].taken++;
  timers[timer].handler = handler;
  timers[timer].arg = arg;
  timers[timer].deadline_us = pc_now_us() + first_us;
  timers[timer].period_us = period_us;
  timers[timer].pending = 0;
  kernel_signal_condition(&kernel_timer_wakeup);
  kernel_unlock();
  return timer_handle(timer);
}

void pc_timer_stop(int handle) {
  int timer = handle % MAX_TIMERS;
  if (handle < 0) return;
  kernel_enter();
  if (timers[timer].in_use && timer_handle(timer) == handle) {
    timers[timer].in_use = 0;
    timers[timer].pending = 0;
  }
  kernel_unlock();
}

void pc_raise_interrupt(pc_handler handler, void *arg) {
  kernel_enter();
  if (raised_count < MAX_RAISED) {
    struct raised_interrupt *slot = &raised[(raised_first + raised_count) % MAX_RAISED];
    slot->handler = handler;
    slot->arg = arg;
    raised_count++;
    request_handler_thread();
  }
  kernel_leave(E_OK);
}

/* The next pending handler, or 0 when none is (kernel_lock held). */
static int take_pending(struct raised_interrupt *call) {
  int timer;
  if (raised_count > 0) {
    *call = raised[raised_first];
    raised_first = (raised_first + 1) % MAX_RAISED;
    raised_count--;
    return 1;
  }
  for (timer = 0; timer < MAX_TIMERS; timer++) {
    if (timers[timer].in_use && timers[timer].pending) {
      timers[timer].pending = 0;
      call->handler = timers[timer].handler;
      call->arg = timers[timer].arg;
      if (timers[timer].period_us == 0) timers[timer].in_use = 0;
      return 1;
    }
  }
  return 0;
}

void *kernel_handler_thread(void *unused) {
  struct raised_interrupt call;
  (void)unused;
  kernel_current = &kernel_handler_tcb;
  kernel_enter();
  for (;;) {
    kernel_wait_for_cpu(&kernel_handler_tcb);
    while (take_pending(&call)) {
      kernel_unlock();
      call.handler(call.arg);
      kernel_enter();
    }
    kernel_handler_tcb.state = WAITING;
    kernel_running = NULL;
    kernel_schedule();
  }
  return NULL;
}

void *kernel_timer_thread(void *unused) {
  (void)unused;
  kernel_enter();
  for (;;) {
    uint64_t now = pc_now_us();
    uint64_t next = now + 1000000u;
    uint_t index;
    int timer;
    struct timespec until;
    for (index = 0; index < pc_task_count; index++) {
      struct tcb *task = &kernel_tasks[index];
      if (task->state != WAITING || !task->has_deadline) continue;
      if (task->deadline_us <= now) {
        if (task->waiting_on != NULL) kernel_queue_remove(&task->waiting_on->waiters, task);
        kernel_end_wait(task, task->wait == WAIT_DELAY ? E_OK : E_TMOUT);
      } else if (task->deadline_us < next) {
        next = task->deadline_us;
      }
    }
    for (timer = 0; timer < MAX_TIMERS; timer++) {
      struct timer *t = &timers[timer];
      if (!t->in_use) continue;
      if (t->deadline_us <= now) {
        /* A tick that falls due while the last one is still pending is
         * lost, as an interrupt that is already requested is. */
        if (!t->pending) {
          t->pending = 1;
          request_handler_thread();
        }
        if (t->period_us == 0) continue;
        t->deadline_us += t->period_us;
        if (t->deadline_us <= now) t->deadline_us = now + t->period_us;
      }
      if (t->deadline_us < next) next = t->deadline_us;
    }
    if (kernel_running == NULL) kernel_schedule();
    until.tv_sec = start_time.tv_sec + (time_t)(next / 1000000u);
    until.tv_nsec = start_time.tv_nsec + (long)(next % 1000000u) * 1000;
    if (until.tv_nsec >= 1000000000L) {
      until.tv_sec++;
      until.tv_nsec -= 1000000000L;
    }
    pthread_cond_timedwait(&kernel_timer_wakeup, &kernel_lock, &until);
  }
  return NULL;
}

static void cyclic_handler_call(void *arg) {
  const struct pc_cyclic_config *config = arg;
  config->handler(config->exinf);
}

ER kernel_start_cyclic(uint_t index) {
  const struct pc_cyclic_config *config = &pc_cyclic_configs[index];
  uint64_t period_us = (uint64_t)config->period * 1000u;
  uint64_t first_us = config->phase > 0 ? (uint64_t)config->phase * 1000u : period_us;
  if (kernel_cyclic_timers[index] >= 0) return E_OK;
  kernel_cyclic_timers[index] =
      pc_timer_start(cyclic_handler_call, (void *)config, first_us, period_us);
  return kernel_cyclic_timers[index] >= 0 ? E_OK : E_NOSPT;
}

ER sta_cyc(ID cycid) {
  if (cycid < 1 || (uint_t)cycid > pc_cyclic_count) return E_ID;
  return kernel_start_cyclic((uint_t)cycid - 1);
}

ER stp_cyc(ID cycid) {
  if (cycid < 1 || (uint_t)cycid > pc_cyclic_count) return E_ID;
  pc_timer_stop(kernel_cyclic_timers[cycid - 1]);
  kernel_cyclic_timers[cycid - 1] = -1;
  return E_OK;
}
