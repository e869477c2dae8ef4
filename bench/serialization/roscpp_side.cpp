// SPDX-License-Identifier: BSD-3-Clause
// roscpp's side of the serialization benchmark.
#include <cstring>

#include <geometry_msgs/PoseStamped.h>
#include <ros/serialization.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/String.h>

#include "instances.h"
#include "measure.h"

namespace bench_side {

template <class M> uint32_t encodedSize(const M& message) {
  return ros::serialization::serializationLength(message);
}

template <class M> void encode(const M& message, uint8_t* buffer, uint32_t) {
  // roscpp sizes its stream from the message, as a publisher does.
  ros::serialization::OStream stream(buffer, ros::serialization::serializationLength(message));
  ros::serialization::serialize(stream, message);
}

template <class M> void decode(M& message, const uint8_t* buffer, uint32_t size) {
  ros::serialization::IStream stream(const_cast<uint8_t*>(buffer), size);
  ros::serialization::deserialize(stream, message);
}

#include "message_side.inc"

}  // namespace bench_side
