// SPDX-License-Identifier: BSD-3-Clause
// bench/mros2/fragment_receive.py's program: embeddedRTPS' real MessageReceiver
// (with the patch data-frag-for-best-effort-readers) over the stand-in entities of
// testing/mros2_library/receiver, one best-effort reader matched with one writer.
// stdin: "case NAME" lines, each followed by the datagrams (hex) of one sample. For each
// case it times the receiver over the sample's datagrams, ROUNDS times (each round a
// newer sequence number, written into every datagram at SN_OFFSET), and prints
// "NAME MEDIAN_NS SAMPLES_DELIVERED". With the argument "sizeof" it prints
// sizeof(rtps::MessageReceiver) instead.
#include <stdio.h>
#include <string.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <string>
#include <vector>

#include "rtps/entities/Participant.h"
#include "rtps/messages/MessageReceiver.h"

namespace {
const int kRounds = 2001;
// Where a DATA's or DATA_FRAG's writerSN (its low half) is in the datagrams the script
// writes: the RTPS header (20), the submessage header (4), the fields before it (16).
const size_t kSnOffset = 20 + 4 + 16;

unsigned delivered;
void take(const rtps::Reader&, const rtps::ReaderCacheChange&) { ++delivered; }

std::vector<uint8_t> bytes_of(const std::string& hex) {
  std::vector<uint8_t> bytes;
  for (size_t i = 0; i + 1 < hex.size(); i += 2)
    bytes.push_back(static_cast<uint8_t>(std::stoul(hex.substr(i, 2), nullptr, 16)));
  return bytes;
}

rtps::Guid_t guid(uint8_t prefix_byte, uint8_t key, rtps::EntityKind_t kind) {
  rtps::GuidPrefix_t prefix;
  prefix.id.fill(prefix_byte);
  return rtps::Guid_t{prefix, rtps::EntityId_t{{0, 0, key}, kind}};
}
}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && strcmp(argv[1], "sizeof") == 0) {
    printf("%zu\n", sizeof(rtps::MessageReceiver));
    return 0;
  }
  rtps::Participant participant;
  participant.m_guidPrefix.id.fill(1);
  rtps::Reader reader(guid(1, 1, rtps::EntityKind_t::USER_DEFINED_READER_WITHOUT_KEY),
                      rtps::ReliabilityKind_t::BEST_EFFORT,
                      {guid(0x11, 1, rtps::EntityKind_t::USER_DEFINED_WRITER_WITHOUT_KEY)}, take);
  participant.readers = {&reader};
  static rtps::MessageReceiver receiver(&participant);

  std::vector<std::pair<std::string, std::vector<std::vector<uint8_t>>>> cases;
  std::string line;
  while (std::getline(std::cin, line)) {
    if (line.compare(0, 5, "case ") == 0)
      cases.push_back({line.substr(5), {}});
    else if (!cases.empty())
      cases.back().second.push_back(bytes_of(line));
  }
  uint32_t sn = 1;
  for (auto& entry : cases) {
    std::vector<double> times;
    delivered = 0;
    for (int round = 0; round < kRounds; ++round, ++sn) {
      for (auto& datagram : entry.second) memcpy(&datagram[kSnOffset], &sn, sizeof sn);
      auto start = std::chrono::steady_clock::now();
      for (auto& datagram : entry.second)
        receiver.processMessage(datagram.data(), static_cast<rtps::DataSize_t>(datagram.size()));
      times.push_back(std::chrono::duration<double, std::nano>(
          std::chrono::steady_clock::now() - start).count());
    }
    std::nth_element(times.begin(), times.begin() + kRounds / 2, times.end());
    printf("%s %.0f %u\n", entry.first.c_str(), times[kRounds / 2], delivered);
  }
  return 0;
}
