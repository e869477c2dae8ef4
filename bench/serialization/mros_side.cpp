// SPDX-License-Identifier: BSD-3-Clause
// genmros' side of the serialization benchmark (heap storage; built against
// a bounded export, the bounded side; with BENCH_BARE_MEMCPY, the memcpy
// floor of the same wire images).
#include <cstring>

#include <geometry_msgs/PoseStamped.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/String.h>

#include "instances.h"
#include "measure.h"

namespace bench_side {

template <class M> uint32_t encodedSize(const M& message) { return message.serializedLength(); }

template <class M> void encode(const M& message, uint8_t* buffer, uint32_t size) {
  message.serialize(buffer, size);
}

template <class M> void decode(M& message, const uint8_t* buffer, uint32_t size) {
  message.deserialize(buffer, size);
}

#include "message_side.inc"

}  // namespace bench_side
