// SPDX-License-Identifier: BSD-3-Clause
// Hand-written per-app aggregate (mROS v1 style) for the footprint benchmark.
#include "bench_msgs/UserTypeTest.h"

static void callCallback(int id, void (*fp)(void*), char* rbuf) {
  switch (id) {
    case USERTYPETEST_MSG_ID:
      subtask_methods::CallCallbackFuncs<USERTYPETEST_MSG_ID>().call(fp, rbuf);
      break;
  }
}

static const char* getMD5Sum(int id) {
  switch (id) {
    case USERTYPETEST_MSG_ID:
      return message_traits::MD5Sum<USERTYPETEST_MSG_ID>().value();
  }
  return 0;
}
