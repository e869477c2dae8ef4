// SPDX-License-Identifier: BSD-3-Clause
// The stand-in's definitions: the CMSIS-RTOS2 calls of mros2's init on
// std::thread, lwIP's init (declared as the PC target declares them), and
// where the rtps stand-in keeps what was sent, the readers made and the
// fragment counts.
#include <chrono>
#include <thread>

#include "cmsis_os.h"
#include "lwip.h"
#include "rtps/rtps.h"

osThreadId_t osThreadNew(osThreadFunc_t func, void* argument, const osThreadAttr_t*) {
  // mros2's init task waits for a match that never comes here: it is left running.
  std::thread(func, argument).detach();
  return nullptr;
}
osStatus_t osThreadTerminate(osThreadId_t) { return osOK; }
osStatus_t osDelay(uint32_t ticks) {
  std::this_thread::sleep_for(std::chrono::milliseconds(ticks));
  return osOK;
}
osMessageQueueId_t osMessageQueueNew(uint32_t, uint32_t, const void*) {
  static int queue;
  return &queue;
}
osStatus_t osMessageQueueGet(osMessageQueueId_t, void*, uint8_t*, uint32_t) { return osError; }
void MX_LWIP_Init(void) {}

namespace rtps {
FragmentCounts MessageReceiver::fragmentCounts;

std::vector<Sent>& sent_samples() {
  static std::vector<Sent> sent;
  return sent;
}
std::vector<Reader*>& Domain::readers() {
  static std::vector<Reader*> made;
  return made;
}
uint8_t next_entity_key() {
  static uint8_t key;
  return ++key;
}
}  // namespace rtps
