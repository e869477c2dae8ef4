// Deterministic random field values for the genmros test harnesses.
//
// The same seed gives the same sequence in every translation unit, so a
// roscpp message and a genmros message filled from one seed hold the same
// values. Modes choose what the peer under comparison can represent.
#ifndef GENMROS_TEST_HARNESS_RANDOM_H
#define GENMROS_TEST_HARNESS_RANDOM_H

#include <cstdint>
#include <cstring>
#include <string>

namespace harness {

enum Mode {
  kBinary = 0,   // any bytes in strings, any bit patterns in floats, long arrays
  kText = 1,     // UTF-8 strings and normalized times (what genpy keeps as is)
  kCompact = 2,  // binary values, but short arrays and strings (prefix checks)
};

class Random {
 public:
  Random(uint64_t seed, int mode) : state_(seed * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull), mode_(mode) {}

  uint64_t next() {
    state_ ^= state_ >> 12;
    state_ ^= state_ << 25;
    state_ ^= state_ >> 27;
    return state_ * 0x2545F4914F6CDD1Dull;
  }

  // Integers: mostly uniform bits, often an extreme of the type.
  template <class T> void value(T& out) {
    const uint64_t pick = next() % 8;
    const uint64_t bits = next();
    T candidate;
    if (pick == 0) {
      std::memset(&candidate, 0, sizeof candidate);
    } else if (pick == 1) {
      std::memset(&candidate, 0xFF, sizeof candidate);
    } else if (pick == 2) {
      std::memset(&candidate, 0xFF, sizeof candidate);
      reinterpret_cast<uint8_t*>(&candidate)[sizeof candidate - 1] = 0x7F;
    } else if (pick == 3) {
      std::memset(&candidate, 0, sizeof candidate);
      reinterpret_cast<uint8_t*>(&candidate)[sizeof candidate - 1] = 0x80;
    } else {
      std::memcpy(&candidate, &bits, sizeof candidate);
    }
    out = candidate;
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

  void text(std::string& out) {
    const size_t size = length();
    out.clear();
    for (size_t i = 0; i < size; ++i) {
      if (mode_ == kText) {
        static const char* const pieces[] = {"a", "Z", "0", " ", "\xc3\xa9", "\xe2\x82\xac", "\n", "\""};
        out += pieces[next() % 8];
      } else {
        out += static_cast<char>(next() & 0xFF);
      }
    }
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
  size_t budget_ = 1200;
};

}  // namespace harness

#endif  // GENMROS_TEST_HARNESS_RANDOM_H
