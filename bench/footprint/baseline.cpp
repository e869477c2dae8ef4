// The footprint benchmark's baseline: start-up, the C library stubs and a
// task that uses no message type. Its size is subtracted from every row.
#include <string>

#include "library.h"

extern "C" void api_deliver(int, void (*)(void*), const char*) {}

// Topic names travel as std::string in the mROS v1 API, whatever the type.
static void* topic(std::string name) { return library_topic(name.c_str(), 0, 0, 0, 0); }

int main() {
  topic("bench");
  library_subscribe(topic("bench"), 0);
  library_run();
  return 0;
}
