/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The ASP kernel stand-in's semaphores (CRE_SEM): sig_sem, wai_sem and their
 * variants. A task that waits is queued on the semaphore, FIFO, and woken by
 * sig_sem or, at its time-out, by the timer thread (kernel_timers.c).
 */
#define _GNU_SOURCE
#include <stddef.h>

#include "kernel.h"
#include "kernel_internal.h"
#include "pc_target.h"

struct semaphore *kernel_semaphores;

static struct semaphore *semaphore_of(ID id) {
  if (id < 1 || (uint_t)id > pc_semaphore_count) return NULL;
  return &kernel_semaphores[id - 1];
}

ER sig_sem(ID semid) {
  struct semaphore *semaphore;
  kernel_enter();
  semaphore = semaphore_of(semid);
  if (semaphore == NULL) return kernel_leave(E_ID);
  if (semaphore->waiters.first != NULL) {
    struct tcb *task = semaphore->waiters.first;
    kernel_queue_remove(&semaphore->waiters, task);
    kernel_end_wait(task, E_OK);
    return kernel_leave(E_OK);
  }
  if (semaphore->count >= semaphore->config->max_count) return kernel_leave(E_QOVR);
  semaphore->count++;
  return kernel_leave(E_OK);
}

ER isig_sem(ID semid) { return sig_sem(semid); }

ER twai_sem(ID semid, TMO tmout) {
  struct tcb *self = kernel_current;
  struct semaphore *semaphore;
  ER result;
  if (self == NULL || self == &kernel_handler_tcb) return E_CTX;
  kernel_enter();
  semaphore = semaphore_of(semid);
  if (semaphore == NULL) return kernel_leave(E_ID);
  if (semaphore->count > 0) {
    semaphore->count--;
    return kernel_leave(E_OK);
  }
  if (tmout == TMO_POL) return kernel_leave(E_TMOUT);
  self->waiting_on = semaphore;
  kernel_queue_add(&semaphore->waiters, self, 0);
  result = kernel_block(self, WAIT_SEMAPHORE, tmout);
  self->waiting_on = NULL;
  return kernel_leave(result);
}

ER wai_sem(ID semid) { return twai_sem(semid, TMO_FEVR); }

ER pol_sem(ID semid) { return twai_sem(semid, TMO_POL); }
