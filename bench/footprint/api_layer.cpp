// The API layer of mROS v1 (mros-lib/mros-src/api/ros.cpp) in its shape:
// advertise/subscribe/publish templates over the type interface, the
// per-firmware message_headers.h, and the explicit instantiations of
// message_class_specialization.h at the end.
#include "ros.h"

#include "library.h"
#include "message_headers.h"

template <class T>
ros::Subscriber ros::NodeHandle::subscribe(std::string topic, int, void (*fp)(T)) {
  const int type_id = message_traits::DataTypeId<T>::value();
  Subscriber subscriber;
  subscriber.object = library_topic(topic.c_str(), message_traits::DataType<T>::value(), type_id, getMD5Sum(type_id),
                                    message_traits::Definition<T>::value());
  library_subscribe(subscriber.object, reinterpret_cast<void (*)(void*)>(fp));
  return subscriber;
}

template <class T> ros::Publisher ros::NodeHandle::advertise(std::string topic, int) {
  const int type_id = message_traits::DataTypeId<T*>::value();
  Publisher publisher;
  publisher.object = library_topic(topic.c_str(), message_traits::DataType<T*>::value(), type_id, getMD5Sum(type_id),
                                   message_traits::Definition<T*>::value());
  return publisher;
}

template <class T> void ros::Publisher::publish(T& data) {
  const unsigned size = static_cast<unsigned>(data.dataSize()) + 4;
  char* block = library_alloc_block(object, size);
  if (block == 0) return;
  char* body = block + 4;
  data.memCopy(body);
  library_publish(object, block, size);
}

extern "C" void api_deliver(int type_id, void (*callback)(void*), const char* block) {
  callCallback(type_id, callback, const_cast<char*>(block));
}

#include "message_class_specialization.h"
