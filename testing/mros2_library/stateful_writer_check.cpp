// SPDX-License-Identifier: BSD-3-Clause
// A unit check of embeddedRTPS' real StatefulWriter (include/rtps/entities/
// StatefulWriter.tpp) with genmros' patch reliable-where-asked: one writer,
// whose network driver records what it sends, and no thread pool (samples
// are kept, not sent, unless a reader asks). Each line of stdin is a step:
//   keep DEPTH WAIT_MS           keepLast(DEPTH, WAIT_MS); prints "kept" or "refused"
//   reader ID                    a matched reader (entity key ID)
//   publish                      newChange of a 4-byte sample; prints "published SN"
//                                or "refused", and "waited MS"
//   acknack ID BASE COUNT        the reader's ACKNACK: it has every sample below BASE
//   acknack-later MS ID BASE COUNT  the same, from another thread MS milliseconds on
//   gone ID                      the reader removed
// The driver prints "heartbeat FIRST LAST" and "data SN" for what the writer
// sends; the check prints "done" after each step.
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "recording_driver.h"
#include "rtps/entities/StatefulWriter.h"

// The writer is given no thread pool: it never calls one.
bool rtps::ThreadPool::addWorkload(rtps::Writer*) { abort(); }

namespace {

rtps::StatefulWriterT<recording::WriterDriver> writer;
const rtps::GuidPrefix_t local = {{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}};
const rtps::GuidPrefix_t remote = {{0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x11,
                                    0x11, 0x11}};

rtps::EntityId_t reader_id(int key) {
  return rtps::EntityId_t{{0, 0, static_cast<uint8_t>(key)},
                          rtps::EntityKind_t::USER_DEFINED_READER_WITHOUT_KEY};
}

void acknack(int key, uint32_t base, int32_t count) {
  rtps::SubmessageAckNack message;
  message.readerId = reader_id(key);
  message.writerId = writer.m_attributes.endpointGuid.entityId;
  message.readerSNState = rtps::SequenceNumberSet(rtps::SequenceNumber_t{0, base});
  message.readerSNState.numBits = 0;
  message.count = rtps::Count_t{count};
  writer.onNewAckNack(message, remote);
}

}  // namespace

int main() {
  rtps::TopicData attributes;
  attributes.endpointGuid = rtps::Guid_t{
      local, rtps::EntityId_t{{0, 0, 1}, rtps::EntityKind_t::USER_DEFINED_WRITER_WITHOUT_KEY}};
  recording::WriterDriver driver;
  writer.init(attributes, rtps::TopicKind_t::NO_KEY, nullptr, driver);
  const uint8_t sample[4] = {0, 1, 0, 0};
  std::vector<std::thread> later;
  std::string line;
  while (std::getline(std::cin, line)) {
    std::istringstream step(line);
    std::string kind;
    step >> kind;
    if (kind == "keep") {
      unsigned depth, wait;
      step >> depth >> wait;
      printf(writer.keepLast(static_cast<uint16_t>(depth), wait) ? "kept\n" : "refused\n");
    } else if (kind == "reader") {
      int key;
      step >> key;
      writer.addNewMatchedReader(rtps::ReaderProxy(rtps::Guid_t{remote, reader_id(key)},
                                                   rtps::LocatorIPv4()));
    } else if (kind == "publish") {
      uint32_t start = sys_now();
      const rtps::CacheChange* change = writer.newChange(rtps::ChangeKind_t::ALIVE, sample,
                                                         sizeof sample);
      if (change != nullptr) {
        printf("published %u\n", static_cast<unsigned>(change->sequenceNumber.low));
      } else {
        printf("refused (%u so far)\n", static_cast<unsigned>(writer.refusedSamples()));
      }
      printf("waited %u\n", static_cast<unsigned>(sys_now() - start));
    } else if (kind == "acknack") {
      int key;
      uint32_t base;
      int32_t count;
      step >> key >> base >> count;
      acknack(key, base, count);
    } else if (kind == "acknack-later") {
      unsigned milliseconds;
      int key;
      uint32_t base;
      int32_t count;
      step >> milliseconds >> key >> base >> count;
      later.emplace_back([=] {
        sys_msleep(milliseconds);
        acknack(key, base, count);
      });
    } else if (kind == "gone") {
      int key;
      step >> key;
      writer.removeReader(rtps::Guid_t{remote, reader_id(key)});
    }
    printf("done\n");
    fflush(stdout);
  }
  for (std::thread& thread : later) thread.join();
  return 0;
}
