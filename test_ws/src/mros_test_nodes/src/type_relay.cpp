// SPDX-License-Identifier: BSD-3-Clause
// The roscpp twin of the firmware's type_relay (used by the tests): for each
// test message type it subscribes <from>/<Type> and republishes every
// message unchanged on <to>/<Type>, so a chain rospy -> mROS -> roscpp ->
// mROS -> rospy checks every pair of implementations.
//
//   type_relay FROM_PREFIX TO_PREFIX [ROS remappings]
#include <mros_test/ArrayTypes.h>
#include <mros_test/BuiltinTypes.h>
#include <mros_test/Constants.h>
#include <mros_test/Empty.h>
#include <mros_test/NestedTypes.h>
#include <mros_test/PersonalData.h>
#include <ros/ros.h>

#include <cstdio>
#include <std_msgs/Header.h>

#include <string>
#include <vector>

template <class T>
void relay(ros::NodeHandle& n, const std::string& from, const std::string& to,
           const std::string& type_name, std::vector<ros::Subscriber>& subscribers) {
  ros::Publisher publisher = n.advertise<T>(to + "/" + type_name, 100);
  subscribers.push_back(n.subscribe<T>(
      from + "/" + type_name, 100,
      [publisher](const typename T::ConstPtr& message) { publisher.publish(*message); }));
}

int main(int argc, char** argv) {
  // Whole lines at once when stdout is a pipe, so a test sees them as printed.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  ros::init(argc, argv, "ros_type_relay");
  if (argc < 3) {
    ROS_FATAL("usage: type_relay FROM_PREFIX TO_PREFIX");
    return 2;
  }
  const std::string from = argv[1];
  const std::string to = argv[2];
  ros::NodeHandle n;
  std::vector<ros::Subscriber> subscribers;
  relay<mros_test::PersonalData>(n, from, to, "PersonalData", subscribers);
  relay<mros_test::BuiltinTypes>(n, from, to, "BuiltinTypes", subscribers);
  relay<mros_test::ArrayTypes>(n, from, to, "ArrayTypes", subscribers);
  relay<mros_test::NestedTypes>(n, from, to, "NestedTypes", subscribers);
  relay<mros_test::Constants>(n, from, to, "Constants", subscribers);
  relay<mros_test::Empty>(n, from, to, "Empty", subscribers);
  relay<std_msgs::Header>(n, from, to, "Header", subscribers);
  ROS_INFO("relaying %s/* to %s/*", from.c_str(), to.c_str());
  ros::spin();
}
