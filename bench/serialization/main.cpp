// SPDX-License-Identifier: BSD-3-Clause
// One measurement of one side of the serialization benchmark, in a process
// of its own. table.py runs the sides and prints the tables.
//   bench_SIDE list                                  the instances (tab, then 1 for a large payload)
//   bench_SIDE time INSTANCE encode|decode SECONDS HEAP_SHIFT
//                                                    wire size, median nanoseconds per call
//   bench_SIDE repeat INSTANCE encode|decode CALLS   exactly CALLS calls, for callgrind
//
// HEAP_SHIFT bytes are allocated, and kept, before anything is measured.
// Where a decoded string lands relative to cache lines and to the stack
// decides its cost more than either library does: the same decode of a
// 64-character std_msgs/String takes 16 ns or 29 ns depending on the bytes
// allocated before it, for roscpp and genmros alike. Each executable starts
// from a different heap (roscpp's libraries allocate at start-up), so one
// fixed layout per side would measure the layouts. table.py gives both sides
// the same shift in a round and a different shift each round.
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "instances.h"
#include "measure.h"

int main(int argc, char** argv) {
  if (argc == 2 && std::strcmp(argv[1], "list") == 0) {
    for (int instance = 0; instance < kInstanceCount; ++instance) {
      std::printf("%s\t%d\n", kInstanceNames[instance], kLargePayload[instance] ? 1 : 0);
    }
    return 0;
  }
  const bool timed = argc == 6 && std::strcmp(argv[1], "time") == 0;
  if (!timed && !(argc == 5 && std::strcmp(argv[1], "repeat") == 0)) {
    std::fprintf(stderr,
                 "usage: %s list | time INSTANCE encode|decode SECONDS HEAP_SHIFT"
                 " | repeat INSTANCE encode|decode CALLS\n",
                 argv[0]);
    return 2;
  }
  const int instance = std::atoi(argv[2]);
  const Operation operation = std::strcmp(argv[3], "encode") == 0 ? kEncode : kDecode;
  if (instance < 0 || instance >= kInstanceCount) return 2;
  if (!timed) {
    bench_side::repeat(instance, operation, std::strtoull(argv[4], 0, 10));
    return 0;
  }
  void* const volatile heap_shift = std::malloc(static_cast<size_t>(std::atoi(argv[5])));
  const double nanoseconds = bench_side::nanoseconds(instance, operation, std::atof(argv[4]));
  std::printf("%zu %.3f\n", bench_side::wireSize(instance), nanoseconds);
  std::free(heap_shift);
  return 0;
}
