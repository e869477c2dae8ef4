// SPDX-License-Identifier: BSD-3-Clause
// Deterministic random field values for the genmros test harnesses.
//
// The same seed gives the same sequence in every translation unit, so a
// roscpp message and a genmros message filled from one seed hold the same
// values, on any byte order (the target CPU tests draw them on big-endian
// CPUs too). Modes choose what the peer under comparison can represent.
// C++98 and later, as the message headers.
#ifndef GENMROS_TEST_HARNESS_RANDOM_H
#define GENMROS_TEST_HARNESS_RANDOM_H

#include <stdint.h>

#include <cstring>
#include <string>

namespace harness {

template <size_t kBytes> struct UnsignedOfSize;
template <> struct UnsignedOfSize<1> { typedef uint8_t type; };
template <> struct UnsignedOfSize<2> { typedef uint16_t type; };
template <> struct UnsignedOfSize<4> { typedef uint32_t type; };
template <> struct UnsignedOfSize<8> { typedef uint64_t type; };

enum Mode {
  kBinary = 0,   // any bytes in strings, any bit patterns in floats, long arrays
  kText = 1,     // UTF-8 strings and normalized times (what genpy keeps as is)
  kCompact = 2,  // binary values, but short arrays and strings (prefix checks)
};

class Random {
 public:
  Random(uint64_t seed, int mode)
      : state_(seed * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull), mode_(mode), budget_(1200) {}

  uint64_t next() {
    state_ ^= state_ >> 12;
    state_ ^= state_ << 25;
    state_ ^= state_ >> 27;
    return state_ * 0x2545F4914F6CDD1Dull;
  }

  // Integers: mostly uniform bits, often an extreme of the type. Built as
  // unsigned numbers, so every byte order draws the same values.
  template <class T> void value(T& out) {
    typedef typename UnsignedOfSize<sizeof(T)>::type Unsigned;
    const uint64_t pick = next() % 8;
    const uint64_t bits = next();
    const Unsigned all_ones = static_cast<Unsigned>(~static_cast<Unsigned>(0));
    Unsigned candidate;
    if (pick == 0) {
      candidate = 0;
    } else if (pick == 1) {
      candidate = all_ones;
    } else if (pick == 2) {
      candidate = static_cast<Unsigned>(all_ones >> 1);  // largest signed value
    } else if (pick == 3) {
      candidate = static_cast<Unsigned>(static_cast<Unsigned>(1) << (8 * sizeof(T) - 1));  // smallest
    } else {
      candidate = static_cast<Unsigned>(bits);
    }
    std::memcpy(&out, &candidate, sizeof out);
  }

  void value(float& out) { floating<float, uint32_t>(out); }
  void value(double& out) { floating<double, uint64_t>(out); }

  void boolean(uint8_t& out) { out = static_cast<uint8_t>(next() & 1); }

  void stamp(uint32_t& sec, uint32_t& nsec) {
    value(sec);
    nsec = static_cast<uint32_t>(next() % 1000000000u);
  }

  void span(int32_t& sec, int32_t& nsec) {
    value(sec);
    nsec = static_cast<int32_t>(next() % 1000000000u);
  }

  // Element counts: empty, short, or (outside compact mode) long. Long runs
  // draw on a per-instance budget, so nested arrays stay in the kilobytes.
  size_t length() {
    const uint64_t pick = next() % 10;
    size_t count;
    if (pick < 2) {
      count = 0;
    } else if (pick < 8 || mode_ == kCompact || budget_ < kLongRunMax) {
      count = 1 + next() % 4;
    } else {
      count = 40 + next() % (kLongRunMax - 40);
    }
    budget_ = budget_ > count ? budget_ - count : 0;
    return count;
  }

  // Any string type with assignment from std::string: std::string, or
  // genmros' bounded_string (compact mode stays within 4 bytes).
  template <class Text> void text(Text& out) {
    const size_t size = length();
    std::string drawn;
    for (size_t i = 0; i < size; ++i) {
      if (mode_ == kText) {
        static const char* const pieces[] = {"a", "Z", "0", " ", "\xc3\xa9", "\xe2\x82\xac", "\n", "\""};
        drawn += pieces[next() % 8];
      } else {
        drawn += static_cast<char>(next() & 0xFF);
      }
    }
    out = drawn;
  }

 private:
  template <class F, class Bits> void floating(F& out) {
    Bits bits;
    const uint64_t pick = next() % 6;
    if (pick == 0 && mode_ != kText) {
      // NaN with a random payload: must travel bit for bit.
      bits = static_cast<Bits>(next()) | (sizeof(F) == 4 ? Bits(0x7F800001u) : Bits(0x7FF0000000000001ull));
    } else if (pick == 1) {
      bits = sizeof(F) == 4 ? Bits(0xFF800000u) : Bits(0xFFF0000000000000ull);  // -inf
    } else if (pick == 2) {
      bits = static_cast<Bits>(next() & 0xFFFF);  // denormal
    } else {
      const F plain = static_cast<F>(static_cast<int64_t>(next() % 2000001) - 1000000) / static_cast<F>(7);
      std::memcpy(&bits, &plain, sizeof bits);
    }
    std::memcpy(&out, &bits, sizeof out);
  }

  static const size_t kLongRunMax = 340;

  uint64_t state_;
  int mode_;
  size_t budget_;
};

}  // namespace harness

#endif  // GENMROS_TEST_HARNESS_RANDOM_H
