// SPDX-License-Identifier: BSD-3-Clause
// The samples the main job's mros2 boards publish (evaluation/ros2_peer.py
// holds the same values in Python): sample `number` of chatter, image (200
// bytes of pixels: over mros2's 100-byte buffer, so sent in fragments) and
// reading. Used by the stand-in board (board_ros2.cpp) and by the mros2 app
// (evaluation/mros2_app), which runs on mros2 itself.
#ifndef EVALUATION_BOARD_SAMPLES_HPP
#define EVALUATION_BOARD_SAMPLES_HPP

#include <stdio.h>

#include "mros2_test_msgs/msg/reading.hpp"
#include "sensor_msgs/msg/image.hpp"
#include "std_msgs/msg/string.hpp"

namespace board_samples {

inline void fill_chatter(std_msgs::msg::String& text, int number) {
  char line[32];
  snprintf(line, sizeof line, "board sample %d", number);
  text.data = line;
}

inline void fill_image(sensor_msgs::msg::Image& image, int number) {
  image.header.stamp.sec = number;
  image.header.stamp.nanosec = 1000u * static_cast<uint32_t>(number);
  image.header.frame_id = "camera";
  image.height = 10;
  image.width = 20;
  image.encoding = "mono8";
  image.step = 20;
  image.data.resize(200);
  for (size_t i = 0; i < image.data.size(); ++i) {
    image.data[i] = static_cast<uint8_t>(number + static_cast<int>(i));
  }
}

inline void fill_reading(mros2_test_msgs::msg::Reading& reading, int number) {
  reading.stamp.sec = number;
  reading.stamp.nanosec = 7u * static_cast<uint32_t>(number);
  reading.sensor = "imu";
  reading.position[0] = static_cast<float>(number);
  reading.position[1] = static_cast<float>(number) + 0.5f;
  reading.position[2] = -static_cast<float>(number);
  reading.samples.push_back(static_cast<int16_t>(number));
  reading.samples.push_back(static_cast<int16_t>(-number));
}

}  // namespace board_samples

#endif  // EVALUATION_BOARD_SAMPLES_HPP
