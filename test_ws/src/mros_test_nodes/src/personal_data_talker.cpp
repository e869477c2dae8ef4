// SPDX-License-Identifier: BSD-3-Clause
// The ROS side of the paper's evaluation (Fig. 9): a roscpp node publishing
// mros_test/PersonalData ("Charlie", "Parker", 32, score counting up) on
// test_msg five times a second.
#include <mros_test/PersonalData.h>
#include <ros/ros.h>

#include <cstdio>

int main(int argc, char** argv) {
  // Whole lines at once when stdout is a pipe, so a test sees them as printed.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  ros::init(argc, argv, "ros_personal_talker");
  ros::NodeHandle n;
  ros::Publisher pub = n.advertise<mros_test::PersonalData>("test_msg", 1);
  ros::Rate loop_rate(5);
  mros_test::PersonalData msg;
  msg.first_name = "Charlie";
  msg.last_name = "Parker";
  msg.age = 32;
  msg.score = 100100;
  while (ros::ok()) {
    pub.publish(msg);
    ROS_INFO("published %s %s age:%u score:%d", msg.first_name.c_str(), msg.last_name.c_str(),
             msg.age, msg.score);
    msg.score++;
    loop_rate.sleep();
  }
}
