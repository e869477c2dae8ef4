// SPDX-License-Identifier: BSD-3-Clause
// The roscpp talker of bench/mros_v1_pc_bench.py, the side the real mROS v1
// library's talker (bench/mros_v1_pc/app.cpp) is compared with. Publishes COUNT messages on
// /bench, either PersonalData (score = sequence number) or a 640x480 rgb8
// sensor_msgs/Image (header.seq = sequence number), at RATE per second
// (0: as fast as publish() returns), and writes "sequence send_time_ns"
// lines (CLOCK_MONOTONIC, just before publish) to SEND_TIMES_FILE.
//
//   bench_talker personal|image COUNT RATE SEND_TIMES_FILE [remappings]
#include <ros/ros.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <unistd.h>
#include <vector>

#include <mros_test/PersonalData.h>
#include <sensor_msgs/Image.h>

namespace {

int64_t nowNs() {
  timespec now;
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<int64_t>(now.tv_sec) * 1000000000 + now.tv_nsec;
}

void setSequence(mros_test::PersonalData& message, uint32_t sequence) {
  message.score = static_cast<int32_t>(sequence);
}

void setSequence(sensor_msgs::Image& message, uint32_t sequence) { message.header.seq = sequence; }

template <class T>
int run(ros::NodeHandle& n, T& message, int count, int rate, const char* times_path) {
  ros::Publisher publisher = n.advertise<T>("/bench", 0);  // 0: no limit, nothing dropped
  sleep(2);  // the benchmark's subscriber connects meanwhile
  std::vector<int64_t> send_times(static_cast<size_t>(count));
  ros::Rate loop_rate(rate > 0 ? rate : 1);
  for (int i = 0; i < count; ++i) {
    setSequence(message, static_cast<uint32_t>(i));
    send_times[static_cast<size_t>(i)] = nowNs();
    publisher.publish(message);
    if (rate > 0) {
      loop_rate.sleep();
    }
  }
  FILE* out = std::fopen(times_path, "w");
  if (out == nullptr) {
    return 1;
  }
  for (int i = 0; i < count; ++i) {
    std::fprintf(out, "%d %lld\n", i, static_cast<long long>(send_times[static_cast<size_t>(i)]));
  }
  std::fclose(out);
  sleep(2);  // the connections drain their queues
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s personal|image COUNT RATE SEND_TIMES_FILE\n", argv[0]);
    return 2;
  }
  const std::string kind = argv[1];
  const int count = std::atoi(argv[2]);
  const int rate = std::atoi(argv[3]);
  ros::init(argc, argv, "ros_bench_talker");
  ros::NodeHandle n;
  if (kind == "image") {
    sensor_msgs::Image image;
    image.height = 480;
    image.width = 640;
    image.encoding = "rgb8";
    image.step = 640 * 3;
    image.data.assign(640 * 480 * 3, 0x5a);
    return run(n, image, count, rate, argv[4]);
  }
  mros_test::PersonalData person;
  person.first_name = "Phil";
  person.last_name = "Woods";
  person.age = 83;
  return run(n, person, count, rate, argv[4]);
}
