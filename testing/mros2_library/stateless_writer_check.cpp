// SPDX-License-Identifier: BSD-3-Clause
// A unit check of embeddedRTPS' real StatelessWriter (include/rtps/entities/
// StatelessWriter.tpp): one writer, whose network driver records what it
// sends, and no thread pool; the check runs the writer thread's workloads
// itself, so a burst can outrun them. Each line of stdin is a step:
//   reader ID     a matched reader (entity key ID)
//   publish       newChange of a 4-byte sample; prints "published SN"
//   work          one workload of the writer thread: progress()
// The driver prints "data SN" for what the writer sends; the check prints
// "done" after each step.
#include <stdio.h>
#include <stdlib.h>

#include <iostream>
#include <sstream>
#include <string>

#include "recording_driver.h"
#include "rtps/entities/StatelessWriter.h"

// The writer is given no thread pool: it never calls one.
bool rtps::ThreadPool::addWorkload(rtps::Writer*) { abort(); }

int main() {
  const rtps::GuidPrefix_t local = {{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}};
  const rtps::GuidPrefix_t remote = {{0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x11,
                                      0x11, 0x11, 0x11}};
  rtps::TopicData attributes;
  attributes.endpointGuid = rtps::Guid_t{
      local, rtps::EntityId_t{{0, 0, 1}, rtps::EntityKind_t::USER_DEFINED_WRITER_WITHOUT_KEY}};
  recording::WriterDriver driver;
  static rtps::StatelessWriterT<recording::WriterDriver> writer;
  writer.init(attributes, rtps::TopicKind_t::NO_KEY, nullptr, driver);
  const uint8_t sample[4] = {0, 1, 0, 0};
  std::string line;
  while (std::getline(std::cin, line)) {
    std::istringstream step(line);
    std::string kind;
    step >> kind;
    if (kind == "reader") {
      int key;
      step >> key;
      const rtps::EntityId_t reader{{0, 0, static_cast<uint8_t>(key)},
                                    rtps::EntityKind_t::USER_DEFINED_READER_WITHOUT_KEY};
      writer.addNewMatchedReader(
          rtps::ReaderProxy(rtps::Guid_t{remote, reader}, rtps::LocatorIPv4()));
    } else if (kind == "publish") {
      const rtps::CacheChange* change =
          writer.newChange(rtps::ChangeKind_t::ALIVE, sample, sizeof sample);
      printf("published %u\n", static_cast<unsigned>(change->sequenceNumber.low));
    } else if (kind == "work") {
      writer.progress();
    }
    printf("done\n");
    fflush(stdout);
  }
  return 0;
}
