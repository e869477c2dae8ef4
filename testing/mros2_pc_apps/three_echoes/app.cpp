/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * An mros2 app written as mros2-posix' apps are: three subscriptions and three publishers,
 * each callback changing the sample it takes and publishing it on its topic's echo:
 * text (String) comes back on text_echo as "echo: <text>", twist (Twist) on twist_echo with
 * linear.x + 1 and angular.z doubled, pose (Pose) on pose_echo with position.z + 1. The
 * plain node (testing/mros2_pc_peer.py) and its control (testing/mros2_pc_control.py, which
 * does the same in rclpy) check every field.
 */
#include "mros2.h"
#include "geometry_msgs/msg/pose.hpp"
#include "geometry_msgs/msg/twist.hpp"
#include "std_msgs/msg/string.hpp"

#include "cmsis_os.h"
#include "netif.h"
#include "netif_posix_add.h"

#include <stdio.h>

namespace {

mros2::Publisher text_echo, twist_echo, pose_echo;

/* mros2 sends a message over its 100-byte buffer later, from embeddedRTPS' writer thread,
 * through a reference to it: the texts published are kept in a ring. */
const int kKept = 32;
std_msgs::msg::String texts[kKept];
int texts_taken;

void on_text(std_msgs::msg::String *text)
{
  std_msgs::msg::String &echo = texts[texts_taken++ % kKept];
  echo.data = "echo: " + text->data;
  printf("text %d\n", texts_taken);
  text_echo.publish(echo);
}

void on_twist(geometry_msgs::msg::Twist *twist)
{
  twist->linear.x += 1;
  twist->angular.z *= 2;
  twist_echo.publish(*twist);
}

void on_pose(geometry_msgs::msg::Pose *pose)
{
  pose->position.z += 1;
  pose_echo.publish(*pose);
}

}  // namespace

int main()
{
  netif_posix_add(NETIF_IPADDR, NETIF_NETMASK);
  osKernelStart();
  mros2::init(0, NULL);
  mros2::Node node = mros2::Node::create_node("three_echoes");
  text_echo = node.create_publisher<std_msgs::msg::String>("text_echo", 10);
  twist_echo = node.create_publisher<geometry_msgs::msg::Twist>("twist_echo", 10);
  pose_echo = node.create_publisher<geometry_msgs::msg::Pose>("pose_echo", 10);
  node.create_subscription<std_msgs::msg::String>("text", 10, on_text);
  node.create_subscription<geometry_msgs::msg::Twist>("twist", 10, on_twist);
  node.create_subscription<geometry_msgs::msg::Pose>("pose", 10, on_pose);
  printf("app ready\n");
  mros2::spin();
  return 0;
}
