// The mROS v1 API (mros-lib/mros-src/api/ros.h) as the footprint benchmark
// needs it: the same templates and signatures.
#ifndef BENCH_FOOTPRINT_ROS_H
#define BENCH_FOOTPRINT_ROS_H

#include <string>

namespace ros {

class Publisher {
 public:
  template <class T> void publish(T& data);
  void* object;
};

class Subscriber {
 public:
  void* object;
};

class NodeHandle {
 public:
  template <class T> Subscriber subscribe(std::string topic, int queue_size, void (*fp)(T));
  template <class T> Publisher advertise(std::string topic, int queue_size);
};

}  // namespace ros

namespace message_traits {
template <int V> struct MD5Sum { static const char* value(); };
template <class T> struct DataType { static const char* value(); };
template <class T> struct DataTypeId { static int value(void); };
template <class T> struct Definition { static const char* value(); };
}  // namespace message_traits

namespace subtask_methods {
template <int T> struct CallCallbackFuncs { static void call(void (*fp)(void*), char* rbuf); };
}  // namespace subtask_methods

#endif  // BENCH_FOOTPRINT_ROS_H
