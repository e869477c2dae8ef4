// SPDX-License-Identifier: BSD-3-Clause
// Hand-written per-app instantiations (mROS v1 style) for the footprint benchmark.
#include "ros.h"
#include "mros_test/PersonalData.h"

template ros::Subscriber ros::NodeHandle::subscribe(std::string, int, void (*fp)(mros_test::PersonalData*));
template ros::Publisher ros::NodeHandle::advertise<mros_test::PersonalData>(std::string, int);
template void ros::Publisher::publish(mros_test::PersonalData&);
