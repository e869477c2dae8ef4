// SPDX-License-Identifier: BSD-3-Clause
// The talker of bench/mros_v1_pc_bench.py as an mROS v1 app, for the real
// library on the PC target: usr_task1 publishes mros_test/PersonalData on
// /bench (score = sequence number) COUNT times at RATE per second (0: as
// fast as the library goes: the task only gives up the CPU after each
// publish, dly_tsk(0), since on ASP a task that never calls the kernel
// starves the library's own lower-priority tasks) and writes "sequence
// send_time_ns" lines (CLOCK_MONOTONIC, just before publish) to FILE, then
// ends the program. An app has no command line: MROS_BENCH="COUNT RATE FILE".
// Built with the app.cfg, app.h and Makefile beside it.
#include "app.h"
#include "ros.h"

#include <time.h>

#include <vector>

#include "mbed.h"
#include "mros_test/PersonalData.h"

static long long now_ns() {
  timespec now;
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<long long>(now.tv_sec) * 1000000000LL + now.tv_nsec;
}

void usr_task1() {
  int count = 0, rate = 0;
  char path[512];
  const char *setting = getenv("MROS_BENCH");
  if (setting == NULL || sscanf(setting, "%d %d %511s", &count, &rate, path) != 3 || rate < 0) {
    syslog(LOG_ERROR, "MROS_BENCH=\"COUNT RATE FILE\" is not set");
    exit(2);
  }
  int argc = 0;
  char *argv = NULL;
  ros::init(argc, argv, "mros_bench_talker");
  ros::NodeHandle n;
  ros::Publisher publisher = n.advertise<mros_test::PersonalData>("bench", 1);
  mros_test::PersonalData message;
  message.first_name = "Phil";
  message.last_name = "Woods";
  message.age = 83;
  std::vector<long long> send_times(count);
  wait(3.0);  // the benchmark's subscriber connects meanwhile
  long long next = now_ns();
  for (int i = 0; i < count; ++i) {
    message.score = i;
    send_times[i] = now_ns();
    publisher.publish(message);
    if (rate == 0) {
      dly_tsk(0);
      continue;
    }
    next += 1000000000LL / rate;
    long long rest_ms = (next - now_ns()) / 1000000;
    if (rest_ms > 0) dly_tsk(static_cast<RELTIM>(rest_ms));
  }
  FILE *out = fopen(path, "w");
  for (int i = 0; out != NULL && i < count; ++i) fprintf(out, "%d %lld\n", i, send_times[i]);
  if (out != NULL) fclose(out);
  wait(2.0);  // the connections drain
  exit(out != NULL ? 0 : 1);
}

void usr_task2() { slp_tsk(); }
