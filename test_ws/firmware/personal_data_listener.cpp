// The paper's Fig. 7: an mROS node subscribing mros_test/PersonalData on
// test_msg and printing what a ROS node sent.
#include "ros.h"

#include <string>

#include <mros_test/PersonalData.h>

void Callback(mros_test::PersonalData::Ptr msg) {
  ROS_INFO("I heard a msg from ros host");
  std::string name = msg->first_name + " " + msg->last_name;
  ROS_INFO("name:%s", name.c_str());
  ROS_INFO("age:%u", msg->age);
  ROS_INFO("score:%d", msg->score);
}

int main(int argc, char** argv) {
  ros::init(argc, argv, "mros_node2");
  ros::NodeHandle n;
  ros::Subscriber sub = n.subscribe("test_msg", 1, Callback);
  ros::spin();
}
