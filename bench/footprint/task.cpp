// SPDX-License-Identifier: BSD-3-Clause
// One mROS task that publishes and subscribes BENCH_TYPE (from BENCH_HEADER),
// and main(), which runs it and lets the library deliver the frame.
#include "ros.h"

#include "library.h"
#include BENCH_HEADER

extern "C" void bench_sink(const void* received);

static void onMessage(BENCH_TYPE* message) { bench_sink(message); }

static BENCH_TYPE message;

int main() {
  ros::NodeHandle node;
  ros::Subscriber subscriber = node.subscribe("bench", 1, onMessage);
  ros::Publisher publisher = node.advertise<BENCH_TYPE>("bench", 1);
  (void)subscriber;
  publisher.publish(message);
  library_run();
  return 0;
}
