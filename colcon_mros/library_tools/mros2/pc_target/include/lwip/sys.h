// SPDX-License-Identifier: BSD-3-Clause
// lwIP's operating system layer (lwip/sys.h, the port's sys_arch): threads,
// mutexes, semaphores and time, as the board's port gives them from its
// RTOS. Threads run on the stack size they are created with (the arm
// target holds them to it).
#ifndef MROS2_PC_LWIP_SYS_H
#define MROS2_PC_LWIP_SYS_H

#include "cmsis_os.h"  // the CMSIS-RTOS2 port's sys_arch.h includes it
#include "lwip/err.h"

typedef struct {
  void* handle;  // NULL until sys_mutex_new
} sys_mutex_t;
typedef struct {
  void* handle;  // NULL until sys_sem_new
} sys_sem_t;
typedef void* sys_thread_t;
typedef void (*lwip_thread_fn)(void* arg);

#define SYS_ARCH_TIMEOUT 0xffffffffUL

#ifdef __cplusplus
extern "C" {
#endif
err_t sys_mutex_new(sys_mutex_t* mutex);
void sys_mutex_lock(sys_mutex_t* mutex);
void sys_mutex_unlock(sys_mutex_t* mutex);
void sys_mutex_free(sys_mutex_t* mutex);

err_t sys_sem_new(sys_sem_t* sem, u8_t count);
void sys_sem_signal(sys_sem_t* sem);
// Milliseconds waited, or SYS_ARCH_TIMEOUT; timeout 0 waits for ever.
u32_t sys_arch_sem_wait(sys_sem_t* sem, u32_t timeout);
void sys_sem_free(sys_sem_t* sem);
int sys_sem_valid(sys_sem_t* sem);

sys_thread_t sys_thread_new(const char* name, lwip_thread_fn thread, void* arg, int stacksize,
                            int prio);
void sys_msleep(u32_t ms);
u32_t sys_now(void);
#ifdef __cplusplus
}
#endif

#define sys_sem_wait(sem) sys_arch_sem_wait(sem, 0)

#endif  // MROS2_PC_LWIP_SYS_H
