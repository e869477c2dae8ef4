// SPDX-License-Identifier: BSD-3-Clause
// CMSIS-RTOS2 as mros2 calls it (cmsis_os.h), on host threads.
//
// Where it differs from the board's RTOS (CMSIS-FreeRTOS): osKernelStart
// returns, as mros2-posix' cmsis-posix does, so that an app's main goes on;
// priorities are not held (the host schedules the threads, all at once);
// osThreadTerminate(NULL) ends the calling thread, as in cmsis-posix, where
// CMSIS-RTOS2 answers osErrorParameter.
#include <stdarg.h>
#include <stdio.h>
#include <time.h>

#include "board_threads.h"
#include "cmsis_impl_logger.h"
#include "cmsis_os.h"
#include "mros2_pc_settings.h"

namespace {

// CMSIS-FreeRTOS' stack for a thread whose attributes give none: STM32Cube's
// configMINIMAL_STACK_SIZE, 128 words.
const uint32_t kDefaultStackBytes = 128 * 4;

uint32_t milliseconds_since_start() {
  static const struct timespec start = [] {
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return now;
  }();
  struct timespec now;
  clock_gettime(CLOCK_MONOTONIC, &now);
  return (uint32_t)((now.tv_sec - start.tv_sec) * 1000 + (now.tv_nsec - start.tv_nsec) / 1000000);
}

// A queue keeps its sizes; the calls that put into one are not here,
// because mros2 makes none.
struct MessageQueue {
  uint32_t count;
  uint32_t size;
};

}  // namespace

extern "C" {

void mros2_pc_log(const char* severity, const char* format, ...) {
  va_list arguments;
  va_start(arguments, format);
  flockfile(stdout);
  printf("[%s] ", severity);
  vprintf(format, arguments);
  printf("\n");
  funlockfile(stdout);
  fflush(stdout);
  va_end(arguments);
}

osStatus_t osKernelStart(void) {
  milliseconds_since_start();  // the tick counts from here
  return osOK;
}

uint32_t osKernelGetTickCount(void) { return milliseconds_since_start(); }

osThreadId_t osThreadNew(osThreadFunc_t func, void* argument, const osThreadAttr_t* attr) {
  uint32_t stack_size = attr != NULL && attr->stack_size != 0 ? attr->stack_size
                                                              : kDefaultStackBytes;
  return mros2_pc::start_thread(attr != NULL ? attr->name : NULL, func, argument, stack_size);
}

osStatus_t osThreadTerminate(osThreadId_t thread_id) {
  if (thread_id != NULL && thread_id != mros2_pc::current_thread()) {
    return osErrorParameter;  // ending another thread: mros2 never asks it
  }
  mros2_pc::exit_thread();
}

osStatus_t osDelay(uint32_t ticks) {
  mros2_pc::sleep_milliseconds(ticks);  // configTICK_RATE_HZ 1000: a tick is a millisecond
  return osOK;
}

osMessageQueueId_t osMessageQueueNew(uint32_t msg_count, uint32_t msg_size, const void*) {
  return new MessageQueue{msg_count, msg_size};
}

// Nothing puts into the queue: the call waits its time-out and says so.
osStatus_t osMessageQueueGet(osMessageQueueId_t mq_id, void*, uint8_t*, uint32_t timeout) {
  if (mq_id == NULL) return osErrorParameter;
  if (timeout == 0) return osErrorResource;
  do {
    mros2_pc::sleep_milliseconds(timeout == osWaitForever ? 1000 : timeout);
  } while (timeout == osWaitForever);
  return osErrorTimeout;
}

}  // extern "C"
