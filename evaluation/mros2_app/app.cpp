/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The main job's mros2 app: what the stand-in board (evaluation/firmware_ros2) does, written
 * as mros2 apps are and run on mros2 itself by genmros mros2-pc.
 *
 * It subscribes to command (String), twist (Twist) and reading_in (Reading). The n-th command
 * makes it publish sample n of chatter, image (in fragments) and reading
 * (board_samples.hpp); each command, twist and reading_in is published again on
 * <topic>_echo. mros2 v0.5.4 as it is sends every message through its last publisher, so
 * built without APP_ALL_PUBLISHERS the app has one, image, and echoes nothing. With it (genmros'
 * whole patch set) chatter goes out on chatter_reliable too, from a reliable publisher
 * (mros2::QoS(10).reliable(), the patch reliable-where-asked), and the app serves
 * parameter_types and calls name_lengths (rcl_interfaces/srv/GetParameterTypes: a name's type
 * is its length; the patch services-both-ways): once name_lengths is there, it calls it
 * kCalls times, call i asking for "call i" and i times "x", and prints "call i ok" or
 * "call i failed". All publishing happens in the callbacks, on mros2's reader thread, as
 * mros2's shared send buffers need.
 */
#include "mros2.h"
#include "geometry_msgs/msg/twist.hpp"
#include "mros2_test_msgs/msg/reading.hpp"
#ifdef APP_ALL_PUBLISHERS
#include "rcl_interfaces/srv/get_parameter_types.hpp"
#endif
#include "sensor_msgs/msg/image.hpp"
#include "std_msgs/msg/string.hpp"

#include "cmsis_os.h"
#include "netif.h"
#include "netif_posix_add.h"

#include <stdio.h>
#include <string>

#include "../firmware_ros2/board_samples.hpp"

namespace {

/* mros2 sends a message over its 100-byte buffer later, from embeddedRTPS' writer thread,
 * through a reference to it: each image published is kept in a ring that the peer's 20
 * samples never lap. */
const int kKept = 32;
sensor_msgs::msg::Image images[kKept];
int commands_received;

mros2::Publisher image_publisher;
#ifdef APP_ALL_PUBLISHERS
mros2::Publisher chatter_publisher, chatter_reliable_publisher, reading_publisher;
mros2::Publisher command_echo, twist_echo, reading_echo;
#endif

void on_command(std_msgs::msg::String *command)
{
  const int number = commands_received++;
  sensor_msgs::msg::Image &image = images[number % kKept];
  image = sensor_msgs::msg::Image();
  board_samples::fill_image(image, number);
  image_publisher.publish(image);
#ifdef APP_ALL_PUBLISHERS
  std_msgs::msg::String text;
  board_samples::fill_chatter(text, number);
  chatter_publisher.publish(text);
  chatter_reliable_publisher.publish(text);
  mros2_test_msgs::msg::Reading reading;
  board_samples::fill_reading(reading, number);
  reading_publisher.publish(reading);
  command_echo.publish(*command);
#else
  (void)command;
#endif
}

void on_twist(geometry_msgs::msg::Twist *twist)
{
#ifdef APP_ALL_PUBLISHERS
  twist_echo.publish(*twist);
#else
  (void)twist;
#endif
}

void on_reading(mros2_test_msgs::msg::Reading *reading)
{
#ifdef APP_ALL_PUBLISHERS
  reading_echo.publish(*reading);
#else
  (void)reading;
#endif
}

#ifdef APP_ALL_PUBLISHERS
typedef rcl_interfaces::srv::GetParameterTypes GetParameterTypes;
const int kCalls = 20;
// A lost reply comes again at the rclpy writer's next heartbeat (Fast DDS: every 3 s), under qemu.
const uint32_t kCallTimeoutMs = 20000;

void name_lengths(GetParameterTypes::Request *request, GetParameterTypes::Response *response)
{
  for (const auto &name : request->names) {
    response->types.push_back(static_cast<uint8_t>(name.size()));
  }
}

bool reply_right(const GetParameterTypes::Request &request,
                 const GetParameterTypes::Response &response)
{
  if (response.types.size() != request.names.size()) {
    return false;
  }
  for (size_t i = 0; i < request.names.size(); ++i) {
    if (response.types[i] != request.names[i].size()) {
      return false;
    }
  }
  return true;
}

void call_name_lengths(mros2::Client &client)
{
  while (!client.service_is_ready()) {
    osDelay(100);
  }
  for (int i = 0; i < kCalls; ++i) {
    GetParameterTypes::Request request;
    request.names.push_back("call " + std::to_string(i));
    request.names.push_back(std::string(i, 'x'));
    GetParameterTypes::Response response;
    const bool right = client.call(request, response, kCallTimeoutMs) &&
                       reply_right(request, response);
    printf("call %d %s\n", i, right ? "ok" : "failed");
    fflush(stdout);
  }
}
#endif

}  // namespace

int main()
{
  netif_posix_add(NETIF_IPADDR, NETIF_NETMASK);
  osKernelStart();
  mros2::init(0, NULL);
  mros2::Node node = mros2::Node::create_node("main_job_board");
#ifdef APP_ALL_PUBLISHERS
  chatter_publisher = node.create_publisher<std_msgs::msg::String>("chatter", 10);
  chatter_reliable_publisher =
      node.create_publisher<std_msgs::msg::String>("chatter_reliable", mros2::QoS(10).reliable());
  reading_publisher = node.create_publisher<mros2_test_msgs::msg::Reading>("reading", 10);
  command_echo = node.create_publisher<std_msgs::msg::String>("command_echo", 10);
  twist_echo = node.create_publisher<geometry_msgs::msg::Twist>("twist_echo", 10);
  reading_echo = node.create_publisher<mros2_test_msgs::msg::Reading>("reading_in_echo", 10);
#endif
  image_publisher = node.create_publisher<sensor_msgs::msg::Image>("image", 10);
  mros2::Subscriber commands =
      node.create_subscription<std_msgs::msg::String>("command", 10, on_command);
  mros2::Subscriber twists =
      node.create_subscription<geometry_msgs::msg::Twist>("twist", 10, on_twist);
  mros2::Subscriber readings =
      node.create_subscription<mros2_test_msgs::msg::Reading>("reading_in", 10, on_reading);
#ifdef APP_ALL_PUBLISHERS
  node.create_service<rcl_interfaces::srv::GetParameterTypes>("parameter_types", name_lengths);
  mros2::Client client =
      node.create_client<rcl_interfaces::srv::GetParameterTypes>("name_lengths");
#endif
  printf("app ready\n");
#ifdef APP_ALL_PUBLISHERS
  call_name_lengths(client);
#endif
  mros2::spin();
  return 0;
}
