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

template <class M> uint32_t encodedSize(const M& message) { return message.serializedLength(); }

template <class M> void encode(const M& message, uint8_t* buffer, uint32_t size) {
  message.serialize(buffer, size);
}

template <class M> void decode(M& message, const uint8_t* buffer, uint32_t size) {
  message.deserialize(buffer, size);
}

#include "measure.inc"

}  // namespace mros_side
