/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * An mros2-posix app on genmros' message headers, answering a ROS 2 peer.
 *
 * It subscribes to std_msgs/String requests on "requests" and answers each one:
 * - "image N" publishes the test image N (fill_test_image) on "images": N * 17 bytes of
 *   data, so images from N = 3 on are over mros2's 100-byte buffer and go out in fragments;
 * - any other text is echoed: on "echo" as a String when built with APP_ECHO_PUBLISHER
 *   (a second publisher: needs genmros' mros2 patch set), otherwise as an Image on
 *   "images" whose header.frame_id is the text (mros2 0.4 has one writer for all
 *   publishers).
 * An answer's frame_id (or String) is the request's text, so the peer can tell which
 * request it answers. testing/mros2_posix.py holds the same test image in Python.
 */
#include "mros2.h"
#include "sensor_msgs/msg/image.hpp"
#include "std_msgs/msg/string.hpp"

#include "cmsis_os.h"
#include "netif.h"
#include "netif_posix_add.h"

#include <stdio.h>
#include <stdlib.h>
#include <string>

namespace {

const std::string kImageRequest = "image ";
const uint32_t kImageBytesPerIndex = 17;

mros2::Publisher image_publisher;
#ifdef APP_ECHO_PUBLISHER
mros2::Publisher echo_publisher;
#endif

/* mros2 sends a message over its 100-byte buffer later, from embeddedRTPS' writer thread,
 * through a reference to it (Publisher::publish hands the writer a lambda capturing &msg):
 * a message must outlive publish() until it is sent. So each one published is kept in a
 * ring, which the peer (it waits for each answer before the next request) never laps. */
template <class Message>
class PublishedMessages
{
public:
  Message &fresh()
  {
    Message &slot = slots_[next_];
    next_ = (next_ + 1) % kCount;
    slot = Message();
    return slot;
  }

private:
  static const size_t kCount = 8;
  Message slots_[kCount];
  size_t next_ = 0;
};

PublishedMessages<sensor_msgs::msg::Image> published_images;
#ifdef APP_ECHO_PUBLISHER
PublishedMessages<std_msgs::msg::String> published_strings;
#endif

void fill_test_image(sensor_msgs::msg::Image &image, uint32_t index, const std::string &frame_id)
{
  image.header.stamp.sec = static_cast<int32_t>(index);
  image.header.stamp.nanosec = 1000003u * index;
  image.header.frame_id = frame_id;
  image.height = 1;
  image.width = kImageBytesPerIndex * index;
  image.encoding = "mono8";
  image.is_bigendian = 0;
  image.step = image.width;
  for (uint32_t i = 0; i < image.width; ++i) {
    image.data.push_back(static_cast<uint8_t>(7 * index + i));
  }
}

/* The size is printed before publish(): afterwards the writer thread may be reading the
 * message, and calcTotalSize() restarts its fragment count. */
template <class Message>
void publish(mros2::Publisher &publisher, Message &message, const char *what)
{
  printf("publishing %s: %u bytes on the wire\n", what, (unsigned)message.calcTotalSize());
  fflush(stdout);
  publisher.publish(message);
}

void echo(const std::string &text)
{
#ifdef APP_ECHO_PUBLISHER
  std_msgs::msg::String &answer = published_strings.fresh();
  answer.data = text;
  publish(echo_publisher, answer, "an echo as String");
#else
  sensor_msgs::msg::Image &answer = published_images.fresh();
  answer.header.frame_id = text;
  answer.encoding = "echo";
  publish(image_publisher, answer, "an echo as Image");
#endif
}

/* mros2 calls it on its reader thread; answering from there keeps all publishing on one
 * thread, which mros2's shared send buffers need. */
void on_request(std_msgs::msg::String *request)
{
  const std::string &text = request->data;
  if (text.compare(0, kImageRequest.size(), kImageRequest) == 0) {
    uint32_t index = static_cast<uint32_t>(strtoul(text.c_str() + kImageRequest.size(),
                                                   NULL, 10));
    sensor_msgs::msg::Image &image = published_images.fresh();
    fill_test_image(image, index, text);
    publish(image_publisher, image, text.c_str());
  } else {
    echo(text);
  }
}

#ifdef APP_SETS_RTPS_ADDRESS
/* mros2_setIPAddrRTPS takes lwIP's byte order: the address' first byte lowest. (The
 * system's inet_addr is out of reach: <arpa/inet.h> clashes with lwIP's declarations.) */
uint32_t lwip_address(const char *dotted)
{
  unsigned bytes[4] = {0, 0, 0, 0};
  sscanf(dotted, "%u.%u.%u.%u", &bytes[0], &bytes[1], &bytes[2], &bytes[3]);
  return bytes[0] | (bytes[1] << 8) | (bytes[2] << 16) | (bytes[3] << 24);
}
#endif

}  // namespace

int main()
{
  netif_posix_add(NETIF_IPADDR, NETIF_NETMASK);
#ifdef APP_SETS_RTPS_ADDRESS
  mros2_setIPAddrRTPS(lwip_address(NETIF_IPADDR));
#endif
  osKernelStart();
  mros2::init(0, NULL);

  mros2::Node node = mros2::Node::create_node("genmros_app");
  image_publisher = node.create_publisher<sensor_msgs::msg::Image>("images", 10);
#ifdef APP_ECHO_PUBLISHER
  echo_publisher = node.create_publisher<std_msgs::msg::String>("echo", 10);
#endif
  mros2::Subscriber requests =
      node.create_subscription<std_msgs::msg::String>("requests", 10, on_request);
  printf("app ready\n");
  fflush(stdout);
  mros2::spin();
  return 0;
}
