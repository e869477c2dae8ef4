/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * An mros2 app with reliable endpoints (genmros' mros2 patch reliable-where-asked) beside
 * best-effort ones: what comes on text (a reliable subscription) goes back unchanged on
 * text_echo (a reliable publisher keeping its last 10), in a callback, as mros2 apps
 * publish; what comes on plain goes back on plain_echo, both best-effort as mros2's
 * endpoints are (created with mros2's int argument). Every 100 texts, and at each refused
 * publish, it prints how many it took and how many publishes were refused.
 */
#include "mros2.h"
#include "std_msgs/msg/string.hpp"

#include "cmsis_os.h"
#include "netif.h"
#include "netif_posix_add.h"

#include <stdio.h>

namespace {

mros2::Publisher text_echo, plain_echo;
int texts_taken, publishes_refused;

void on_text(std_msgs::msg::String *text)
{
  ++texts_taken;
  if (!text_echo.publish(*text)) {
    ++publishes_refused;
    printf("text %d: publish refused (%d refused)\n", texts_taken, publishes_refused);
  } else if (texts_taken % 100 == 0) {
    printf("text %d (%d refused)\n", texts_taken, publishes_refused);
  }
  fflush(stdout);
}

void on_plain(std_msgs::msg::String *text)
{
  plain_echo.publish(*text);
}

}  // namespace

int main()
{
  netif_posix_add(NETIF_IPADDR, NETIF_NETMASK);
  osKernelStart();
  mros2::init(0, NULL);
  mros2::Node node = mros2::Node::create_node("reliable_echo");
  text_echo = node.create_publisher<std_msgs::msg::String>("text_echo",
                                                           mros2::QoS(10).reliable());
  plain_echo = node.create_publisher<std_msgs::msg::String>("plain_echo", 10);
  node.create_subscription<std_msgs::msg::String>("text", mros2::QoS(10).reliable(), on_text);
  node.create_subscription<std_msgs::msg::String>("plain", 10, on_plain);
  printf("app ready\n");
  fflush(stdout);
  mros2::spin();
  return 0;
}
