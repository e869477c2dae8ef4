// SPDX-License-Identifier: BSD-3-Clause
// The receiving roscpp node of bench/mros_v1_pc_bench.py: subscribes /bench
// (PersonalData or Image, TCP_NODELAY), stamps every message on arrival in
// its callback (CLOCK_MONOTONIC) and, after COUNT messages or IDLE_S seconds
// without one, writes "sequence receive_time_ns" lines to RECEIVE_TIMES_FILE.
//
//   bench_listener personal|image COUNT IDLE_S RECEIVE_TIMES_FILE
#include <mros_test/PersonalData.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <utility>
#include <vector>

namespace {

std::vector<std::pair<uint32_t, int64_t> > arrivals;
size_t expected = 0;
ros::WallTime last_arrival;

int64_t nowNs() {
  timespec now;
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<int64_t>(now.tv_sec) * 1000000000 + now.tv_nsec;
}

void record(uint32_t sequence) {
  arrivals.emplace_back(sequence, nowNs());
  last_arrival = ros::WallTime::now();
  if (arrivals.size() >= expected) {
    ros::shutdown();
  }
}

void onPerson(const mros_test::PersonalData::ConstPtr& message) {
  record(static_cast<uint32_t>(message->score));
}

void onImage(const sensor_msgs::Image::ConstPtr& message) { record(message->header.seq); }

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "ros_bench_listener");
  if (argc < 5) {
    ROS_FATAL("usage: bench_listener personal|image COUNT IDLE_S RECEIVE_TIMES_FILE");
    return 2;
  }
  const std::string kind = argv[1];
  expected = static_cast<size_t>(std::atoi(argv[2]));
  const double idle_s = std::atof(argv[3]);
  arrivals.reserve(expected);
  ros::NodeHandle n;
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  ros::Subscriber sub = kind == "image" ? n.subscribe("/bench", 0, onImage, hints)
                                        : n.subscribe("/bench", 0, onPerson, hints);
  last_arrival = ros::WallTime::now();
  ros::WallTimer idle_check = n.createWallTimer(ros::WallDuration(0.2), [idle_s](const ros::WallTimerEvent&) {
    if (!arrivals.empty() && (ros::WallTime::now() - last_arrival).toSec() > idle_s) {
      ros::shutdown();
    }
  });
  ros::spin();
  FILE* out = std::fopen(argv[4], "w");
  if (out == nullptr) {
    return 1;
  }
  for (const auto& arrival : arrivals) {
    std::fprintf(out, "%u %lld\n", arrival.first, static_cast<long long>(arrival.second));
  }
  std::fclose(out);
  return 0;
}
