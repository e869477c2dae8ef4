// SPDX-License-Identifier: BSD-3-Clause
// roscpp's wire images of the instances a target CPU checks, in the target's
// report format (target_check.h), computed on the host with
// ros::serialization. Usage: expected_bytes INSTANCES MODE [MODE ...]
// (the plan of target_main.cpp).
#include <cstdlib>

#include "harness_sides.h"
#include "harness_types.inc"
#include "target_check.h"

int main(int argc, char** argv) {
  if (argc < 3) return 2;
  const uint32_t instances = static_cast<uint32_t>(std::strtoul(argv[1], nullptr, 10));
  target::Report report;
  for (int type = 0; type < kTypeCount; ++type) {
    for (uint32_t seed = 0; seed < instances; ++seed) {
      const int mode = std::atoi(argv[2 + seed % (argc - 2)]);
      const std::vector<uint8_t> wire = roscpp_side::sample(type, seed, mode);
      report.instance(kTypes[type], seed, mode, wire.data(), static_cast<uint32_t>(wire.size()));
    }
  }
  report.out.flush();
  return 0;
}
