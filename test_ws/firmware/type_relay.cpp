// An mROS node for the tests: for each message type of the test workspace it
// subscribes <from>/<Type> and publishes every message it receives, as it
// received it, on <to>/<Type>. A ROS node that sends a message through it
// and compares what comes back checks both directions of the generated
// code: deserialize (ROS -> mROS) and serialize (mROS -> ROS).
//
//   type_relay FROM_PREFIX TO_PREFIX [ROS remappings]
#include "ros.h"

#include <cstdio>
#include <string>
#include <vector>

#include <mros_test/ArrayTypes.h>
#include <mros_test/BuiltinTypes.h>
#include <mros_test/Constants.h>
#include <mros_test/Empty.h>
#include <mros_test/NestedTypes.h>
#include <mros_test/PersonalData.h>
#include <std_msgs/Header.h>

namespace {

std::vector<ros::Subscriber> subscribers;

template <class T>
struct Relay {
  static ros::Publisher publisher;

  static void forward(T* message) { publisher.publish(*message); }

  static void start(ros::NodeHandle& n, const std::string& from, const std::string& to,
                    const std::string& type_name) {
    publisher = n.advertise<T>(to + "/" + type_name, 100);
    subscribers.push_back(n.subscribe(from + "/" + type_name, 100, &Relay<T>::forward));
  }
};

template <class T>
ros::Publisher Relay<T>::publisher;

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s FROM_PREFIX TO_PREFIX [remappings]\n", argv[0]);
    return 2;
  }
  const std::string from = argv[1];
  const std::string to = argv[2];
  ros::init(argc, argv, "mros_type_relay");
  ros::NodeHandle n;
  Relay<mros_test::PersonalData>::start(n, from, to, "PersonalData");
  Relay<mros_test::BuiltinTypes>::start(n, from, to, "BuiltinTypes");
  Relay<mros_test::ArrayTypes>::start(n, from, to, "ArrayTypes");
  Relay<mros_test::NestedTypes>::start(n, from, to, "NestedTypes");
  Relay<mros_test::Constants>::start(n, from, to, "Constants");
  Relay<mros_test::Empty>::start(n, from, to, "Empty");
  Relay<std_msgs::Header>::start(n, from, to, "Header");
  ROS_INFO("relaying %s/* to %s/*", from.c_str(), to.c_str());
  ros::spin();
}
