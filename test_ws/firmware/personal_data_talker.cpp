// The paper's Fig. 6: an mROS node publishing mros_test/PersonalData
// ("Phil", "Woods", 83, score counting up) on mros_str, five times a second.
#include "ros.h"

#include <mros_test/PersonalData.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "mros_node");
  ros::NodeHandle n;
  ros::Publisher pub = n.advertise<mros_test::PersonalData>("mros_str", 1);
  ros::Rate loop_rate(5);
  mros_test::PersonalData msg;
  msg.first_name = "Phil";
  msg.last_name = "Woods";
  msg.age = 83;
  msg.score = 100000;
  while (1) {
    loop_rate.sleep();
    pub.publish(msg);
    ROS_INFO("published %s %s age:%u score:%d", msg.first_name.c_str(), msg.last_name.c_str(),
             msg.age, msg.score);
    msg.score++;
  }
}
