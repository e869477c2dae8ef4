// SPDX-License-Identifier: BSD-3-Clause
// A unit check of mros2's real src/mros2.cpp, as it is or with genmros'
// patch series, against the embeddedRTPS stand-in (rtps/rtps.h): two
// publishers publish once each (one sample over mros2's 100-byte buffer, so
// in fragments), then samples are delivered to two subscribers as
// embeddedRTPS' reader would: a whole one, then a short, a corrupt, a
// big-endian and a 2-byte one. It prints each sent sample (topic, type
// name, bytes), how many samples the callbacks got and, where the library
// counts them (CHECK_DROPPED_SAMPLES), how many it dropped.
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "mros2.h"
#include "test_interface_files/msg/basic_types.hpp"
#include "test_interface_files/msg/strings.hpp"

namespace {
int delivered;
void on_basic(test_interface_files::msg::BasicTypes*) { ++delivered; }
void on_strings(test_interface_files::msg::Strings*) { ++delivered; }

// Samples lie at the start of a zeroed block larger than any read the
// unsized copyFromBuf may make, so the library as it is reads no memory
// it does not own: what the check shows is what it delivers.
uint8_t room[70000];

template <class T> uint32_t image(T& msg, bool little_endian) {
  memset(room, 0, sizeof room);
  room[1] = little_endian ? 1 : 0;
  msg.copyToBuf(&room[4]);
  return 4 + msg.calcRawTotalSize();
}

void deliver(size_t reader, uint32_t size) {
  rtps::Domain::readers()[reader]->deliver(room, static_cast<rtps::DataSize_t>(size));
}
}  // namespace

int main() {
  mros2::init(0, NULL);
  mros2::Node node = mros2::Node::create_node("library_check");
  mros2::Publisher alpha =
      node.create_publisher<test_interface_files::msg::BasicTypes>("alpha", 10);
  mros2::Publisher beta = node.create_publisher<test_interface_files::msg::Strings>("beta", 10);
  node.create_subscription("gamma", 10, on_basic);
  node.create_subscription("delta", 10, on_strings);

  test_interface_files::msg::BasicTypes basic;
  basic.int32_value = -123456;
  test_interface_files::msg::Strings strings;
  strings.string_value = std::string(150, 'x');
  alpha.publish(basic);
  beta.publish(strings);
  for (size_t i = 0; i < rtps::sent_samples().size(); ++i) {
    const rtps::Sent& sent = rtps::sent_samples()[i];
    printf("sent %s %s ", sent.topic.c_str(), sent.type_name.c_str());
    for (size_t j = 0; j < sent.bytes.size(); ++j) printf("%02x", sent.bytes[j]);
    printf("\n");
  }

  deliver(0, image(basic, true));                // whole
  deliver(0, image(basic, true) - 8);            // short
  image(strings, true);
  room[4] = room[5] = room[6] = room[7] = 0xff;  // corrupt: a string longer than the sample
  deliver(1, 4 + strings.calcRawTotalSize());
  deliver(0, image(basic, false));               // big-endian CDR
  deliver(0, 2);                                 // no whole encapsulation header
  printf("delivered %d\n", delivered);
#ifdef CHECK_DROPPED_SAMPLES
  printf("dropped %u\n", static_cast<unsigned>(mros2::Subscriber::dropped_samples));
#endif
  fflush(stdout);
  _exit(0);  // mros2's init task still waits for a match
}
