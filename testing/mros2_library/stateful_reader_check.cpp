// SPDX-License-Identifier: BSD-3-Clause
// A unit check of embeddedRTPS' real StatefulReader (include/rtps/entities/
// StatefulReader.tpp and WriterProxy.h), as it is or with genmros' patches:
// one reader, matched with one remote writer, whose network driver records
// the ACKNACKs it is given. Each line of stdin is a step:
//   data SN [SIZE]              a sample of the writer (4 bytes unless SIZE),
//                               to newChange
//   heartbeat FIRST LAST COUNT  a HEARTBEAT of the writer, to onNewHeartbeat
// The reader prints "took SN" for each sample it delivers and "asks SN ..."
// (the sequence numbers an ACKNACK requests, none for an acknowledgement
// alone) for each ACKNACK it sends; the check prints "done" after each step,
// so that a writer simulated on the other side of the pipes can answer.
#include <stdio.h>

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "recording_driver.h"
#include "rtps/entities/StatefulReader.h"

namespace {

// The RTPS header (20 bytes) and the ACKNACK's submessage header (4), reader
// and writer ids (8) come before its sequence number set.
const size_t kSetOffset = 20 + 4 + 8;

struct AckNackDriver {
  void sendPacket(rtps::PacketInfo& packet) {
    const std::vector<uint8_t> datagram = recording::datagram_of(packet);
    uint32_t low = recording::word_at(datagram, kSetOffset + 4);
    uint32_t bits = recording::word_at(datagram, kSetOffset + 8);
    printf("asks");
    for (uint32_t bit = 0; bit < bits; ++bit) {
      uint32_t word = recording::word_at(datagram, kSetOffset + 12 + 4 * (bit / 32));
      if (word & (uint32_t{1} << (31 - bit % 32))) printf(" %u", static_cast<unsigned>(low + bit));
    }
    printf("\n");
  }
};

void print_taken(void*, const rtps::ReaderCacheChange& change) {
  printf("took %u\n", static_cast<unsigned>(change.sn.low));
}

}  // namespace

int main() {
  const rtps::GuidPrefix_t local = {{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}};
  const rtps::GuidPrefix_t remote = {{0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x11,
                                      0x11, 0x11}};
  const rtps::EntityId_t reader_id = {{0, 0, 1}, rtps::EntityKind_t::USER_DEFINED_READER_WITHOUT_KEY};
  const rtps::EntityId_t writer_id = {{0, 0, 1}, rtps::EntityKind_t::USER_DEFINED_WRITER_WITHOUT_KEY};
  rtps::TopicData attributes;
  attributes.endpointGuid = rtps::Guid_t{local, reader_id};
  AckNackDriver driver;
  static rtps::StatefulReaderT<AckNackDriver> reader;
  reader.init(attributes, driver);
  reader.registerCallback(print_taken, NULL);
  rtps::Guid_t writer{remote, writer_id};
  reader.addNewMatchedWriter(rtps::WriterProxy(writer, rtps::LocatorIPv4()));

  // A sample's encapsulation (CDR, little-endian), then zeros up to its size.
  std::vector<uint8_t> sample;
  std::string line;
  while (std::getline(std::cin, line)) {
    std::istringstream step(line);
    std::string kind;
    step >> kind;
    if (kind == "data") {
      uint32_t sn, size;
      step >> sn;
      if (!(step >> size) || size < 4) size = 4;
      sample.assign(size, 0);
      sample[1] = 1;
      rtps::ReaderCacheChange change(rtps::ChangeKind_t::ALIVE, writer, rtps::SequenceNumber_t{0, sn},
                                     sample.data(), static_cast<rtps::DataSize_t>(size));
      reader.newChange(change);
    } else if (kind == "heartbeat") {
      uint32_t first, last;
      int32_t count;
      step >> first >> last >> count;
      rtps::SubmessageHeartbeat heartbeat;
      heartbeat.readerId = reader_id;
      heartbeat.writerId = writer_id;
      heartbeat.firstSN = rtps::SequenceNumber_t{0, first};
      heartbeat.lastSN = rtps::SequenceNumber_t{0, last};
      heartbeat.count = rtps::Count_t{count};
      reader.onNewHeartbeat(heartbeat, remote);
    }
    printf("done\n");
    fflush(stdout);
  }
  return 0;
}
