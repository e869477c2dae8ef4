// ros_api.cpp: the mROS v1 API templates over the type-independent core.
// This is the only place where message types meet the communication library:
// each firmware compiles this file with its own generated
// message_headers.h / message_class_specialization.h (on its include path),
// which instantiate advertise, subscribe and publish for exactly its types.
#include "ros.h"

#include <ctime>

#include "message_headers.h"
#include "mros_posix/core.h"

namespace {

// The type-specific getter functions give what registration needs (paper 5.1).
template <class T>
mros::posix::TopicType topicTypeOf() {
  mros::posix::TopicType type;
  type.datatype = message_traits::DataType<T*>::value();
  type.md5sum = getMD5Sum(message_traits::DataTypeId<T*>::value());
  type.definition = message_traits::Definition<T*>::value();
  return type;
}

// Receiving (paper 5.3): a message object of the topic's type is made, the
// type-specific code fills it from the received body, then the callback runs.
template <class T>
bool deliver(void (*callback)(void*), const uint8_t* body, uint32_t size) {
  T message;
  if (message.deserialize(body, size) != static_cast<int32_t>(size)) {
    return false;
  }
  reinterpret_cast<void (*)(T*)>(callback)(&message);
  return true;
}

int64_t monotonicNanoseconds() {
  timespec now;
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<int64_t>(now.tv_sec) * 1000000000 + now.tv_nsec;
}

}  // namespace

void ros::init(int argc, char** argv, std::string node_name) {
  mros::posix::initNode(argc, argv, node_name);
}

void ros::init(int, char*, std::string node_name) {
  mros::posix::initNode(0, nullptr, node_name);
}

template <class T>
ros::Subscriber ros::NodeHandle::subscribe(std::string topic, int, void (*fp)(T*)) {
  Subscriber subscriber;  // the queue size has no use: see mros::posix::subscribe
  subscriber.set(mros::posix::subscribe(topic, topicTypeOf<T>(), &deliver<T>,
                                        reinterpret_cast<void (*)(void*)>(fp)));
  return subscriber;
}

template <class T>
ros::Publisher ros::NodeHandle::advertise(std::string topic, int queue_size) {
  Publisher publisher;
  publisher.set(mros::posix::advertise(topic, topicTypeOf<T>(), queue_size));
  return publisher;
}

// Sending (paper 5.2, Fig. 3): the type-specific code reports the size and
// serializes into the send buffer; the common code queues it for sending.
template <class T>
void ros::Publisher::publish(T& data) {
  mros::posix::Publication* publication = static_cast<mros::posix::Publication*>(get());
  if (publication == nullptr) {
    ROS_ERROR("publish() on a publisher that was not advertised");
    return;
  }
  std::shared_ptr<mros::posix::Frame> frame =
      std::make_shared<mros::posix::Frame>(data.serializedLength());
  if (data.serialize(frame->body(), frame->bodySize()) < 0) {
    ROS_ERROR("%s: message does not fit its own serialized length",
              message_traits::DataType<T*>::value());
    return;
  }
  mros::posix::publish(publication, frame);
}

ros::Rate::Rate(int rate)
    : period_ns(rate > 0 ? 1000000000 / rate : 0), next_wakeup_ns(monotonicNanoseconds()) {}

void ros::Rate::sleep(void) {
  next_wakeup_ns += period_ns;
  const int64_t now = monotonicNanoseconds();
  if (next_wakeup_ns <= now) {
    next_wakeup_ns = now;
    return;
  }
  const int64_t wait = next_wakeup_ns - now;
  timespec duration = {static_cast<time_t>(wait / 1000000000), static_cast<long>(wait % 1000000000)};
  while (nanosleep(&duration, &duration) != 0) {
  }
}

void ros::spin(void) { mros::posix::spin(); }

bool ros::ok(void) { return mros::posix::ok(); }

#include "message_class_specialization.h"
