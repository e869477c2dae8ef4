// SPDX-License-Identifier: BSD-3-Clause
// Hand-written mROS v1 header for bench_msgs/PersonName (the footprint
// benchmark's reference, in the style of mROS v1's custom_pubsub headers).
#ifndef _BENCH_MSGS_PERSONNAME_H
#define _BENCH_MSGS_PERSONNAME_H

#include <stdint.h>
#include <string.h>

#include <string>

static const int PERSONNAME_MSG_ID = 102;

namespace bench_msgs {
class PersonName {
 public:
  std::string firstName;
  std::string lastName;

  int dataSize() { return firstName.size() + lastName.size() + 4 * 2; }

  void memCopy(char*& addrPtr) {
    uint32_t size = firstName.size();
    memcpy(addrPtr, &size, 4);
    addrPtr += 4;
    memcpy(addrPtr, firstName.c_str(), size);
    addrPtr += size;
    size = lastName.size();
    memcpy(addrPtr, &size, 4);
    addrPtr += 4;
    memcpy(addrPtr, lastName.c_str(), size);
    addrPtr += size;
  }

  void deserialize(char*& rbuf) {
    uint32_t size;
    memcpy(&size, rbuf, 4);
    rbuf += 4;
    firstName.assign(rbuf, size);
    rbuf += size;
    memcpy(&size, rbuf, 4);
    rbuf += 4;
    lastName.assign(rbuf, size);
    rbuf += size;
  }
};
}  // namespace bench_msgs

#endif
