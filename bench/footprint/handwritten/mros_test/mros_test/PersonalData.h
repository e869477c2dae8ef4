// SPDX-License-Identifier: BSD-3-Clause
// Hand-written mROS v1 header for mros_test/PersonalData, in the style of the
// headers mROS v1 ships (mros_ws/custom_pubsub/include): the footprint
// benchmark's reference. Trusts every length it reads.
#ifndef _MROS_TEST_PERSONALDATA_H
#define _MROS_TEST_PERSONALDATA_H

#include <stdint.h>
#include <string.h>

#include <string>

static const int PERSONALDATA_MSG_ID = 100;

namespace mros_test {
class PersonalData {
 public:
  std::string first_name;
  std::string last_name;
  uint16_t age;
  int32_t score;

  PersonalData() : age(0), score(0) {}

  int dataSize() { return first_name.size() + last_name.size() + 4 * 2 + 2 + 4; }

  void memCopy(char*& addrPtr) {
    uint32_t size = first_name.size();
    memcpy(addrPtr, &size, 4);
    addrPtr += 4;
    memcpy(addrPtr, first_name.c_str(), size);
    addrPtr += size;
    size = last_name.size();
    memcpy(addrPtr, &size, 4);
    addrPtr += 4;
    memcpy(addrPtr, last_name.c_str(), size);
    addrPtr += size;
    memcpy(addrPtr, &age, 2);
    addrPtr += 2;
    memcpy(addrPtr, &score, 4);
    addrPtr += 4;
  }

  void deserialize(char*& rbuf) {
    uint32_t size;
    memcpy(&size, rbuf, 4);
    rbuf += 4;
    first_name.assign(rbuf, size);
    rbuf += size;
    memcpy(&size, rbuf, 4);
    rbuf += 4;
    last_name.assign(rbuf, size);
    rbuf += size;
    memcpy(&age, rbuf, 2);
    rbuf += 2;
    memcpy(&score, rbuf, 4);
    rbuf += 4;
  }
};
}  // namespace mros_test

namespace message_traits {
template <>
struct MD5Sum<PERSONALDATA_MSG_ID> {
  static const char* value() { return "db8764b0e4c604ae579ade5118a6958c"; }
};

template <>
struct DataType<mros_test::PersonalData*> {
  static const char* value() { return "mros_test/PersonalData"; }
};

template <>
struct DataTypeId<mros_test::PersonalData*> {
  static int value() { return PERSONALDATA_MSG_ID; }
};

template <>
struct Definition<mros_test::PersonalData*> {
  static const char* value() {
    return "# The user-defined type of the mROS paper's evaluation.\n\
string first_name\n\
string last_name\n\
uint16 age\n\
int32 score\n\
";
  }
};
}  // namespace message_traits

namespace subtask_methods {
template <>
struct CallCallbackFuncs<PERSONALDATA_MSG_ID> {
  static void call(void (*fp)(void*), char* rbuf) {
    mros_test::PersonalData msg;
    rbuf += 4;
    msg.deserialize(rbuf);
    fp(&msg);
  }
};
}  // namespace subtask_methods

#endif
