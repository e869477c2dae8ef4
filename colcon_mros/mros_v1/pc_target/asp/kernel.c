/*
 * TOPPERS/ASP's task scheduling on POSIX threads, for running the unchanged
 * mROS v1 library and its apps on a PC.
 *
 * mROS v1's only mutual exclusion is raising a task's priority
 * (mros_exclusive_area.c), which is correct only under ASP's rules, so this
 * keeps them: every task is a thread, but exactly one holds the CPU
 * (`running`); the others wait on their own condition variable. The highest
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
 * syslog, ASP's system log service, is syslog.c's.
 *
 * A task's code runs on the board's stack size where task_stacks.c
 * provides it; the host's lock, condition variables and clock, which stand
 * for ASP's interrupt masking, run on the task thread's host stack
 * (pc_on_host_stack), so that only the kernel's own frames count there.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <limits.h>
#include <pthread.h>
#include <setjmp.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "kernel.h"
#include "pc_target.h"

/* The handler thread's place in the ready queues: above every task. */
#define HANDLER_PRIORITY 0
/* Host threads need far more stack than the cfg's few KiB for the board. */
#define TASK_THREAD_STACK (1024 * 1024)
#define MAX_TIMERS 64
#define MAX_RAISED 64

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

static pthread_mutex_t kernel_lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t timer_wakeup;
static struct tcb *running;
static struct task_queue ready[TMAX_TPRI + 1];
static struct tcb *tasks;
static struct tcb handler_tcb;
static struct semaphore *semaphores;
static int *cyclic_timers;
static struct timer timers[MAX_TIMERS];
static struct raised_interrupt raised[MAX_RAISED];
static unsigned raised_first, raised_count;
static struct timespec start_time;
static __thread struct tcb *current;

static pthread_once_t clock_started = PTHREAD_ONCE_INIT;

static void start_clock(void) { clock_gettime(CLOCK_MONOTONIC, &start_time); }

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

static void fatal(const char *what) {
  fprintf(stderr, "mROS PC target: %s\n", what);
  exit(70);
}

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

static void enter(void) { pc_on_host_stack(lock_on_host, NULL); }

static void unlock(void) { pc_on_host_stack(unlock_on_host, NULL); }

static void signal_condition(pthread_cond_t *condition) {
  pc_on_host_stack(signal_on_host, condition);
}

/* ---- ready queues and dispatching (kernel_lock held) ---- */

static void queue_add(struct task_queue *queue, struct tcb *task, int at_head) {
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

static void queue_remove(struct task_queue *queue, struct tcb *task) {
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

static void make_ready(struct tcb *task, int at_head) {
  task->state = READY;
  queue_add(&ready[task->priority], task, at_head);
}

static void remove_ready(struct tcb *task) { queue_remove(&ready[task->priority], task); }

static struct tcb *highest_ready(void) {
  PRI priority;
  for (priority = HANDLER_PRIORITY; priority <= TMAX_TPRI; priority++) {
    if (ready[priority].first != NULL) return ready[priority].first;
  }
  return NULL;
}

/* Gives the free CPU to the highest priority ready task, if any. */
static void schedule(void) {
  struct tcb *next = highest_ready();
  running = next;
  if (next != NULL) {
    remove_ready(next);
    next->state = RUNNING;
    signal_condition(&next->dispatched);
  }
}

static void wait_for_cpu_on_host(void *task) {
  struct tcb *self = task;
  while (running != self) pthread_cond_wait(&self->dispatched, &kernel_lock);
}

static void wait_for_cpu(struct tcb *self) { pc_on_host_stack(wait_for_cpu_on_host, self); }

/* The caller gives up the CPU (it is already queued or waiting) and runs
 * again when it is dispatched. */
static void switch_away(struct tcb *self) {
  running = NULL;
  schedule();
  wait_for_cpu(self);
}

/* A ready task, or the CPU being free, after an event outside any task. */
static void wake(struct tcb *task) {
  make_ready(task, 0);
  if (running == NULL) schedule();
}

/* A switch point: a higher priority task that is ready runs first; the
 * caller keeps its place at the head of its priority. */
static void preempt_if_needed(struct tcb *self) {
  struct tcb *highest;
  if (self == NULL || running != self) return;
  highest = highest_ready();
  if (highest != NULL && highest->priority < self->priority) {
    make_ready(self, 1);
    switch_away(self);
  }
}

static struct tcb *task_of(ID id) {
  if (id == TSK_SELF) return current != &handler_tcb ? current : NULL;
  if (id < 1 || (uint_t)id > pc_task_count) return NULL;
  return &tasks[id - 1];
}

static ER leave(ER result) {
  preempt_if_needed(current);
  unlock();
  return result;
}

/* Blocks the calling task until it is woken or the time-out passes. */
static ER block(struct tcb *self, enum wait_reason reason, TMO timeout) {
  self->state = WAITING;
  self->wait = reason;
  self->wait_result = E_OK;
  self->has_deadline = timeout != TMO_FEVR;
  if (self->has_deadline) {
    self->deadline_us = pc_now_us() + (uint64_t)timeout * 1000u;
    signal_condition(&timer_wakeup);
  }
  switch_away(self);
  self->wait = WAIT_NONE;
  return self->wait_result;
}

static void end_wait(struct tcb *task, ER result) {
  task->wait_result = result;
  task->has_deadline = 0;
  wake(task);
}

/* ---- tasks ---- */

static void finish_task(struct tcb *self) {
  self->state = DORMANT;
  self->priority = self->base_priority = self->config->priority;
  self->wakeup_requests = 0;
  if (self->activation_requests > 0) {
    self->activation_requests--;
    make_ready(self, 0);
  }
  switch_away(self);
}

static void run_task_code(void *task) {
  struct tcb *self = task;
  self->config->task(self->config->exinf);
}

static void *task_thread(void *argument) {
  struct tcb *self = argument;
  current = self;
  pc_task_thread_init(self->id);
  enter();
  for (;;) {
    wait_for_cpu(self);
    unlock();
    if (setjmp(self->exit_point) == 0) pc_run_task(run_task_code, self);
    enter();
    finish_task(self);
  }
  return NULL;
}

static ER activate(ID id) {
  struct tcb *task = task_of(id);
  if (task == NULL) return E_ID;
  if (task->state == DORMANT) {
    wake(task);
    return E_OK;
  }
  if (task->activation_requests >= TMAX_ACTCNT) return E_QOVR;
  task->activation_requests++;
  return E_OK;
}

ER act_tsk(ID tskid) {
  enter();
  return leave(activate(tskid));
}

ER iact_tsk(ID tskid) { return act_tsk(tskid); }

/* can_act and can_wup: the task's queued requests of one kind, cleared. */
static ER_UINT cancel_requests(ID tskid, int wakeups) {
  struct tcb *task;
  unsigned *requests;
  ER_UINT count;
  enter();
  task = task_of(tskid);
  if (task == NULL) return leave(E_ID);
  requests = wakeups ? &task->wakeup_requests : &task->activation_requests;
  count = (ER_UINT)*requests;
  *requests = 0;
  return leave(count);
}

ER_UINT can_act(ID tskid) { return cancel_requests(tskid, 0); }

/* ext_tsk ends the task's code wherever it calls it, as ASP's does: the
 * task's frames are left behind and its thread goes back to task_thread's
 * loop, to wait for the next activation. task_thread runs on the thread's
 * host stack and set exit_point there before it called pc_run_task, whose
 * call is still running: the jump goes up to a live frame of the same
 * thread, which longjmp allows. The task's code runs on its board stack
 * (task_stacks.c, arm target) or on the same host stack (native); either
 * way the jump is made from the host stack (pc_on_host_stack), right below
 * task_thread's frames, so no frame on the board stack is running when it
 * lands and the board stack is simply used afresh at the next activation.
 * Nothing is skipped that needs undoing: ext_tsk holds no lock (it is a
 * service call made outside enter()), and C frames have no destructors. */
static void exit_task(void *task) { longjmp(((struct tcb *)task)->exit_point, 1); }

ER ext_tsk(void) {
  struct tcb *self = current;
  if (self == NULL || self == &handler_tcb) return E_CTX;
  pc_on_host_stack(exit_task, self);
  return E_SYS; /* not reached */
}

ER get_tid(ID *p_tskid) {
  *p_tskid = (current != NULL && current != &handler_tcb) ? current->id : TSK_NONE;
  return E_OK;
}

ER iget_tid(ID *p_tskid) {
  enter();
  *p_tskid = (running != NULL && running != &handler_tcb) ? running->id : TSK_NONE;
  unlock();
  return E_OK;
}

ER get_pri(ID tskid, PRI *p_tskpri) {
  struct tcb *task;
  enter();
  task = task_of(tskid);
  if (task == NULL) return leave(E_ID);
  if (task->state == DORMANT) return leave(E_OBJ);
  *p_tskpri = task->priority;
  return leave(E_OK);
}

/* As in ASP, a task whose priority is set, even to the one it has, goes to
 * the tail of that priority's queue: same-priority tasks run first. */
ER chg_pri(ID tskid, PRI tskpri) {
  struct tcb *task;
  PRI priority;
  enter();
  task = task_of(tskid);
  if (task == NULL) return leave(E_ID);
  priority = tskpri == TPRI_INI ? task->config->priority : tskpri;
  if (priority < TMIN_TPRI || priority > TMAX_TPRI) return leave(E_PAR);
  if (task->state == DORMANT) return leave(E_OBJ);
  task->base_priority = priority;
  if (task->state == RUNNING) {
    task->priority = priority;
    make_ready(task, 0);
    switch_away(task);
  } else if (task->state == READY) {
    remove_ready(task);
    task->priority = priority;
    make_ready(task, 0);
  } else {
    task->priority = priority;
  }
  return leave(E_OK);
}

ER rot_rdq(PRI tskpri) {
  struct tcb *self = current;
  PRI priority;
  enter();
  priority = (tskpri == TPRI_SELF && self != NULL) ? self->priority : tskpri;
  if (priority < TMIN_TPRI || priority > TMAX_TPRI) return leave(E_PAR);
  if (self != NULL && running == self && self->priority == priority) {
    make_ready(self, 0);
    switch_away(self);
  } else if (ready[priority].first != ready[priority].last) {
    struct tcb *first = ready[priority].first;
    remove_ready(first);
    make_ready(first, 0);
  }
  return leave(E_OK);
}

static ER sleep_for(TMO timeout) {
  struct tcb *self = current;
  if (self == NULL || self == &handler_tcb) return E_CTX;
  enter();
  if (self->wakeup_requests > 0) {
    self->wakeup_requests--;
    return leave(E_OK);
  }
  if (timeout == TMO_POL) return leave(E_TMOUT);
  return leave(block(self, WAIT_SLEEP, timeout));
}

ER slp_tsk(void) { return sleep_for(TMO_FEVR); }

ER tslp_tsk(TMO tmout) { return sleep_for(tmout); }

ER wup_tsk(ID tskid) {
  struct tcb *task;
  enter();
  task = task_of(tskid);
  if (task == NULL) return leave(E_ID);
  if (task->state == DORMANT) return leave(E_OBJ);
  if (task->state == WAITING && task->wait == WAIT_SLEEP) {
    end_wait(task, E_OK);
    return leave(E_OK);
  }
  if (task->wakeup_requests >= TMAX_WUPCNT) return leave(E_QOVR);
  task->wakeup_requests++;
  return leave(E_OK);
}

ER iwup_tsk(ID tskid) { return wup_tsk(tskid); }

ER_UINT can_wup(ID tskid) { return cancel_requests(tskid, 1); }

ER dly_tsk(RELTIM dlytim) {
  struct tcb *self = current;
  if (self == NULL || self == &handler_tcb) return E_CTX;
  enter();
  block(self, WAIT_DELAY, (TMO)dlytim);
  return leave(E_OK);
}

/* ---- semaphores ---- */

static struct semaphore *semaphore_of(ID id) {
  if (id < 1 || (uint_t)id > pc_semaphore_count) return NULL;
  return &semaphores[id - 1];
}

ER sig_sem(ID semid) {
  struct semaphore *semaphore;
  enter();
  semaphore = semaphore_of(semid);
  if (semaphore == NULL) return leave(E_ID);
  if (semaphore->waiters.first != NULL) {
    struct tcb *task = semaphore->waiters.first;
    queue_remove(&semaphore->waiters, task);
    end_wait(task, E_OK);
    return leave(E_OK);
  }
  if (semaphore->count >= semaphore->config->max_count) return leave(E_QOVR);
  semaphore->count++;
  return leave(E_OK);
}

ER isig_sem(ID semid) { return sig_sem(semid); }

ER twai_sem(ID semid, TMO tmout) {
  struct tcb *self = current;
  struct semaphore *semaphore;
  ER result;
  if (self == NULL || self == &handler_tcb) return E_CTX;
  enter();
  semaphore = semaphore_of(semid);
  if (semaphore == NULL) return leave(E_ID);
  if (semaphore->count > 0) {
    semaphore->count--;
    return leave(E_OK);
  }
  if (tmout == TMO_POL) return leave(E_TMOUT);
  self->waiting_on = semaphore;
  queue_add(&semaphore->waiters, self, 0);
  result = block(self, WAIT_SEMAPHORE, tmout);
  self->waiting_on = NULL;
  return leave(result);
}

ER wai_sem(ID semid) { return twai_sem(semid, TMO_FEVR); }

ER pol_sem(ID semid) { return twai_sem(semid, TMO_POL); }

/* ---- time and interrupt-level code ---- */

ER get_tim(SYSTIM *p_systim) {
  *p_systim = (SYSTIM)(pc_now_us() / 1000u);
  return E_OK;
}

bool_t sns_ctx(void) { return current == &handler_tcb; }

static void request_handler_thread(void) {
  if (handler_tcb.state == WAITING) wake(&handler_tcb);
}

/* A timer's handle: its slot and how often the slot was taken, so that the
 * handle of a one-shot timer that fired (and gave its slot back) stops
 * nothing when another timer has the slot now. */
static int timer_handle(int timer) {
  return (int)(timers[timer].taken % (unsigned)(INT_MAX / MAX_TIMERS)) * MAX_TIMERS + timer;
}

int pc_timer_start(pc_handler handler, void *arg, uint64_t first_us, uint64_t period_us) {
  int timer;
  enter();
  for (timer = 0; timer < MAX_TIMERS; timer++) {
    if (!timers[timer].in_use) break;
  }
  if (timer == MAX_TIMERS) {
    unlock();
    return -1;
  }
  timers[timer].in_use = 1;
  timers[timer].taken++;
  timers[timer].handler = handler;
  timers[timer].arg = arg;
  timers[timer].deadline_us = pc_now_us() + first_us;
  timers[timer].period_us = period_us;
  timers[timer].pending = 0;
  signal_condition(&timer_wakeup);
  unlock();
  return timer_handle(timer);
}

void pc_timer_stop(int handle) {
  int timer = handle % MAX_TIMERS;
  if (handle < 0) return;
  enter();
  if (timers[timer].in_use && timer_handle(timer) == handle) {
    timers[timer].in_use = 0;
    timers[timer].pending = 0;
  }
  unlock();
}

void pc_raise_interrupt(pc_handler handler, void *arg) {
  enter();
  if (raised_count < MAX_RAISED) {
    struct raised_interrupt *slot = &raised[(raised_first + raised_count) % MAX_RAISED];
    slot->handler = handler;
    slot->arg = arg;
    raised_count++;
    request_handler_thread();
  }
  leave(E_OK);
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

static void *handler_thread(void *unused) {
  struct raised_interrupt call;
  (void)unused;
  current = &handler_tcb;
  enter();
  for (;;) {
    wait_for_cpu(&handler_tcb);
    while (take_pending(&call)) {
      unlock();
      call.handler(call.arg);
      enter();
    }
    handler_tcb.state = WAITING;
    running = NULL;
    schedule();
  }
  return NULL;
}

static void *timer_thread(void *unused) {
  (void)unused;
  enter();
  for (;;) {
    uint64_t now = pc_now_us();
    uint64_t next = now + 1000000u;
    uint_t index;
    int timer;
    struct timespec until;
    for (index = 0; index < pc_task_count; index++) {
      struct tcb *task = &tasks[index];
      if (task->state != WAITING || !task->has_deadline) continue;
      if (task->deadline_us <= now) {
        if (task->waiting_on != NULL) queue_remove(&task->waiting_on->waiters, task);
        end_wait(task, task->wait == WAIT_DELAY ? E_OK : E_TMOUT);
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
    if (running == NULL) schedule();
    until.tv_sec = start_time.tv_sec + (time_t)(next / 1000000u);
    until.tv_nsec = start_time.tv_nsec + (long)(next % 1000000u) * 1000;
    if (until.tv_nsec >= 1000000000L) {
      until.tv_sec++;
      until.tv_nsec -= 1000000000L;
    }
    pthread_cond_timedwait(&timer_wakeup, &kernel_lock, &until);
  }
  return NULL;
}

static void cyclic_handler_call(void *arg) {
  const struct pc_cyclic_config *config = arg;
  config->handler(config->exinf);
}

static ER start_cyclic(uint_t index) {
  const struct pc_cyclic_config *config = &pc_cyclic_configs[index];
  uint64_t period_us = (uint64_t)config->period * 1000u;
  uint64_t first_us = config->phase > 0 ? (uint64_t)config->phase * 1000u : period_us;
  if (cyclic_timers[index] >= 0) return E_OK;
  cyclic_timers[index] = pc_timer_start(cyclic_handler_call, (void *)config, first_us, period_us);
  return cyclic_timers[index] >= 0 ? E_OK : E_NOSPT;
}

ER sta_cyc(ID cycid) {
  if (cycid < 1 || (uint_t)cycid > pc_cyclic_count) return E_ID;
  return start_cyclic((uint_t)cycid - 1);
}

ER stp_cyc(ID cycid) {
  if (cycid < 1 || (uint_t)cycid > pc_cyclic_count) return E_ID;
  pc_timer_stop(cyclic_timers[cycid - 1]);
  cyclic_timers[cycid - 1] = -1;
  return E_OK;
}

/* ---- the hooks of the lwIP and mbed stand-ins ---- */

void pc_host_call_begin(void) {
  struct tcb *self = current;
  if (self == NULL || self == &handler_tcb) return;
  enter();
  self->state = IN_HOST_CALL;
  running = NULL;
  schedule();
  unlock();
}

void pc_host_call_end(void) {
  struct tcb *self = current;
  if (self == NULL || self == &handler_tcb) return;
  enter();
  wake(self);
  wait_for_cpu(self);
  unlock();
}

void pc_dispatch_point(void) {
  enter();
  leave(E_OK);
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
  pthread_once(&clock_started, start_clock);
  init_cond(&timer_wakeup, 1);

  tasks = calloc(pc_task_count + 1, sizeof *tasks);
  semaphores = calloc(pc_semaphore_count + 1, sizeof *semaphores);
  cyclic_timers = calloc(pc_cyclic_count + 1, sizeof *cyclic_timers);
  if (tasks == NULL || semaphores == NULL || cyclic_timers == NULL) fatal("out of memory");
  for (index = 0; index < pc_task_count; index++) {
    struct tcb *task = &tasks[index];
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
  handler_tcb.priority = handler_tcb.base_priority = HANDLER_PRIORITY;
  handler_tcb.state = WAITING;
  init_cond(&handler_tcb.dispatched, 0);
  for (index = 0; index < pc_semaphore_count; index++) {
    semaphores[index].config = &pc_semaphore_configs[index];
    semaphores[index].count = pc_semaphore_configs[index].initial_count;
  }
  for (index = 0; index < pc_cyclic_count; index++) cyclic_timers[index] = -1;
  pc_task_stacks_init();

  for (index = 0; index < pc_initializer_count; index++) {
    pc_initializer_configs[index].routine(pc_initializer_configs[index].exinf);
  }
  for (index = 0; index < pc_task_count; index++) start_thread(task_thread, &tasks[index]);
  start_thread(handler_thread, NULL);
  start_thread(timer_thread, NULL);
  for (index = 0; index < pc_cyclic_count; index++) {
    if (pc_cyclic_configs[index].attr & TA_STA) start_cyclic(index);
  }
  enter();
  for (index = 0; index < pc_task_count; index++) {
    if (tasks[index].config->attr & TA_ACT) make_ready(&tasks[index], 0);
  }
  schedule();
  unlock();
  serve_signals();
  return 0;
}
