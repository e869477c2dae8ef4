// SPDX-License-Identifier: BSD-3-Clause
// The ROS side of the paper's evaluation (Fig. 8): a roscpp node printing
// the mros_test/PersonalData messages that the mROS node publishes on
// mros_str.
#include <mros_test/PersonalData.h>
#include <ros/ros.h>

#include <cstdio>

void heard(const mros_test::PersonalData::ConstPtr& msg) {
  ROS_INFO("I heard from mROS: %s %s age:%u score:%d", msg->first_name.c_str(),
           msg->last_name.c_str(), msg->age, msg->score);
}

int main(int argc, char** argv) {
  // Whole lines at once when stdout is a pipe, so a test sees them as printed.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  ros::init(argc, argv, "ros_personal_listener");
  ros::NodeHandle n;
  ros::Subscriber sub = n.subscribe("mros_str", 10, heard);
  ros::spin();
}
