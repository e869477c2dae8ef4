// SPDX-License-Identifier: BSD-3-Clause
// Holds genmros' headers against roscpp, type by type:
//   - MD5 sum, data type and definition text equal roscpp's traits;
//   - for many seeds, genmros' wire image equals roscpp's byte for byte;
//   - genmros parses roscpp's bytes, consuming all of them, and re-encodes
//     them unchanged (so every value was reproduced).
// Usage: compare_with_roscpp INSTANCES_PER_TYPE. Prints one line per
// mismatch and a summary; exits 1 on any mismatch.
#include <cstdio>
#include <cstdlib>

#include "harness_random.h"
#include "harness_sides.h"
#include "harness_types.inc"

static int failures = 0;

static void fail(const char* type, const char* what, uint64_t seed, const std::vector<uint8_t>& expected,
                 const std::vector<uint8_t>& actual) {
  size_t offset = 0;
  while (offset < expected.size() && offset < actual.size() && expected[offset] == actual[offset]) ++offset;
  std::printf("MISMATCH %s %s seed=%llu roscpp_size=%zu genmros_size=%zu first_difference=%zu\n", type, what,
              static_cast<unsigned long long>(seed), expected.size(), actual.size(), offset);
  ++failures;
}

static void compare_identity(const char* type, const Identity& expected, const Identity& actual) {
  if (expected.md5sum != actual.md5sum) {
    std::printf("MISMATCH %s md5sum roscpp=%s genmros=%s\n", type, expected.md5sum.c_str(), actual.md5sum.c_str());
    ++failures;
  }
  if (expected.datatype != actual.datatype) {
    std::printf("MISMATCH %s datatype roscpp=%s genmros=%s\n", type, expected.datatype.c_str(),
                actual.datatype.c_str());
    ++failures;
  }
  if (expected.definition != actual.definition) {
    std::printf("MISMATCH %s definition\n", type);
    ++failures;
  }
}

int main(int argc, char** argv) {
  const uint64_t instances = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 200;
  uint64_t compared = 0;
  uint64_t bytes = 0;
  for (int type = 0; type < kTypeCount; ++type) {
    compare_identity(kTypes[type], roscpp_side::identity(type), mros_side::identity(type));
    for (uint64_t seed = 0; seed < instances; ++seed) {
      const int mode = seed % 2 == 0 ? harness::kBinary : harness::kText;
      const std::vector<uint8_t> expected = roscpp_side::sample(type, seed, mode);
      const std::vector<uint8_t> actual = mros_side::sample(type, seed, mode);
      if (expected != actual) fail(kTypes[type], "serialize", seed, expected, actual);
      std::vector<uint8_t> reencoded;
      const int32_t consumed =
          mros_side::reencode(type, expected.data(), static_cast<uint32_t>(expected.size()), reencoded);
      if (consumed != static_cast<int32_t>(expected.size()) || reencoded != expected) {
        fail(kTypes[type], "deserialize", seed, expected, reencoded);
      }
      ++compared;
      bytes += expected.size();
    }
  }
  for (int service = 0; service < kServiceCount; ++service) {
    compare_identity(kServices[service], roscpp_side::service_identity(service),
                     mros_side::service_identity(service));
  }
  std::printf("compared %d types, %d services, %llu instances, %llu bytes: %d mismatches\n", kTypeCount,
              kServiceCount, static_cast<unsigned long long>(compared), static_cast<unsigned long long>(bytes),
              failures);
  return failures == 0 ? 0 : 1;
}
