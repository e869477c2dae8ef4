// SPDX-License-Identifier: BSD-3-Clause
// lwIP's sys_arch (lwip/sys.h) on host threads: mutexes, counting
// semaphores (as the CMSIS-RTOS2 port's osSemaphoreNew), threads on their
// board stacks, and time in milliseconds. Priorities are not held.
#include <errno.h>
#include <pthread.h>
#include <time.h>

#include "board_threads.h"
#include "lwip/sys.h"

namespace {

struct Semaphore {
  pthread_mutex_t lock;
  pthread_cond_t signalled;
  unsigned count;
};

uint32_t now_milliseconds() {
  struct timespec now;
  clock_gettime(CLOCK_MONOTONIC, &now);
  return (uint32_t)(now.tv_sec * 1000 + now.tv_nsec / 1000000);
}

}  // namespace

extern "C" {

err_t sys_mutex_new(sys_mutex_t* mutex) {
  pthread_mutex_t* made = new pthread_mutex_t;
  pthread_mutex_init(made, NULL);
  mutex->handle = made;
  return ERR_OK;
}

void sys_mutex_lock(sys_mutex_t* mutex) {
  pthread_mutex_lock(static_cast<pthread_mutex_t*>(mutex->handle));
}

void sys_mutex_unlock(sys_mutex_t* mutex) {
  pthread_mutex_unlock(static_cast<pthread_mutex_t*>(mutex->handle));
}

void sys_mutex_free(sys_mutex_t* mutex) {
  pthread_mutex_t* made = static_cast<pthread_mutex_t*>(mutex->handle);
  pthread_mutex_destroy(made);
  delete made;
  mutex->handle = NULL;
}

err_t sys_sem_new(sys_sem_t* sem, u8_t count) {
  Semaphore* made = new Semaphore;
  pthread_mutex_init(&made->lock, NULL);
  pthread_condattr_t attributes;
  pthread_condattr_init(&attributes);
  pthread_condattr_setclock(&attributes, CLOCK_MONOTONIC);
  pthread_cond_init(&made->signalled, &attributes);
  pthread_condattr_destroy(&attributes);
  made->count = count;
  sem->handle = made;
  return ERR_OK;
}

void sys_sem_signal(sys_sem_t* sem) {
  Semaphore* semaphore = static_cast<Semaphore*>(sem->handle);
  pthread_mutex_lock(&semaphore->lock);
  semaphore->count++;
  pthread_cond_signal(&semaphore->signalled);
  pthread_mutex_unlock(&semaphore->lock);
}

u32_t sys_arch_sem_wait(sys_sem_t* sem, u32_t timeout) {
  Semaphore* semaphore = static_cast<Semaphore*>(sem->handle);
  uint32_t start = now_milliseconds();
  struct timespec deadline;
  clock_gettime(CLOCK_MONOTONIC, &deadline);
  deadline.tv_sec += timeout / 1000;
  deadline.tv_nsec += (long)(timeout % 1000) * 1000000;
  if (deadline.tv_nsec >= 1000000000) {
    deadline.tv_sec++;
    deadline.tv_nsec -= 1000000000;
  }
  pthread_mutex_lock(&semaphore->lock);
  while (semaphore->count == 0) {
    if (timeout == 0) {
      pthread_cond_wait(&semaphore->signalled, &semaphore->lock);
    } else if (pthread_cond_timedwait(&semaphore->signalled, &semaphore->lock, &deadline) ==
               ETIMEDOUT) {
      pthread_mutex_unlock(&semaphore->lock);
      return SYS_ARCH_TIMEOUT;
    }
  }
  semaphore->count--;
  pthread_mutex_unlock(&semaphore->lock);
  return now_milliseconds() - start;
}

void sys_sem_free(sys_sem_t* sem) {
  Semaphore* semaphore = static_cast<Semaphore*>(sem->handle);
  pthread_cond_destroy(&semaphore->signalled);
  pthread_mutex_destroy(&semaphore->lock);
  delete semaphore;
  sem->handle = NULL;
}

int sys_sem_valid(sys_sem_t* sem) { return sem->handle != NULL; }

sys_thread_t sys_thread_new(const char* name, lwip_thread_fn thread, void* arg, int stacksize,
                            int) {
  return mros2_pc::start_thread(name, thread, arg, (size_t)stacksize);
}

void sys_msleep(u32_t ms) { mros2_pc::sleep_milliseconds(ms); }

u32_t sys_now(void) { return now_milliseconds(); }

}  // extern "C"
