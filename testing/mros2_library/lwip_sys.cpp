// SPDX-License-Identifier: BSD-3-Clause
// lwIP's system calls (lwip/sys.h, the PC target's), on host threads, for the
// checks that run embeddedRTPS' and mros2's real code without the PC target's
// board threads: mutexes and semaphores work across the check's threads; no
// thread is started.
#include <pthread.h>
#include <time.h>

#include <chrono>
#include <thread>

#include "lwip/sys.h"

extern "C" {
err_t sys_mutex_new(sys_mutex_t* mutex) {
  mutex->handle = new pthread_mutex_t(PTHREAD_MUTEX_INITIALIZER);
  return ERR_OK;
}
void sys_mutex_lock(sys_mutex_t* mutex) { pthread_mutex_lock(static_cast<pthread_mutex_t*>(mutex->handle)); }
void sys_mutex_unlock(sys_mutex_t* mutex) {
  pthread_mutex_unlock(static_cast<pthread_mutex_t*>(mutex->handle));
}
void sys_mutex_free(sys_mutex_t* mutex) { delete static_cast<pthread_mutex_t*>(mutex->handle); }

struct Semaphore {
  pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
  pthread_cond_t signalled = PTHREAD_COND_INITIALIZER;
  unsigned count = 0;
};
err_t sys_sem_new(sys_sem_t* sem, u8_t count) {
  Semaphore* made = new Semaphore;
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
u32_t sys_now(void) {
  struct timespec now;
  clock_gettime(CLOCK_REALTIME, &now);
  return static_cast<u32_t>(now.tv_sec * 1000 + now.tv_nsec / 1000000);
}
u32_t sys_arch_sem_wait(sys_sem_t* sem, u32_t timeout) {
  Semaphore* semaphore = static_cast<Semaphore*>(sem->handle);
  struct timespec deadline;
  clock_gettime(CLOCK_REALTIME, &deadline);
  deadline.tv_sec += timeout / 1000;
  deadline.tv_nsec += static_cast<long>(timeout % 1000) * 1000000;
  if (deadline.tv_nsec >= 1000000000) {
    deadline.tv_sec++;
    deadline.tv_nsec -= 1000000000;
  }
  pthread_mutex_lock(&semaphore->lock);
  while (semaphore->count == 0) {
    if (pthread_cond_timedwait(&semaphore->signalled, &semaphore->lock, &deadline) != 0) {
      pthread_mutex_unlock(&semaphore->lock);
      return SYS_ARCH_TIMEOUT;
    }
  }
  semaphore->count--;
  pthread_mutex_unlock(&semaphore->lock);
  return 0;
}
sys_thread_t sys_thread_new(const char*, lwip_thread_fn, void*, int, int) { return sys_thread_t(); }
void sys_msleep(u32_t milliseconds) { std::this_thread::sleep_for(std::chrono::milliseconds(milliseconds)); }
}

