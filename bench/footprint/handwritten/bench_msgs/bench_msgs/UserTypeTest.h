// SPDX-License-Identifier: BSD-3-Clause
// Hand-written mROS v1 header for bench_msgs/UserTypeTest (the footprint
// benchmark's reference, in the style of mROS v1's custom_pubsub headers).
#ifndef _BENCH_MSGS_USERTYPETEST_H
#define _BENCH_MSGS_USERTYPETEST_H

#include "bench_msgs/LEDValues.h"
#include "bench_msgs/PersonName.h"

static const int USERTYPETEST_MSG_ID = 103;

namespace bench_msgs {
class UserTypeTest {
 public:
  bench_msgs::LEDValues ledVal;
  bench_msgs::PersonName nameVal;

  int dataSize() { return ledVal.dataSize() + nameVal.dataSize(); }

  void memCopy(char*& addrPtr) {
    ledVal.memCopy(addrPtr);
    nameVal.memCopy(addrPtr);
  }

  void deserialize(char*& rbuf) {
    ledVal.deserialize(rbuf);
    nameVal.deserialize(rbuf);
  }
};
}  // namespace bench_msgs

namespace message_traits {
template <>
struct MD5Sum<USERTYPETEST_MSG_ID> {
  static const char* value() { return "4c13c13aa2f193d25835cfad6215cb75"; }
};

template <>
struct DataType<bench_msgs::UserTypeTest*> {
  static const char* value() { return "bench_msgs/UserTypeTest"; }
};

template <>
struct DataTypeId<bench_msgs::UserTypeTest*> {
  static int value() { return USERTYPETEST_MSG_ID; }
};

template <>
struct Definition<bench_msgs::UserTypeTest*> {
  static const char* value() {
    return "LEDValues ledVal\n\
PersonName nameVal\n\
\n\
================================================================================\n\
MSG: bench_msgs/LEDValues\n\
float32 red\n\
float32 green\n\
float32 blue\n\
\n\
================================================================================\n\
MSG: bench_msgs/PersonName\n\
string firstName\n\
string lastName\n\
";
  }
};
}  // namespace message_traits

namespace subtask_methods {
template <>
struct CallCallbackFuncs<USERTYPETEST_MSG_ID> {
  static void call(void (*fp)(void*), char* rbuf) {
    bench_msgs::UserTypeTest msg;
    rbuf += 4;
    msg.deserialize(rbuf);
    fp(&msg);
  }
};
}  // namespace subtask_methods

#endif
