// Serialization speed of genmros' headers against roscpp's, measured side by
// side in one run. Usage: bench_serialization [SECONDS_PER_MEASUREMENT]
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "instances.h"

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 0.5;
  std::printf("| %-32s | %8s | %14s | %14s | %6s | %14s | %14s | %6s |\n", "message", "bytes", "roscpp enc/s",
              "genmros enc/s", "ratio", "roscpp dec/s", "genmros dec/s", "ratio");
  std::printf("|%s|---------:|---------------:|---------------:|-------:|---------------:|---------------:|-------:|\n",
              "----------------------------------");
  for (int instance = 0; instance < kInstanceCount; ++instance) {
    const Rates roscpp = roscpp_side::measure(instance, seconds);
    const Rates mros = mros_side::measure(instance, seconds);
    if (roscpp.bytes != mros.bytes) {
      std::printf("sizes differ for %s: %zu vs %zu\n", kInstanceNames[instance], roscpp.bytes, mros.bytes);
      return 1;
    }
    std::printf("| %-32s | %8zu | %14.0f | %14.0f | %5.2fx | %14.0f | %14.0f | %5.2fx |\n", kInstanceNames[instance],
                mros.bytes, roscpp.encodes_per_second, mros.encodes_per_second,
                mros.encodes_per_second / roscpp.encodes_per_second, roscpp.decodes_per_second,
                mros.decodes_per_second, mros.decodes_per_second / roscpp.decodes_per_second);
  }
  return 0;
}
