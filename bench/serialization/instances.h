// SPDX-License-Identifier: BSD-3-Clause
// The instances the serialization benchmark encodes and decodes. Templates,
// so one definition fills roscpp's classes and genmros' classes alike; only
// resize(), operator[] and assignment from literals, which every storage
// has (std::string/std::vector and genmros' bounded storage).
#ifndef GENMROS_BENCH_INSTANCES_H
#define GENMROS_BENCH_INSTANCES_H

#include <cstring>
#include <type_traits>

enum Instance { kImage, kPoseStamped, kJointState, kString, kInstanceCount };

// Payloads large enough that copying them is the whole cost: the memcpy
// column is measured for these.
static const bool kLargePayload[kInstanceCount] = {true, false, false, false};

static const char* const kInstanceNames[kInstanceCount] = {
    "sensor_msgs/Image 640x480 rgb8", "geometry_msgs/PoseStamped", "sensor_msgs/JointState 6 joints",
    "std_msgs/String 64 chars"};

template <class Image> void make(Image& m, std::integral_constant<int, kImage>) {
  m.header.seq = 7;
  m.header.frame_id = "camera_optical";
  m.height = 480;
  m.width = 640;
  m.encoding = "rgb8";
  m.step = 640 * 3;
  m.data.resize(640 * 480 * 3);
  std::memset(&m.data[0], 0x5a, m.data.size());
}

template <class PoseStamped> void make(PoseStamped& m, std::integral_constant<int, kPoseStamped>) {
  m.header.frame_id = "map";
  m.pose.position.x = 1.5;
  m.pose.position.y = -2.25;
  m.pose.orientation.w = 1.0;
}

template <class JointState> void make(JointState& m, std::integral_constant<int, kJointState>) {
  static const char* const kNames[] = {"joint_0", "joint_1", "joint_2", "joint_3", "joint_4", "joint_5"};
  m.header.frame_id = "base_link";
  m.name.resize(6);
  m.position.resize(6);
  m.velocity.resize(6);
  m.effort.resize(6);
  for (int i = 0; i < 6; ++i) {
    m.name[i] = kNames[i];
    m.position[i] = 0.1 * i;
    m.velocity[i] = 0.01 * i;
    m.effort[i] = 1.0 * i;
  }
}

template <class String> void make(String& m, std::integral_constant<int, kString>) {
  m.data = "xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx";  // 64 characters
}

#endif  // GENMROS_BENCH_INSTANCES_H
