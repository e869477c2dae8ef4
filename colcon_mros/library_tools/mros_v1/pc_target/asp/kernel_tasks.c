/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The ASP kernel stand-in's tasks: each task's thread, which runs the
 * task's code once per activation, and the task services (act_tsk, ext_tsk,
 * get_tid, get_pri, chg_pri, rot_rdq, slp_tsk, wup_tsk, dly_tsk and their
 * variants), built from kernel_scheduler.c's steps.
 */
#define _GNU_SOURCE
#include <setjmp.h>
#include <stddef.h>

#include "kernel.h"
#include "kernel_internal.h"
#include "pc_target.h"

struct tcb *kernel_tasks;

static struct tcb *task_of(ID id) {
  if (id == TSK_SELF) return kernel_current != &kernel_handler_tcb ? kernel_current : NULL;
  if (id < 1 || (uint_t)id > pc_task_count) return NULL;
  return &kernel_tasks[id - 1];
}

static void finish_task(struct tcb *self) {
  self->state = DORMANT;
  self->priority = self->base_priority = self->config->priority;
  self->wakeup_requests = 0;
  if (self->activation_requests > 0) {
    self->activation_requests--;
    kernel_make_ready(self, 0);
  }
  kernel_switch_away(self);
}

static void run_task_code(void *task) {
  struct tcb *self = task;
  self->config->task(self->config->exinf);
}

void *kernel_task_thread(void *argument) {
  struct tcb *self = argument;
  kernel_current = self;
  pc_task_thread_init(self->id);
  kernel_enter();
  for (;;) {
    kernel_wait_for_cpu(self);
    kernel_unlock();
    if (setjmp(self->exit_point) == 0) pc_run_task(run_task_code, self);
    kernel_enter();
    finish_task(self);
  }
  return NULL;
}

static ER activate(ID id) {
  struct tcb *task = task_of(id);
  if (task == NULL) return E_ID;
  if (task->state == DORMANT) {
    kernel_wake(task);
    return E_OK;
  }
  if (task->activation_requests >= TMAX_ACTCNT) return E_QOVR;
  task->activation_requests++;
  return E_OK;
}

ER act_tsk(ID tskid) {
  kernel_enter();
  return kernel_leave(activate(tskid));
}

ER iact_tsk(ID tskid) { return act_tsk(tskid); }

/* can_act and can_wup: the task's queued requests of one kind, cleared. */
static ER_UINT cancel_requests(ID tskid, int wakeups) {
  struct tcb *task;
  unsigned *requests;
  ER_UINT count;
  kernel_enter();
  task = task_of(tskid);
  if (task == NULL) return kernel_leave(E_ID);
  requests = wakeups ? &task->wakeup_requests : &task->activation_requests;
  count = (ER_UINT)*requests;
  *requests = 0;
  return kernel_leave(count);
}

ER_UINT can_act(ID tskid) { return cancel_requests(tskid, 0); }

/* ext_tsk ends the task's code wherever it calls it, as ASP's does: the
 * task's frames are left behind and its thread goes back to
 * kernel_task_thread's loop, to wait for the next activation.
 * kernel_task_thread runs on the thread's host stack and set exit_point
 * there before it called pc_run_task, whose call is still running: the jump
 * goes up to a live frame of the same thread, which longjmp allows. The
 * task's code runs on its board stack (task_stacks.c, arm target) or on the
 * same host stack (native); either way the jump is made from the host stack
 * (pc_on_host_stack), right below kernel_task_thread's frames, so no frame
 * on the board stack is running when it lands and the board stack is simply
 * used afresh at the next activation. Nothing is skipped that needs undoing:
 * ext_tsk holds no lock (it is a service call made outside kernel_enter()),
 * and C frames have no destructors. */
static void exit_task(void *task) { longjmp(((struct tcb *)task)->exit_point, 1); }

ER ext_tsk(void) {
  struct tcb *self = kernel_current;
  if (self == NULL || self == &kernel_handler_tcb) return E_CTX;
  pc_on_host_stack(exit_task, self);
  return E_SYS; /* not reached */
}

ER get_tid(ID *p_tskid) {
  *p_tskid = (kernel_current != NULL && kernel_current != &kernel_handler_tcb) ? kernel_current->id
                                                                            : TSK_NONE;
  return E_OK;
}

ER iget_tid(ID *p_tskid) {
  kernel_enter();
  *p_tskid = (kernel_running != NULL && kernel_running != &kernel_handler_tcb) ? kernel_running->id
                                                                            : TSK_NONE;
  kernel_unlock();
  return E_OK;
}

ER get_pri(ID tskid, PRI *p_tskpri) {
  struct tcb *task;
  kernel_enter();
  task = task_of(tskid);
  if (task == NULL) return kernel_leave(E_ID);
  if (task->state == DORMANT) return kernel_leave(E_OBJ);
  *p_tskpri = task->priority;
  return kernel_leave(E_OK);
}

/* As in ASP, a task whose priority is set, even to the one it has, goes to
 * the tail of that priority's queue: same-priority tasks run first. */
ER chg_pri(ID tskid, PRI tskpri) {
  struct tcb *task;
  PRI priority;
  kernel_enter();
  task = task_of(tskid);
  if (task == NULL) return kernel_leave(E_ID);
  priority = tskpri == TPRI_INI ? task->config->priority : tskpri;
  if (priority < TMIN_TPRI || priority > TMAX_TPRI) return kernel_leave(E_PAR);
  if (task->state == DORMANT) return kernel_leave(E_OBJ);
  task->base_priority = priority;
  if (task->state == RUNNING) {
    task->priority = priority;
    kernel_make_ready(task, 0);
    kernel_switch_away(task);
  } else if (task->state == READY) {
    kernel_remove_ready(task);
    task->priority = priority;
    kernel_make_ready(task, 0);
  } else {
    task->priority = priority;
  }
  return kernel_leave(E_OK);
}

ER rot_rdq(PRI tskpri) {
  struct tcb *self = kernel_current;
  PRI priority;
  kernel_enter();
  priority = (tskpri == TPRI_SELF && self != NULL) ? self->priority : tskpri;
  if (priority < TMIN_TPRI || priority > TMAX_TPRI) return kernel_leave(E_PAR);
  if (self != NULL && kernel_running == self && self->priority == priority) {
    kernel_make_ready(self, 0);
    kernel_switch_away(self);
  } else if (kernel_ready[priority].first != kernel_ready[priority].last) {
    struct tcb *first = kernel_ready[priority].first;
    kernel_remove_ready(first);
    kernel_make_ready(first, 0);
  }
  return kernel_leave(E_OK);
}

static ER sleep_for(TMO timeout) {
  struct tcb *self = kernel_current;
  if (self == NULL || self == &kernel_handler_tcb) return E_CTX;
  kernel_enter();
  if (self->wakeup_requests > 0) {
    self->wakeup_requests--;
    return kernel_leave(E_OK);
  }
  if (timeout == TMO_POL) return kernel_leave(E_TMOUT);
  return kernel_leave(kernel_block(self, WAIT_SLEEP, timeout));
}

ER slp_tsk(void) { return sleep_for(TMO_FEVR); }

ER tslp_tsk(TMO tmout) { return sleep_for(tmout); }

ER wup_tsk(ID tskid) {
  struct tcb *task;
  kernel_enter();
  task = task_of(tskid);
  if (task == NULL) return kernel_leave(E_ID);
  if (task->state == DORMANT) return kernel_leave(E_OBJ);
  if (task->state == WAITING && task->wait == WAIT_SLEEP) {
    kernel_end_wait(task, E_OK);
    return kernel_leave(E_OK);
  }
  if (task->wakeup_requests >= TMAX_WUPCNT) return kernel_leave(E_QOVR);
  task->wakeup_requests++;
  return kernel_leave(E_OK);
}

ER iwup_tsk(ID tskid) { return wup_tsk(tskid); }

ER_UINT can_wup(ID tskid) { return cancel_requests(tskid, 1); }

ER dly_tsk(RELTIM dlytim) {
  struct tcb *self = kernel_current;
  if (self == NULL || self == &kernel_handler_tcb) return E_CTX;
  kernel_enter();
  kernel_block(self, WAIT_DELAY, (TMO)dlytim);
  return kernel_leave(E_OK);
}
