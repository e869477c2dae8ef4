// One measurement of one side of the serialization benchmark, in a process
// of its own. Usage: bench_SIDE INSTANCE encode|decode SECONDS
// Prints the wire size and the median nanoseconds per call. table.py runs
// the sides in interleaved rounds and prints the table; `bench_SIDE list`
// names the instances (tab, then 1 for a large payload).
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
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s INSTANCE encode|decode SECONDS\n", argv[0]);
    return 2;
  }
  const int instance = std::atoi(argv[1]);
  const Operation operation = std::strcmp(argv[2], "encode") == 0 ? kEncode : kDecode;
  if (instance < 0 || instance >= kInstanceCount) return 2;
  const double nanoseconds = bench_side::nanoseconds(instance, operation, std::atof(argv[3]));
  std::printf("%zu %.3f\n", bench_side::wireSize(instance), nanoseconds);
  return 0;
}
