// SPDX-License-Identifier: BSD-3-Clause
// How one benchmark process measures one operation: a warm-up, then batches
// of calls, and the median time per call over the batches. The compiler
// barrier keep() makes every call's result count, so no call is optimized
// away or hoisted out of the loop.
#ifndef GENMROS_BENCH_MEASURE_H
#define GENMROS_BENCH_MEASURE_H

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <vector>

enum Operation { kEncode, kDecode };

// What one side of the benchmark provides (one side per executable, so every
// side starts with a fresh allocator): the wire size of an instance, the
// median nanoseconds per call of an operation on it, and a run of exactly
// `calls` calls (under callgrind, two runs give the instructions per call).
namespace bench_side {
size_t wireSize(int instance);
double nanoseconds(int instance, Operation operation, double seconds);
void repeat(int instance, Operation operation, uint64_t calls);
}  // namespace bench_side

inline void keep(const void* pointer) { asm volatile("" : : "g"(pointer) : "memory"); }

template <class Body> double batchNanoseconds(Body& body, uint64_t calls) {
  typedef std::chrono::steady_clock Clock;
  const Clock::time_point start = Clock::now();
  for (uint64_t i = 0; i < calls; ++i) body();
  return std::chrono::duration<double, std::nano>(Clock::now() - start).count();
}

// About seconds in all: batches of at least a millisecond, the first fifth
// of the time as warm-up (caches, branch predictors, the allocator's free
// lists and its mmap threshold reach their steady state), the rest measured.
template <class Body> double medianNanoseconds(Body body, double seconds) {
  static const int kBatches = 15;
  const double batch_ns = std::max(1e6, seconds * 1e9 / (kBatches + 4));
  uint64_t calls = 1;
  while (batchNanoseconds(body, calls) < batch_ns && calls < (uint64_t(1) << 40)) calls *= 2;
  for (int i = 0; i < 3; ++i) batchNanoseconds(body, calls);
  std::vector<double> per_call;
  for (int i = 0; i < kBatches; ++i) per_call.push_back(batchNanoseconds(body, calls) / calls);
  std::nth_element(per_call.begin(), per_call.begin() + kBatches / 2, per_call.end());
  return per_call[kBatches / 2];
}

// The two ways a side measures a body (message_side.inc builds the bodies).
struct MedianTime {
  double seconds;
  template <class Body> double operator()(Body body) const { return medianNanoseconds(body, seconds); }
};
struct ExactCalls {
  uint64_t calls;
  template <class Body> double operator()(Body body) const {
    for (uint64_t i = 0; i < calls; ++i) body();
    return 0;
  }
};

#endif  // GENMROS_BENCH_MEASURE_H
