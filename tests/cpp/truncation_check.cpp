// SPDX-License-Identifier: BSD-3-Clause
// Feeds genmros' deserialize every proper prefix of valid wire images, each
// in a heap block of exactly that size (so AddressSanitizer sees any read
// past it), and random corruptions of them. Every prefix must be refused
// with -1; corrupted input may parse or not, but must stay in bounds.
// Usage: truncation_check INSTANCES_PER_TYPE. Exits 1 on a failure.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "harness_random.h"
#include "harness_sides.h"
#include "harness_types.inc"

static int32_t parse_copy(int type, const std::vector<uint8_t>& bytes, size_t size) {
  std::unique_ptr<uint8_t[]> block(new uint8_t[size == 0 ? 1 : size]);
  if (size != 0) std::memcpy(block.get(), bytes.data(), size);
  std::vector<uint8_t> reencoded;
  return mros_side::reencode(type, block.get(), static_cast<uint32_t>(size), reencoded);
}

int main(int argc, char** argv) {
  const uint64_t instances = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 5;
  int failures = 0;
  uint64_t prefixes = 0;
  uint64_t corruptions = 0;
  for (int type = 0; type < kTypeCount; ++type) {
    for (uint64_t seed = 0; seed < instances; ++seed) {
      const std::vector<uint8_t> bytes = mros_side::sample(type, seed, harness::kCompact);
      if (parse_copy(type, bytes, bytes.size()) != static_cast<int32_t>(bytes.size())) {
        std::printf("FAIL %s seed=%llu: complete image refused\n", kTypes[type], static_cast<unsigned long long>(seed));
        ++failures;
      }
      for (size_t size = 0; size < bytes.size(); ++size, ++prefixes) {
        if (parse_copy(type, bytes, size) != -1) {
          std::printf("FAIL %s seed=%llu: prefix of %zu/%zu bytes accepted\n", kTypes[type],
                      static_cast<unsigned long long>(seed), size, bytes.size());
          ++failures;
          break;
        }
      }
      harness::Random noise(seed + 7919u * static_cast<uint64_t>(type), harness::kBinary);
      for (int round = 0; round < 20 && !bytes.empty(); ++round, ++corruptions) {
        std::vector<uint8_t> corrupted = bytes;
        corrupted[noise.next() % corrupted.size()] = static_cast<uint8_t>(noise.next());
        corrupted[noise.next() % corrupted.size()] = 0xFF;
        parse_copy(type, corrupted, corrupted.size());
      }
    }
  }
  std::printf("checked %d types: %llu prefixes, %llu corruptions: %d failures\n", kTypeCount,
              static_cast<unsigned long long>(prefixes), static_cast<unsigned long long>(corruptions), failures);
  return failures == 0 ? 0 : 1;
}
