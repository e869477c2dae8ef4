// SPDX-License-Identifier: BSD-3-Clause
// One firmware of bench/mros2/footprint.sh: publishes a message and receives
// one through mros2's calls, as an mros2 application does. The calls are
// defined in testing/mros2_runtime/mros2_runtime_check.cpp (what mros2's
// src/mros2.cpp does, instantiated by the firmware's templates.hpp); the
// received buffer is the one just published.
//   -DBENCH_STRING: std_msgs::msg::String   -DBENCH_TWIST: geometry_msgs::msg::Twist
//   neither: the baseline, the same firmware without any message: the topic
//   name strings and the sent buffer the runtime calls use, nothing else.
// Both header sets are used through the one-argument copyFromBuf (the
// runtime's): mros2's hand-written headers have no checked one.
#include <stdint.h>
#include <string.h>

#include <string>

#include "mros2.h"

#if defined(BENCH_STRING)
#include "std_msgs/msg/string.hpp"
typedef std_msgs::msg::String Message;
static void fill(Message& message) { message.data = "hello from the board"; }
static uint32_t use(const Message& message) { return static_cast<uint32_t>(message.data.size()); }
#elif defined(BENCH_TWIST)
#include "geometry_msgs/msg/twist.hpp"
typedef geometry_msgs::msg::Twist Message;
volatile double g_speed = 0.5;
static void fill(Message& message) {
  message.linear.x = g_speed;
  message.angular.z = 2 * g_speed;
}
static uint32_t use(const Message& message) {
  return static_cast<uint32_t>(message.linear.x + message.angular.z);
}
#endif

#if defined(BENCH_IOSTREAM)
#include <iostream>  // the start-up of iostream, which mros2's geometry_msgs headers include
#endif

volatile uint32_t g_sink;

#if defined(BENCH_STRING) || defined(BENCH_TWIST)
static void on_message(intptr_t received) { g_sink = use(*reinterpret_cast<Message*>(received)); }
static void on_message_typed(Message* received) { g_sink = use(*received); }

int main() {
  mros2::Node node;
  mros2::Publisher publisher = node.create_publisher<Message>("to_host", 10);
  mros2::Subscriber subscriber = node.create_subscription("to_board", 10, on_message_typed);
  Message message;
  fill(message);
  publisher.publish(message);
  mros2::SubscribeDataType callback = {on_message, 0};
  rtps::ReaderCacheChange change(g_sent, g_sent_size);
  mros2::Subscriber::callback_handler<Message>(&callback, change);
  g_sink = static_cast<uint32_t>(publisher.topic_name.size() + subscriber.topic_name.size());
  return 0;
}
#else
int main() {
  std::string to_host = "rt/" + std::string("to_host");
  std::string to_board = "rt/" + std::string("to_board");
  g_sent[g_sink % sizeof g_sent] = 1;
  g_sent_size = g_sink;
  rtps::ReaderCacheChange change(g_sent, g_sent_size);
  g_sink = static_cast<uint32_t>(to_host.size() + to_board.size() + change.getData()[0]);
  return 0;
}
#endif
