// genmros' half of the serialization benchmark.
#include <chrono>
#include <type_traits>
#include <vector>

#include <geometry_msgs/PoseStamped.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/String.h>

#include "instances.h"

namespace mros_side {

template <class M, int kInstance> Rates measure_type(double seconds) {
  M message;
  make(message, std::integral_constant<int, kInstance>());
  std::vector<uint8_t> buffer(message.serializedLength());
  const uint32_t size = static_cast<uint32_t>(buffer.size());
  Rates rates;
  rates.bytes = size;
  rates.encodes_per_second = rate(seconds, [&] { message.serialize(buffer.data(), size); });
  rates.decodes_per_second = rate(seconds, [&] {
    M decoded;
    decoded.deserialize(buffer.data(), size);
  });
  return rates;
}

Rates measure(int instance, double seconds) {
  switch (instance) {
    case kImage: return measure_type<sensor_msgs::Image, kImage>(seconds);
    case kPoseStamped: return measure_type<geometry_msgs::PoseStamped, kPoseStamped>(seconds);
    case kJointState: return measure_type<sensor_msgs::JointState, kJointState>(seconds);
    default: return measure_type<std_msgs::String, kString>(seconds);
  }
}

}  // namespace mros_side
