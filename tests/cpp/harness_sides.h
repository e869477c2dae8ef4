// SPDX-License-Identifier: BSD-3-Clause
// The two sides a harness compares: roscpp's classes and genmros' classes,
// each compiled in its own translation unit (they share names and
// namespaces), reached through type indexes.
#ifndef GENMROS_TEST_HARNESS_SIDES_H
#define GENMROS_TEST_HARNESS_SIDES_H

#include <cstdint>
#include <string>
#include <vector>

struct Identity {
  std::string md5sum;
  std::string datatype;
  std::string definition;
};

namespace roscpp_side {
std::vector<uint8_t> sample(int type, uint64_t seed, int mode);
Identity identity(int type);
Identity service_identity(int service);
}  // namespace roscpp_side

namespace mros_side {
std::vector<uint8_t> sample(int type, uint64_t seed, int mode);
int32_t reencode(int type, const uint8_t* input, uint32_t size, std::vector<uint8_t>& out);
Identity identity(int type);
Identity service_identity(int service);
}  // namespace mros_side

#endif  // GENMROS_TEST_HARNESS_SIDES_H
