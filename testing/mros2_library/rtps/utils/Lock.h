// SPDX-License-Identifier: BSD-3-Clause
// A stand-in of embeddedRTPS' rtps/utils/Lock.h (its name and signature): a
// scoped lock of an lwIP mutex.
#ifndef MROS2_LIBRARY_STAND_IN_RTPS_LOCK_H
#define MROS2_LIBRARY_STAND_IN_RTPS_LOCK_H

#include "lwip/sys.h"

namespace rtps {
class Lock {
 public:
  explicit Lock(sys_mutex_t& mutex) : mutex_(mutex) { sys_mutex_lock(&mutex_); }
  ~Lock() { sys_mutex_unlock(&mutex_); }

 private:
  sys_mutex_t& mutex_;
};
}  // namespace rtps

#endif  // MROS2_LIBRARY_STAND_IN_RTPS_LOCK_H
