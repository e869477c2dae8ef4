// SPDX-License-Identifier: BSD-3-Clause
// What every target CPU checks on genmros' classes, one random instance at a
// time, and the line format in which it reports the wire images:
//
//   case TYPE SEED MODE SIZE HEX      the instance's wire image
//   FAIL TYPE SEED MODE WHAT          a check that failed on the target
//   checked N instances, P prefixes: F failures
//
// The host prints roscpp's images of the same instances in the same format
// (expected_bytes.cpp), and the test compares the two. The instance is built
// on the target through genmros' classes (the fill functions of
// cpp_harness.py over harness_random.h, the same seeds as on the host), and
// the target serializes it itself. C++98 and later, no exceptions, no RTTI,
// no stdio (bare-metal boards write through newlib's semihosting write()).
#ifndef GENMROS_TEST_TARGET_CHECK_H
#define GENMROS_TEST_TARGET_CHECK_H

#include <stdint.h>
#include <string.h>
#include <unistd.h>

#include <vector>

#include "harness_random.h"

namespace target {

// Buffered text on standard output.
class Output {
 public:
  Output() : used_(0) {}
  ~Output() { flush(); }

  void text(const char* characters) {
    while (*characters != '\0') put(*characters++);
  }

  void number(uint32_t value) {
    char digits[10];
    int count = 0;
    do {
      digits[count++] = static_cast<char>('0' + value % 10);
      value /= 10;
    } while (value != 0);
    while (count > 0) put(digits[--count]);
  }

  void hex(const uint8_t* bytes, uint32_t size) {
    static const char kDigits[] = "0123456789abcdef";
    for (uint32_t i = 0; i < size; ++i) {
      put(kDigits[bytes[i] >> 4]);
      put(kDigits[bytes[i] & 15]);
    }
    if (size == 0) put('-');
  }

  void put(char character) {
    if (used_ == sizeof buffer_) flush();
    buffer_[used_++] = character;
  }

  void flush() {
    size_t done = 0;
    while (done < used_) {
      const ssize_t written = write(1, buffer_ + done, used_ - done);
      if (written <= 0) break;
      done += static_cast<size_t>(written);
    }
    used_ = 0;
  }

 private:
  char buffer_[512];
  size_t used_;
};

struct Report {
  Output out;
  uint32_t instances;
  uint32_t prefixes;
  uint32_t failures;

  Report() : instances(0), prefixes(0), failures(0) {}

  void instance(const char* type, uint32_t seed, int mode, const uint8_t* wire, uint32_t size) {
    line("case ", type, seed, mode);
    out.number(size);
    out.put(' ');
    out.hex(wire, size);
    out.put('\n');
    ++instances;
  }

  void fail(const char* type, uint32_t seed, int mode, const char* what) {
    line("FAIL ", type, seed, mode);
    out.text(what);
    out.put('\n');
    ++failures;
  }

  void summary() {
    out.text("checked ");
    out.number(instances);
    out.text(" instances, ");
    out.number(prefixes);
    out.text(" prefixes: ");
    out.number(failures);
    out.text(" failures\n");
    out.flush();
  }

 private:
  // The start every line about one instance has: tag, type, seed and mode.
  void line(const char* tag, const char* type, uint32_t seed, int mode) {
    out.text(tag);
    out.text(type);
    out.put(' ');
    out.number(seed);
    out.put(' ');
    out.number(static_cast<uint32_t>(mode));
    out.put(' ');
  }
};

// One instance of M: serialize (exactly into its size, refused one byte
// short), report the image, deserialize it completely, serialize again to
// the same bytes, the same through the mROS v1 interface (dataSize, memCopy,
// deserialize(char*&)), and (compact instances) refuse every proper prefix
// with -1. Each message lives in its own block: the Cortex-M0 board has
// 16 KB of RAM.
template <class M>
void checkInstance(void (*fill)(M&, harness::Random&), const char* type, uint32_t seed, int mode,
                   Report& report) {
  std::vector<uint8_t> wire;
  {
    M message;
    harness::Random random(seed, mode);
    fill(message, random);
    const uint32_t size = message.serializedLength();
    // One guard byte past the image: nothing may be written there.
    wire.assign(size + 1, 0xA5);
    if (message.serialize(&wire[0], size) != static_cast<int32_t>(size) || wire[size] != 0xA5) {
      report.fail(type, seed, mode, "serialize");
    }
    if (size > 0 && message.serialize(&wire[0], size - 1) != -1) {
      report.fail(type, seed, mode, "serialize into a buffer one byte short");
    }
  }
  const uint32_t size = static_cast<uint32_t>(wire.size() - 1);
  report.instance(type, seed, mode, &wire[0], size);

  std::vector<uint8_t> again(size + 1, 0);
  {
    M decoded;
    if (decoded.deserialize(&wire[0], size) != static_cast<int32_t>(size)) {
      report.fail(type, seed, mode, "deserialize");
    } else if (decoded.serialize(&again[0], size) != static_cast<int32_t>(size) ||
               memcmp(&again[0], &wire[0], size) != 0) {
      report.fail(type, seed, mode, "serialize after deserialize");
    }
    if (decoded.dataSize() != static_cast<int>(size)) report.fail(type, seed, mode, "dataSize");
    char* cursor = reinterpret_cast<char*>(&again[0]);
    decoded.memCopy(cursor);
    if (cursor != reinterpret_cast<char*>(&again[0]) + size || memcmp(&again[0], &wire[0], size) != 0) {
      report.fail(type, seed, mode, "memCopy");
    }
  }
  {
    M copied;
    char* cursor = reinterpret_cast<char*>(&again[0]);
    copied.deserialize(cursor);
    if (cursor != reinterpret_cast<char*>(&again[0]) + size || copied.serializedLength() != size) {
      report.fail(type, seed, mode, "deserialize(char*&)");
    }
  }

  // Every prefix costs a parse of up to size bytes: compact instances only,
  // so the emulated CPUs finish in seconds.
  for (uint32_t prefix = 0; mode == harness::kCompact && prefix < size; ++prefix, ++report.prefixes) {
    M truncated;
    if (truncated.deserialize(&wire[0], prefix) != -1) {
      report.fail(type, seed, mode, "proper prefix accepted");
      break;
    }
  }
}

}  // namespace target

#endif  // GENMROS_TEST_TARGET_CHECK_H
