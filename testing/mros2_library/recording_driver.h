// SPDX-License-Identifier: BSD-3-Clause
// What the checks' network drivers record instead of sending: the datagram,
// and the writer checks' driver, which prints what a writer sends as
// "heartbeat FIRST LAST" and "data SN".
#ifndef GENMROS_RECORDING_DRIVER_H
#define GENMROS_RECORDING_DRIVER_H

#include <stdio.h>
#include <string.h>

#include <vector>

#include "rtps/communication/PacketInfo.h"
#include "rtps/messages/MessageTypes.h"

namespace recording {

// The RTPS header (20 bytes) and INFO_TS (12) come before the submessage the
// writer sends; in it, its header (4) and the reader and writer ids (8).
const size_t kSubmessage = 20 + 12;

inline uint32_t word_at(const std::vector<uint8_t>& bytes, size_t offset) {
  uint32_t word;
  memcpy(&word, bytes.data() + offset, sizeof word);
  return word;
}

// The datagram a packet's chain of buffers holds.
inline std::vector<uint8_t> datagram_of(const rtps::PacketInfo& packet) {
  std::vector<uint8_t> datagram;
  for (const pbuf* part = packet.buffer.firstElement; part != NULL; part = part->next) {
    const uint8_t* bytes = static_cast<const uint8_t*>(part->payload);
    datagram.insert(datagram.end(), bytes, bytes + part->len);
  }
  return datagram;
}

struct WriterDriver {
  void sendPacket(rtps::PacketInfo& packet) {
    const std::vector<uint8_t> datagram = datagram_of(packet);
    // A heartbeat goes out without INFO_TS.
    if (datagram[20] == static_cast<uint8_t>(rtps::SubmessageKind::HEARTBEAT)) {
      printf("heartbeat %u %u\n", word_at(datagram, 20 + 12 + 4), word_at(datagram, 20 + 12 + 12));
    } else {
      // DATA: extra flags and octets to inline QoS (4), the ids (8), the sequence number.
      printf("data %u\n", word_at(datagram, kSubmessage + 4 + 4 + 8 + 4));
    }
    fflush(stdout);
  }
};

}  // namespace recording

#endif  // GENMROS_RECORDING_DRIVER_H
