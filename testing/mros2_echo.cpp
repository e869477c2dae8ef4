// SPDX-License-Identifier: BSD-3-Clause
// The echo program of the mros2 byte-exact tests (testing/mros2_harness.py
// compiles it with the generated headers of the types it lists in
// MROS2_ECHO_TYPES.h). For each input line "TYPE_INDEX FRAGMENT_SIZE HEX",
// HEX a whole sample (encapsulation header first), it decodes the sample
// with the checked copyFromBuf and writes it back the ways mros2's runtime
// (src/mros2.cpp, v0.5.4) publishes, printing one line:
//   "refused", or
//   "RAW WHOLE FRAGMENTED AGAIN" (hex): RAW the header and copyToBuf's
//   bytes alone (what Fast-CDR and rosbags write), WHOLE what copyToBuf,
//   memAlign and getTotalSize send, FRAGMENTED what copyToFragBuf sends in
//   FRAGMENT_SIZE-byte fragments driven as the runtime drives it, AGAIN
//   the same message published once more through the path its size takes.
// With the argument "names" it prints the DDS type name of each type
// (message_traits::TypeName), one per line, instead.
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <iostream>
#include <string>
#include <vector>

#include MROS2_ECHO_TYPES_HEADER

typedef std::vector<uint8_t> Bytes;

static std::string hex(const Bytes& bytes) {
  static const char digits[] = "0123456789abcdef";
  std::string text;
  for (size_t i = 0; i < bytes.size(); ++i) {
    text += digits[bytes[i] >> 4];
    text += digits[bytes[i] & 15];
  }
  return text;
}

static const uint8_t kHeader[4] = {0, 1, 0, 0};

// What the runtime's small-message path sends (its buf is 100 bytes there;
// here as large as the message needs).
template <class T> static Bytes publish_whole(T& msg, bool raw) {
  Bytes buffer(msg.calcTotalSize() + 4);
  memcpy(&buffer[0], kHeader, 4);
  msg.copyToBuf(&buffer[4]);
  if (raw) {
    buffer.resize(4 + msg.getTotalSize());
    return buffer;
  }
  msg.memAlign(&buffer[4]);
  buffer.resize(msg.getTotalSize() + 4);
  return buffer;
}

// The runtime's fragment callback, called until the message says it is done
// and wrote nothing (then the runtime resets its count).
template <class T> static Bytes publish_fragmented(T& msg, uint32_t fragment_size) {
  Bytes sent;
  uint32_t announced = msg.calcTotalSize();
  std::vector<uint8_t> fragment(fragment_size + 4);
  for (int calls = 0; calls < 1000000; ++calls) {
    uint32_t offset = 0;
    if (msg.getPubCnt() == 0) {
      offset = 4;
      memcpy(&fragment[0], kHeader, 4);
    }
    typename T::FragCopyReturnType done = msg.copyToFragBuf(&fragment[offset], fragment_size - offset);
    uint32_t length = done.second + offset;
    if (done.first) {
      if (done.second > 0) {
        while (length % 4) fragment[length++] = 0;
      } else {
        msg.resetCount();
      }
    }
    sent.insert(sent.end(), fragment.begin(), fragment.begin() + length);
    if (done.first && done.second == 0) break;
  }
  if (sent.size() != announced) {
    std::cerr << "calcTotalSize() said " << announced << ", fragments sent " << sent.size() << "\n";
  }
  return sent;
}

template <class T> static void echo(const Bytes& sample, uint32_t fragment_size) {
  T msg;
  if (sample.size() < 4 || !msg.copyFromBuf(&sample[4], static_cast<uint32_t>(sample.size() - 4))) {
    std::cout << "refused\n";
    return;
  }
  Bytes raw = publish_whole(msg, true);
  Bytes whole = publish_whole(msg, false);
  Bytes fragmented = publish_fragmented(msg, fragment_size);
  // The second publication takes the runtime's path for the size (100: its buf).
  Bytes again = msg.calcTotalSize() > 100 ? publish_fragmented(msg, fragment_size)
                                          : publish_whole(msg, false);
  std::cout << hex(raw) << ' ' << hex(whole) << ' ' << hex(fragmented) << ' ' << hex(again)
            << "\n";
}

template <class T> static const char* type_name() { return message_traits::TypeName<T*>::value(); }

typedef void (*Echo)(const Bytes&, uint32_t);
static const Echo kEchoes[] = {MROS2_ECHO_FUNCTIONS};
typedef const char* (*TypeNameOf)();
static const TypeNameOf kTypeNames[] = {MROS2_ECHO_TYPE_NAMES};

int main(int argc, char** argv) {
  if (argc == 2 && strcmp(argv[1], "names") == 0) {
    for (size_t i = 0; i < sizeof kTypeNames / sizeof kTypeNames[0]; ++i)
      std::cout << kTypeNames[i]() << "\n";
    return 0;
  }
  std::string line;
  while (std::getline(std::cin, line)) {
    size_t type_index = 0;
    unsigned fragment_size = 0;
    char text[1 << 20];
    if (line.size() >= sizeof text) return 2;
    int fields = sscanf(line.c_str(), "%zu %u %s", &type_index, &fragment_size, text);
    if (fields < 2 || type_index >= sizeof kEchoes / sizeof kEchoes[0]) return 2;
    Bytes sample;
    for (size_t i = 0; fields == 3 && text[i] && text[i + 1]; i += 2) {
      char pair[3] = {text[i], text[i + 1], 0};
      sample.push_back(static_cast<uint8_t>(strtoul(pair, 0, 16)));
    }
    kEchoes[type_index](sample, fragment_size);
    std::cout.flush();
  }
  return 0;
}
