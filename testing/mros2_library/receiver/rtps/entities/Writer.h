// SPDX-License-Identifier: BSD-3-Clause
// A stand-in of embeddedRTPS' Writer as its receiver calls it: the check's
// participant has no writer, so no call reaches it.
#ifndef RTPS_WRITER_H
#define RTPS_WRITER_H

#include "rtps/messages/MessageTypes.h"

namespace rtps {
class Writer {
 public:
  void onNewAckNack(const SubmessageAckNack&, const GuidPrefix_t&) {}
};
}  // namespace rtps

#endif  // RTPS_WRITER_H
