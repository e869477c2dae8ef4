// SPDX-License-Identifier: BSD-3-Clause
// A unit check of embeddedRTPS' real MessageReceiver (src/messages/
// MessageReceiver.cpp and MessageTypes.cpp), as it is or with genmros'
// patches, against the stand-in entities of receiver/. The participant's
// readers, each matched with writers of the remote participant 0x11 x 12:
//   00 00 01 04  best effort, matched with 00 00 01 03, 00 00 02 03 and
//                00 00 04 03
//   00 00 02 04  reliable, matched with 00 00 03 03
// Each line of stdin is a datagram in hex, given to processMessage; a reader
// prints each sample it gets as "reader ID writer ID sn N HEX". At the end,
// with CHECK_FRAGMENT_COUNTS, the check prints the refused samples' counts:
// "counts TOO_LARGE POOL_FULL INCONSISTENT ABANDONED UNMATCHED".
#include <stdio.h>

#include <iostream>
#include <string>
#include <vector>

#include "rtps/entities/Participant.h"
#include "rtps/messages/MessageReceiver.h"

namespace {
const rtps::GuidPrefix_t kRemote = {{0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x11,
                                     0x11, 0x11}};

rtps::Guid_t guid(const rtps::GuidPrefix_t& prefix, uint8_t key, rtps::EntityKind_t kind) {
  return rtps::Guid_t{prefix, rtps::EntityId_t{{0, 0, key}, kind}};
}

// Prints a sample as "reader ID writer ID sn N HEX" (the last bytes of the entity ids).
void print(const rtps::Reader& reader, const rtps::ReaderCacheChange& change) {
  printf("reader %02x writer %02x sn %u ", reader.m_attributes.endpointGuid.entityId.entityKey[2],
         change.writerGuid.entityId.entityKey[2], static_cast<unsigned>(change.sn.low));
  for (rtps::DataSize_t i = 0; i < change.size; ++i) printf("%02x", change.getData()[i]);
  printf("\n");
}

std::vector<uint8_t> bytes_of(const std::string& hex) {
  std::vector<uint8_t> bytes;
  for (size_t i = 0; i + 1 < hex.size(); i += 2)
    bytes.push_back(static_cast<uint8_t>(std::stoul(hex.substr(i, 2), nullptr, 16)));
  return bytes;
}
}  // namespace

int main() {
  const rtps::EntityKind_t kReader = rtps::EntityKind_t::USER_DEFINED_READER_WITHOUT_KEY;
  const rtps::EntityKind_t kWriter = rtps::EntityKind_t::USER_DEFINED_WRITER_WITHOUT_KEY;
  rtps::Participant participant;
  participant.m_guidPrefix = {{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}};
  rtps::Reader best_effort(guid(participant.m_guidPrefix, 1, kReader),
                           rtps::ReliabilityKind_t::BEST_EFFORT,
                           {guid(kRemote, 1, kWriter), guid(kRemote, 2, kWriter),
                            guid(kRemote, 4, kWriter)},
                           print);
  rtps::Reader reliable(guid(participant.m_guidPrefix, 2, kReader),
                        rtps::ReliabilityKind_t::RELIABLE, {guid(kRemote, 3, kWriter)}, print);
  participant.readers = {&best_effort, &reliable};
  // The receiver holds its fragment buffers: static, as the participant is on a board.
  static rtps::MessageReceiver receiver(&participant);

  std::string line;
  while (std::getline(std::cin, line)) {
    std::vector<uint8_t> datagram = bytes_of(line);
    receiver.processMessage(datagram.data(), static_cast<rtps::DataSize_t>(datagram.size()));
  }
#ifdef CHECK_FRAGMENT_COUNTS
  const rtps::FragmentCounts& counts = rtps::MessageReceiver::fragmentCounts;
  printf("counts %u %u %u %u %u\n", counts.tooLarge, counts.poolFull, counts.inconsistent,
         counts.abandoned, counts.unmatched);
#endif
  return 0;
}
