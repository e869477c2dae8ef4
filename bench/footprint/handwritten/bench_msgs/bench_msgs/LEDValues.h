// SPDX-License-Identifier: BSD-3-Clause
// Hand-written mROS v1 header for bench_msgs/LEDValues (the footprint
// benchmark's reference, in the style of mROS v1's custom_pubsub headers).
#ifndef _BENCH_MSGS_LEDVALUES_H
#define _BENCH_MSGS_LEDVALUES_H

#include <string.h>

static const int LEDVALUES_MSG_ID = 101;

namespace bench_msgs {
class LEDValues {
 public:
  float red;
  float green;
  float blue;

  LEDValues() : red(0), green(0), blue(0) {}

  int dataSize() { return 4 * 3; }

  void memCopy(char*& addrPtr) {
    memcpy(addrPtr, &red, 4);
    addrPtr += 4;
    memcpy(addrPtr, &green, 4);
    addrPtr += 4;
    memcpy(addrPtr, &blue, 4);
    addrPtr += 4;
  }

  void deserialize(char*& rbuf) {
    memcpy(&red, rbuf, 4);
    rbuf += 4;
    memcpy(&green, rbuf, 4);
    rbuf += 4;
    memcpy(&blue, rbuf, 4);
    rbuf += 4;
  }
};
}  // namespace bench_msgs

#endif
