// ros.h: the mROS v1 user API (ros::init, NodeHandle::advertise/subscribe,
// Publisher::publish, Rate, spin, ROS_INFO ...) on the POSIX target.
// Application code written for mROS compiles against it unchanged; the
// templates are defined in ros_api.cpp, which each firmware compiles with its
// own generated message_class_specialization.h, as mROS v1 does.
#ifndef ROS_H
#define ROS_H

#include <cstdint>
#include <string>

namespace ros {

// Starts the node: reads ROS_MASTER_URI, ROS_IP / ROS_HOSTNAME and the
// command line remappings (from:=to, __name:=, __master:=, __ip:=), opens
// the slave API and TCPROS ports. One node per process.
void init(int argc, char** argv, std::string node_name);
// mROS v1 passed a char* (the board has no command line); kept for sources
// written that way.
void init(int argc, char* argv, std::string node_name);

// Handles are small values, as in mROS v1: they refer to the node's
// registration of the topic (cobj), which lives as long as the node.
class Publisher {
 public:
  Publisher() : cobj(nullptr) {}
  template <class T>
  void publish(T& data);
  void set(void* object) { cobj = object; }
  void* get() { return cobj; }

 private:
  void* cobj;
};

class Subscriber {
 public:
  Subscriber() : cobj(nullptr) {}
  // User-provided, as roscpp's is, so that the usual `ros::Subscriber sub =
  // n.subscribe(...);` (sub never read again) compiles without a warning.
  ~Subscriber() {}
  Subscriber(const Subscriber&) = default;
  Subscriber& operator=(const Subscriber&) = default;
  void set(void* object) { cobj = object; }
  void* get() { return cobj; }

 private:
  void* cobj;
};

class NodeHandle {
 public:
  template <class T>
  Subscriber subscribe(std::string topic, int queue_size, void (*fp)(T*));
  template <class T>
  Publisher advertise(std::string topic, int queue_size);
};

// Sleeps so that a loop runs at `rate` iterations per second, measured from
// the previous sleep (a late iteration does not shorten the next period
// below zero, it restarts the schedule).
class Rate {
 public:
  explicit Rate(int rate);
  void sleep(void);

 private:
  int64_t period_ns;
  int64_t next_wakeup_ns;
};

// Blocks; received messages are delivered by the library's own threads, as
// mROS v1's subscriber task does. The node ends on SIGINT / SIGTERM or the
// slave API's shutdown call: it unregisters from the master and the process
// exits with status 0.
void spin(void);

// True until shutdown has begun (not in mROS v1; for loops that want to end).
bool ok(void);

}  // namespace ros

// The type-specific functions that genmros generates for every message.
namespace message_traits {
template <int V>
struct MD5Sum {
  static const char* value();
};

template <class T>
struct DataType {
  static const char* value();
};

template <class T>
struct DataTypeId {
  static int value(void);
};

template <class T>
struct Definition {
  static const char* value();
};
}  // namespace message_traits

namespace subtask_methods {
template <int T>
struct CallCallbackFuncs {
  static void call(void (*fp)(void*), char* rbuf);
};
}  // namespace subtask_methods

#include "mros_log.h"

#endif  // ROS_H
