// SPDX-License-Identifier: BSD-3-Clause
// The mros2 board of the main job: an app written against genmros' mros2
// headers only (no mros2, no DDS). It publishes 20 samples each of
// std_msgs/String, sensor_msgs/Image (over mros2's 100-byte buffer, so
// written in fragments) and test_ws_ros2's Reading, and answers every
// String, Twist and Reading it receives with the same values on
// <topic>_echo. Each
// sample is sent as mros2 v0.5.4's Publisher::publish writes it: the CDR
// encapsulation header, the image (through copyToBuf and memAlign up to
// 100 bytes, else through copyToFragBuf into a 64-byte fragment buffer),
// zeros to a multiple of 4; each is received as a checked copyFromBuf of
// its size. The ports of evaluation/firmware carry the bytes.
#include <stdio.h>
#include <string.h>

#include "board.h"
#include "board_samples.hpp"
#include "geometry_msgs/msg/twist.hpp"
#include "mros2_test_msgs/msg/reading.hpp"
#include "sensor_msgs/msg/image.hpp"
#include "std_msgs/msg/string.hpp"

namespace {

enum TopicIndex { kChatter, kImage, kReading, kCommand, kTwist, kReadingIn, kCommandEcho,
                  kTwistEcho, kReadingEcho, kTopics };
enum { kSamples = 20 };

template <class T> board::Topic topicOf(const char* name, bool publishes) {
  board::Topic topic = {name, message_traits::TypeName<T*>::value(), "", "", publishes};
  return topic;
}

board::Topic topics[kTopics];

// mros2's buffers: a whole sample up to 100 bytes, else fragments of 64.
uint8_t buf[100];
uint8_t frag_buf[64];
uint8_t sample[board::kMaxMessageSize];

const uint8_t kCdrLittleEndian[4] = {0, 1, 0, 0};

template <class T> void publish(int index, T& msg) {
  uint32_t size = 0;
  if (sizeof(buf) >= msg.calcTotalSize()) {
    memcpy(buf, kCdrLittleEndian, 4);
    msg.copyToBuf(&buf[4]);
    msg.memAlign(&buf[4]);
    size = msg.getTotalSize() + 4;
    memcpy(sample, buf, size);
  } else {
    const uint32_t announced = msg.calcTotalSize();
    for (;;) {
      uint32_t offset = 0;
      if (msg.getPubCnt() == 0) {
        memcpy(frag_buf, kCdrLittleEndian, 4);
        offset = 4;
      }
      typename T::FragCopyReturnType copied =
          msg.copyToFragBuf(&frag_buf[offset], sizeof(frag_buf) - offset);
      uint32_t length = copied.second + offset;
      if (copied.first && copied.second == 0) {
        msg.resetCount();
        break;
      }
      while (copied.first && length % 4 != 0) frag_buf[length++] = 0;
      if (size + length > sizeof sample || size + length > announced) {
        board::log("a sample larger than announced");
        return;
      }
      memcpy(sample + size, frag_buf, length);
      size += length;
    }
  }
  board::send(index, sample, size);
}

template <class T> void echo(int index, const uint8_t* body, uint32_t size) {
  T msg;
  if (size < 4 || memcmp(body, kCdrLittleEndian, 2) != 0 || !msg.copyFromBuf(body + 4, size - 4)) {
    board::log("refused a sample that does not decode");
    return;
  }
  publish(index, msg);
}

void publishSamples(int number) {
  std_msgs::msg::String text;
  board_samples::fill_chatter(text, number);
  publish(kChatter, text);
  sensor_msgs::msg::Image image;
  board_samples::fill_image(image, number);
  publish(kImage, image);
  mros2_test_msgs::msg::Reading reading;
  board_samples::fill_reading(reading, number);
  publish(kReading, reading);
}

}  // namespace

namespace board {

void start() {
  topics[kChatter] = topicOf<std_msgs::msg::String>("chatter", true);
  topics[kImage] = topicOf<sensor_msgs::msg::Image>("image", true);
  topics[kReading] = topicOf<mros2_test_msgs::msg::Reading>("reading", true);
  topics[kCommand] = topicOf<std_msgs::msg::String>("command", false);
  topics[kTwist] = topicOf<geometry_msgs::msg::Twist>("twist", false);
  topics[kReadingIn] = topicOf<mros2_test_msgs::msg::Reading>("reading_in", false);
  topics[kCommandEcho] = topicOf<std_msgs::msg::String>("command_echo", true);
  topics[kTwistEcho] = topicOf<geometry_msgs::msg::Twist>("twist_echo", true);
  topics[kReadingEcho] = topicOf<mros2_test_msgs::msg::Reading>("reading_in_echo", true);
}

int topicCount() { return kTopics; }

const Topic& topic(int index) { return topics[index]; }

void receive(int index, const uint8_t* body, uint32_t size) {
  if (index == kCommand) {
    echo<std_msgs::msg::String>(kCommandEcho, body, size);
  } else if (index == kTwist) {
    echo<geometry_msgs::msg::Twist>(kTwistEcho, body, size);
  } else if (index == kReadingIn) {
    echo<mros2_test_msgs::msg::Reading>(kReadingEcho, body, size);
  }
}

void tick() {
  static int published = 0;
  if (published < kSamples) {
    publishSamples(published++);
  }
}

}  // namespace board
