// SPDX-License-Identifier: BSD-3-Clause
// A stand-in of the CMSIS-RTOS2 calls mros2's src/mros2.cpp makes (as
// cmsis-posix gives them), on std::thread: enough for init, create_node and
// the init task's wait on the host.
#ifndef MROS2_LIBRARY_STAND_IN_CMSIS_OS_H
#define MROS2_LIBRARY_STAND_IN_CMSIS_OS_H

#include <stdint.h>

typedef enum { osOK = 0, osError = -1 } osStatus_t;
typedef int osPriority_t;
typedef void* osThreadId_t;
typedef void* osMessageQueueId_t;
typedef void (*osThreadFunc_t)(void* argument);
typedef struct {
  const char* name;
  uint32_t stack_size;
  osPriority_t priority;
} osThreadAttr_t;
#define osWaitForever 0xFFFFFFFFu

osThreadId_t osThreadNew(osThreadFunc_t func, void* argument, const osThreadAttr_t* attr);
osStatus_t osThreadTerminate(osThreadId_t thread_id);
osStatus_t osDelay(uint32_t ticks);
osMessageQueueId_t osMessageQueueNew(uint32_t count, uint32_t size, const void* attr);
osStatus_t osMessageQueueGet(osMessageQueueId_t queue, void* msg, uint8_t* priority,
                             uint32_t timeout);

#endif  // MROS2_LIBRARY_STAND_IN_CMSIS_OS_H
