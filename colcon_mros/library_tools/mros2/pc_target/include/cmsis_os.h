// SPDX-License-Identifier: BSD-3-Clause
// CMSIS-RTOS2 (cmsis_os2.h) as mros2 and its apps call it: the kernel,
// threads, delays, the tick and message queues. Names, types and values are
// CMSIS-RTOS2's; only the calls mros2 makes are here.
#ifndef MROS2_PC_CMSIS_OS_H
#define MROS2_PC_CMSIS_OS_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
  osOK = 0,
  osError = -1,
  osErrorTimeout = -2,
  osErrorResource = -3,
  osErrorParameter = -4,
  osErrorNoMemory = -5,
  osErrorISR = -6
} osStatus_t;

typedef enum {
  osPriorityNone = 0,
  osPriorityIdle = 1,
  osPriorityLow = 8,
  osPriorityBelowNormal = 16,
  osPriorityNormal = 24,
  osPriorityAboveNormal = 32,
  osPriorityHigh = 40,
  osPriorityRealtime = 48
} osPriority_t;

typedef void* osThreadId_t;
typedef void* osMessageQueueId_t;
typedef void (*osThreadFunc_t)(void* argument);

typedef struct {
  const char* name;
  uint32_t attr_bits;
  void* cb_mem;
  uint32_t cb_size;
  void* stack_mem;
  uint32_t stack_size;
  osPriority_t priority;
  uint32_t tz_module;
  uint32_t reserved;
} osThreadAttr_t;

#define osWaitForever 0xFFFFFFFFU

osStatus_t osKernelStart(void);
uint32_t osKernelGetTickCount(void);
osThreadId_t osThreadNew(osThreadFunc_t func, void* argument, const osThreadAttr_t* attr);
osStatus_t osThreadTerminate(osThreadId_t thread_id);
osStatus_t osDelay(uint32_t ticks);
osMessageQueueId_t osMessageQueueNew(uint32_t msg_count, uint32_t msg_size, const void* attr);
osStatus_t osMessageQueueGet(osMessageQueueId_t mq_id, void* msg_ptr, uint8_t* msg_prio,
                             uint32_t timeout);

#ifdef __cplusplus
}
#endif

#endif  // MROS2_PC_CMSIS_OS_H
