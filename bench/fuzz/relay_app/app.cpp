// SPDX-License-Identifier: BSD-3-Clause
// The node bench/fuzz/network_fuzz.py attacks, as an mROS v1 app: it relays
// five ROS message types, each from src/<Type> to back/<Type>, so that after
// the fuzzing each can be checked to cross the library's receive,
// deserialize, serialize and send byte for byte as before. custom_pubsub's
// mros_config (10 subscriptions, 10 publications) holds the five relays and
// leaves room for the peers the fuzzer makes.
#include "app.h"
#include "ros.h"

#include "geometry_msgs/PoseStamped.h"
#include "geometry_msgs/Twist.h"
#include "sensor_msgs/Imu.h"
#include "sensor_msgs/JointState.h"
#include "std_msgs/String.h"

template <class T>
struct Relay {
  static ros::Publisher back;

  static void forward(T *msg) { back.publish(*msg); }

  static void start(ros::NodeHandle &n, const std::string &name) {
    back = n.advertise<T>("back/" + name, 1);
    n.subscribe("src/" + name, 1, forward);
  }
};

template <class T>
ros::Publisher Relay<T>::back;

void usr_task1() {
  int argc = 0;
  char *argv = NULL;
  ros::init(argc, argv, "mros_fuzz_relay");
  ros::NodeHandle n;
  Relay<std_msgs::String>::start(n, "String");
  Relay<sensor_msgs::JointState>::start(n, "JointState");
  Relay<geometry_msgs::PoseStamped>::start(n, "PoseStamped");
  Relay<sensor_msgs::Imu>::start(n, "Imu");
  Relay<geometry_msgs::Twist>::start(n, "Twist");
  syslog(LOG_NOTICE, "relay ready");
  ros::spin();
}

// app.cfg's second task, which mros_usr_config.c activates too.
void usr_task2() {}
