// The instances the serialization benchmark encodes and decodes. Templates,
// so one definition fills roscpp's classes and genmros' classes alike.
#ifndef GENMROS_BENCH_INSTANCES_H
#define GENMROS_BENCH_INSTANCES_H

#include <cstdint>
#include <string>

enum Instance { kImage, kPoseStamped, kJointState, kString, kInstanceCount };

static const char* const kInstanceNames[] = {"sensor_msgs/Image 640x480 rgb8", "geometry_msgs/PoseStamped",
                                             "sensor_msgs/JointState 6 joints", "std_msgs/String 64 chars"};

template <class Image> void make(Image& m, std::integral_constant<int, kImage>) {
  m.header.seq = 7;
  m.header.frame_id = "camera_optical";
  m.height = 480;
  m.width = 640;
  m.encoding = "rgb8";
  m.step = 640 * 3;
  m.data.assign(640 * 480 * 3, 0x5a);
}

template <class PoseStamped> void make(PoseStamped& m, std::integral_constant<int, kPoseStamped>) {
  m.header.frame_id = "map";
  m.pose.position.x = 1.5;
  m.pose.position.y = -2.25;
  m.pose.orientation.w = 1.0;
}

template <class JointState> void make(JointState& m, std::integral_constant<int, kJointState>) {
  m.header.frame_id = "base_link";
  for (int i = 0; i < 6; ++i) {
    m.name.push_back("joint_" + std::to_string(i));
    m.position.push_back(0.1 * i);
    m.velocity.push_back(0.01 * i);
    m.effort.push_back(1.0 * i);
  }
}

template <class String> void make(String& m, std::integral_constant<int, kString>) { m.data.assign(64, 'x'); }

struct Rates {
  double encodes_per_second;
  double decodes_per_second;
  size_t bytes;
};

// Runs body repeatedly for about seconds; returns calls per second.
template <class Body> double rate(double seconds, Body body) {
  typedef std::chrono::steady_clock Clock;
  const Clock::time_point start = Clock::now();
  uint64_t calls = 0;
  double elapsed = 0;
  do {
    for (int i = 0; i < 64; ++i) body();
    calls += 64;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  } while (elapsed < seconds);
  return calls / elapsed;
}

namespace roscpp_side {
Rates measure(int instance, double seconds);
}
namespace mros_side {
Rates measure(int instance, double seconds);
}

#endif  // GENMROS_BENCH_INSTANCES_H
