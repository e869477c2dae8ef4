// SPDX-License-Identifier: BSD-3-Clause
// The footprint benchmark's baseline: start-up, the C library stubs and a
// task that uses no message type. Its size is subtracted from every row.
#include <string>

#include "library.h"

extern "C" void api_deliver(unsigned, void (*)(void*), const char*, unsigned) {}

// Topic names travel as std::string in the mROS v1 API, whatever the type.
static void topic(std::string name) {
  unsigned topic_id;
  library_topic_create(name.c_str(), 0, &topic_id);
}

int main() {
  topic("bench");
  topic("bench");
  library_run();
  return 0;
}
