// SPDX-License-Identifier: BSD-3-Clause
// Hand-written per-app instantiations (mROS v1 style) for the footprint benchmark.
#include "ros.h"
#include "bench_msgs/UserTypeTest.h"

template ros::Subscriber ros::NodeHandle::subscribe(std::string, int, void (*fp)(bench_msgs::UserTypeTest*));
template ros::Publisher ros::NodeHandle::advertise<bench_msgs::UserTypeTest>(std::string, int);
template void ros::Publisher::publish(bench_msgs::UserTypeTest&);
